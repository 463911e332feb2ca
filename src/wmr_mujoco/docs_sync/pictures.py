"""The pictures in the model READMEs: ``python -m wmr_mujoco.docs_sync.pictures``."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from wmr_mujoco.render.gl_backend import select_backend

if TYPE_CHECKING:
    import mujoco

    from wmr_mujoco.robots import Picture


def pose(model: mujoco.MjModel, data: mujoco.MjData, picture: Picture) -> None:
    """Put ``data`` in the picture's pose: its keyframe, then its joint angles.

    An integrator actuator (a steering servo) on a posed joint gets the same angle as
    its target, so the pose is also where the servo holds.
    """
    import mujoco

    if picture.keyframe is not None:
        mujoco.mj_resetDataKeyframe(model, data, model.key(picture.keyframe).id)
    for joint, angle in picture.joint_angles.items():
        jid = model.joint(joint).id
        data.qpos[model.jnt_qposadr[jid]] = angle
        for a in range(model.nu):
            if (model.actuator_trnid[a, 0] == jid
                    and model.actuator_dyntype[a] == mujoco.mjtDyn.mjDYN_INTEGRATOR):
                data.act[model.actuator_actadr[a]] = angle


def write_pictures(width: int = 640, height: int = 400) -> list[Path]:
    """Render every robot with model files in the pose its registry entry gives."""
    select_backend()
    import mujoco

    from wmr_mujoco.models.loading import load
    from wmr_mujoco.render.rendering import CameraSettings, Filmer, write_media
    from wmr_mujoco.robots import ROBOTS

    written = []
    for spec in ROBOTS.values():
        if spec.build is None or not spec.has_files:
            continue
        model = load(spec)
        data = mujoco.MjData(model)
        pose(model, data, spec.picture)
        mujoco.mj_forward(model, data)
        with Filmer(model, width, height, CameraSettings(shadows=True, reflections=True,
                                                          elevation=-35)) as f:
            image = f.frame(data)
        written.append(write_media(spec.robot_path.with_suffix(".png"), image))
    return written


if __name__ == "__main__":
    for p in write_pictures():
        print(f"wrote {p}")
