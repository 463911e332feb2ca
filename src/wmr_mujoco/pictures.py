"""The pictures in the model READMEs: ``python -m wmr_mujoco.pictures``."""

from __future__ import annotations

from pathlib import Path

from wmr_mujoco.gl_backend import select_backend


def write_pictures(width: int = 640, height: int = 400) -> list[Path]:
    """Render every robot at rest (free disc: leaning keyframe) to its model folder."""
    select_backend()
    import mujoco

    from wmr_mujoco.loading import load
    from wmr_mujoco.registry import ROBOTS
    from wmr_mujoco.rendering import CameraSettings, Filmer, write_media

    written = []
    for spec in ROBOTS.values():
        model = load(spec.name)
        data = mujoco.MjData(model)
        if model.nkey:
            mujoco.mj_resetDataKeyframe(model, data, model.key("leaning").id)
        if model.na:
            data.act[:] = 0.35  # steering target: show the steering joint turned
            data.joint("steer").qpos[0] = 0.35
        mujoco.mj_forward(model, data)
        with Filmer(model, width, height, CameraSettings(shadows=True, reflections=True,
                                                          elevation=-35)) as f:
            image = f.frame(data)
        written.append(write_media(spec.robot_path.with_suffix(".png"), image))
    return written


if __name__ == "__main__":
    for p in write_pictures():
        print(f"wrote {p}")
