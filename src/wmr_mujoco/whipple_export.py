"""Files of ``models/whipple/``: ``python -m wmr_mujoco.whipple_export``.

Writes ``whipple.xml`` and ``scene.xml`` from the builder's defaults, the eigenvalue figure
``eigenvalues.png``, the picture ``whipple.png`` and the push clips (need an OpenGL
backend) and the tables between the ``whipple parameters``, ``whipple eigenvalues`` and
``whipple metrics`` markers of the README.
The fidelity-versus-cost table is :mod:`wmr_mujoco.whipple_study`'s.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from wmr_mujoco.atomic import write_text_atomic
from wmr_mujoco.builders import common
from wmr_mujoco.builders import whipple as builder
from wmr_mujoco.info import flatten_params
from wmr_mujoco.markers import replace_between
from wmr_mujoco.paths import MODELS_DIR
from wmr_mujoco.whipple_measure import real_time_factor
from wmr_mujoco.whipple_params import DEFAULT_PARAMS, WhippleParams
from wmr_mujoco.whipple_validation import (
    TABLE_SPEEDS,
    all_metrics,
    eigen_rows,
    eigen_series,
    eigen_tolerance,
    passed,
    write_figure,
)

FOLDER = MODELS_DIR / "whipple"
ROBOT_FILE = "whipple.xml"
SCENE_FILE = "scene.xml"


def write_model_files(folder: Path = FOLDER) -> list[Path]:
    """``whipple.xml`` (builder defaults) and ``scene.xml`` (include + floor and light)."""
    from wmr_mujoco.export import scene_xml

    folder.mkdir(parents=True, exist_ok=True)
    robot = folder / ROBOT_FILE
    scene = folder / SCENE_FILE
    write_text_atomic(robot, common.to_xml(builder.build(WhippleParams())))
    write_text_atomic(scene, scene_xml(SimpleNamespace(name="whipple",
                                                       robot_file=ROBOT_FILE)))
    return [robot, scene]


def _fmt(z: complex | float) -> str:
    z = complex(z)
    if abs(z.imag) > 0:
        return f"{z.real:.4f} ± {abs(z.imag):.4f}i"
    return f"{z.real:.4f}"


def eigen_table(params: WhippleParams = DEFAULT_PARAMS,
                speeds: Sequence[float] = TABLE_SPEEDS) -> str:
    """Markdown: measured (physics) against benchmark modes, with each part's error."""
    lines = ["| v (m/s) | mode | MuJoCo (1/s) | benchmark (1/s) | error Re, Im (1/s) "
             "| tolerance (1/s) |", "|---|---|---|---|---|---|"]
    for row in eigen_rows(params, speeds):
        m, b = row.measured, row.benchmark
        for name, mz, bz in (("weave", m.weave, b.weave), ("capsize", m.capsize, b.capsize),
                             ("castering", m.castering, b.castering)):
            mz, bz = complex(mz), complex(bz)
            err = f"{mz.real - bz.real:+.4f}"
            tol = f"{eigen_tolerance(bz.real):.3f}"
            if name == "weave":
                err += f", {mz.imag - bz.imag:+.4f}"
                tol += f", {eigen_tolerance(bz.imag):.3f}"
            lines.append(f"| {row.speed:g} | {name} | {_fmt(mz)} | {_fmt(bz)} | {err} | "
                         f"{tol} |")
    return "\n".join(lines)


def metrics_table(params: WhippleParams = DEFAULT_PARAMS) -> str:
    """Markdown: every judged metric with its target and verdict, and the real-time factor."""
    lines = ["| metric | value | unit | target | kind | pass |", "|---|---|---|---|---|---|"]
    for m in all_metrics(params):
        name, value, unit, target, kind = m
        tgt = "—" if np.isnan(target) else f"{target:.4g}"
        verdict = "—" if np.isnan(target) else ("yes" if passed(m) else "NO")
        lines.append(f"| {name} | {value:.4g} | {unit} | {tgt} | {kind} | {verdict} |")
    lines.append(f"| real-time factor (one thread) | {real_time_factor(params):.0f} | × | — "
                 f"| reported | — |")
    return "\n".join(lines)


def write_picture(folder: Path = FOLDER) -> Path:
    """Render the bicycle at rest (steered a little) to ``whipple.png``."""
    from wmr_mujoco.gl_backend import select_backend

    select_backend()
    import mujoco

    from wmr_mujoco.rendering import CameraSettings, Filmer, write_media
    from wmr_mujoco.whipple_measure import compile_model

    model = compile_model(WhippleParams())
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("upright").id)
    data.joint("steer").qpos[0] = 0.3
    mujoco.mj_forward(model, data)
    with Filmer(model, 640, 400, CameraSettings(distance=1.8, shadows=True, reflections=True,
                                                elevation=-15, azimuth=120)) as f:
        image = f.frame(data)
    return write_media(folder / "whipple.png", image)


def parameter_table(params: WhippleParams = DEFAULT_PARAMS) -> str:
    """Markdown table of the default parameters (paper frame, SI units)."""
    rows = ["| parameter | value |", "|---|---|"]
    rows += [f"| `{k}` | {v} |" for k, v in flatten_params(params).items()]
    rows.append(f"| total mass | {params.total_mass:.6g} kg |")
    return "\n".join(rows)


#: Clips: (file, speed m/s, seconds) of the push runs shown in the README.
CLIPS = (("push_5mps.gif", 5.0, 8.0), ("fall_3mps.gif", 3.0, 4.0))


def write_clips(folder: Path = FOLDER, width: int = 200, height: int = 134,
                fps: int = 8) -> list[Path]:
    """GIFs of the uncontrolled bicycle pushed sideways: recovering at 5 m/s, falling at 3.

    Each frame is sampled from the same run :func:`~wmr_mujoco.whipple_measure.push_response`
    measures.
    """
    from wmr_mujoco.gl_backend import select_backend

    select_backend()
    from wmr_mujoco.rendering import CameraSettings, Filmer, write_media
    from wmr_mujoco.whipple_measure import compile_model, push_response

    model = compile_model(DEFAULT_PARAMS)
    written = []
    for name, speed, seconds in CLIPS:
        frames: list[np.ndarray] = []
        with Filmer(model, width, height, CameraSettings(distance=2.2, azimuth=150,
                                                         elevation=-15)) as f:
            count = [0]

            def grab(t: float, data: object, f: Filmer = f, frames: list = frames,
                     count: list = count) -> None:
                if t + 1e-9 >= count[0] / fps:  # one frame per 1/fps of simulated time
                    frames.append(f.frame(data))
                    count[0] += 1

            push_response(DEFAULT_PARAMS, speed, duration=seconds, model=model,
                          observer=grab)
        # Hold the last frame for a second (a fallen bicycle stops the run early).
        frames += [frames[-1]] * fps
        written.append(write_media(folder / name, frames, fps=fps))
    return written


def main(argv: Sequence[str] | None = None) -> None:
    """Write the model files, figure, picture and README tables."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--no-picture", action="store_true", help="skip picture and clips")
    args = parser.parse_args(argv)
    for p in write_model_files():
        print(f"wrote {p}")
    params = WhippleParams()
    series = eigen_series(params, np.arange(0.5, 10.01, 0.5), np.linspace(0.0, 10.0, 401))
    print(f"wrote {write_figure(FOLDER / 'eigenvalues.png', series)}")
    readme = FOLDER / "README.md"
    replace_between(readme, "whipple parameters", parameter_table(params))
    replace_between(readme, "whipple eigenvalues", eigen_table(params))
    replace_between(readme, "whipple metrics", metrics_table(params))
    print(f"wrote {readme}")
    if not args.no_picture:
        print(f"wrote {write_picture()}")
        for p in write_clips():
            print(f"wrote {p}")


if __name__ == "__main__":
    main()
