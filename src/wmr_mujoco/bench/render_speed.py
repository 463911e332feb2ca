"""How fast ``wmr render`` is on this machine's OpenGL: drawing, filming and encoding.

``python -m wmr_mujoco.bench.render_speed [--out FILE.md]`` prints (and writes) one
Markdown table for the robot with the most geoms at 640×480, so the same command gives
comparable figures on a CPU machine (Mesa llvmpipe through EGL) and on a GPU machine
(the vendor's EGL):

* **draw**: frames/s of :class:`~wmr_mujoco.render.rendering.Filmer` alone on a fixed
  state, as ``wmr render`` draws (no shadows or reflections) and with both;
* **film**: frames/s of the whole ``wmr render`` pipeline except the encoder (the
  scenario simulated through the runner, trails drawn, each frame handed on), i.e.
  :func:`~wmr_mujoco.render.video.film_scenario` with a frame sink that drops frames;
* **encode**: frames/s of the H.264 encoder on those frames (only where an ``ffmpeg``
  is found; it runs on the CPU whatever the OpenGL).

Timings are medians of ``--repeats`` runs after one warm-up.
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import tempfile
from collections.abc import Sequence
from pathlib import Path

WIDTH, HEIGHT, FPS = 640, 480, 30
#: Seconds of the scenario filmed in the ``film`` and ``encode`` columns.
FILM_SECONDS = 4.0


def _gl_strings() -> tuple[str, str]:
    """``GL_VENDOR`` and ``GL_RENDERER`` of MuJoCo's offscreen context."""
    import mujoco
    from OpenGL import GL

    ctx = mujoco.GLContext(16, 16)
    ctx.make_current()
    try:
        return (GL.glGetString(GL.GL_VENDOR).decode(),
                GL.glGetString(GL.GL_RENDERER).decode())
    finally:
        ctx.free()


def measure(repeats: int = 5) -> dict[str, object]:
    """The figures of the module docstring, and what they were measured on."""
    import mujoco

    from wmr_mujoco.bench.bench import render_fps
    from wmr_mujoco.render import rendering
    from wmr_mujoco.render.video import clip_scenario, film_scenario, pick_scenario
    from wmr_mujoco.sim.timing import median_time

    draw = render_fps(repeats)
    robot = str(draw["robot"])
    scenario = clip_scenario(pick_scenario(robot), FILM_SECONDS)
    frames: list = []

    def film() -> None:
        frames.clear()
        film_scenario(scenario, lambda f: frames.append(None), WIDTH, HEIGHT, FPS)

    t_film = median_time(film, repeats)
    nframes = len(frames)
    out: dict[str, object] = {
        "robot": robot, "backend": draw["backend"], "mujoco": mujoco.__version__,
        "draw_fps": draw["no_shadows"], "draw_shadows_fps": draw["shadows"],
        "film_fps": nframes / t_film, "frames": nframes, "encode_fps": None,
        "machine": f"{platform.machine()}, {os.cpu_count()} CPU cores",
    }
    out["gl_vendor"], out["gl_renderer"] = _gl_strings()
    try:
        import imageio_ffmpeg

        imageio_ffmpeg.get_ffmpeg_exe()
    except (ImportError, RuntimeError):  # no encoder here: the column says so
        return out
    kept: list = []
    film_scenario(scenario, lambda f: kept.append(f.copy()), WIDTH, HEIGHT, FPS)

    def encode() -> None:
        with tempfile.TemporaryDirectory() as tmp, \
                rendering.video_writer(Path(tmp) / "c.mp4", WIDTH, HEIGHT, FPS) as write:
            for f in kept:
                write(f)

    out["encode_fps"] = len(kept) / median_time(encode, repeats)
    return out


def table(r: dict[str, object]) -> str:
    """One Markdown table of :func:`measure`'s figures."""
    enc = "no ffmpeg here" if r["encode_fps"] is None else f"{r['encode_fps']:.0f}"
    return "\n".join([
        f"`python -m wmr_mujoco.bench.render_speed`: {r['robot']} at {WIDTH}×{HEIGHT}, "
        f"MuJoCo {r['mujoco']}, MUJOCO_GL={r['backend']}, OpenGL renderer "
        f"\"{r['gl_renderer']}\" ({r['gl_vendor']}), {r['machine']}; frames/s, medians.",
        "",
        "| draw (as `wmr render`) | draw with shadows and reflections | film: `wmr render` "
        "without the encoder | encode (H.264, CPU) |",
        "|---|---|---|---|",
        f"| {r['draw_fps']:.0f} | {r['draw_shadows_fps']:.0f} | {r['film_fps']:.0f} | {enc} |",
    ])


def main(argv: Sequence[str] | None = None) -> int:
    """Measure, print the table and write it to ``--out`` if given."""
    parser = argparse.ArgumentParser(prog="python -m wmr_mujoco.bench.render_speed",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, help="write the table to this .md file")
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args(argv)
    from wmr_mujoco.atomic import write_text_atomic
    from wmr_mujoco.render.gl_backend import select_backend

    if args.out is not None and not args.out.parent.is_dir():
        parser.error(f"--out {str(args.out)!r}: folder {str(args.out.parent)!r} does not "
                     "exist")
    select_backend()
    text = table(measure(args.repeats))
    print(text)
    if args.out is not None:
        write_text_atomic(args.out, text + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
