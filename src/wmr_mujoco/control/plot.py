"""Figures of closed-loop runs (matplotlib, Agg backend), written atomically."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from wmr_mujoco.atomic import atomic_path
from wmr_mujoco.control.closed_loop import Comparison
from wmr_mujoco.loop.control.paths import Path as RefPath


def _figure(ncols: int):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt, *plt.subplots(1, ncols, figsize=(5.0 * ncols, 4.2))


def plot_comparison(comp: Comparison, path: RefPath, out: Path) -> Path:
    """Both runs' trajectories over the path, and their cross-track errors; PNG."""
    plt, fig, (ax, ax2) = _figure(2)
    ax.plot(path.xy[:, 0], path.xy[:, 1], color="0.6", lw=3, label="path")
    for run, style in ((comp.model, "--"), (comp.physics, "-")):
        label = "physics (mujoco)" if run.backend == "mujoco" else f"model ({run.backend})"
        ax.plot(run.pose[:, 0], run.pose[:, 1], style, lw=1.2, label=label)
        ax2.plot(run.time, 1000 * run.cross_track, style, lw=1.2, label=label)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.legend(fontsize=8)
    ax2.set_xlabel("time [s]")
    ax2.set_ylabel("cross-track error [mm]")
    ax2.axhline(0.0, color="0.7", lw=0.8)
    ax2.legend(fontsize=8)
    fig.tight_layout()
    with atomic_path(out) as tmp:
        fig.savefig(tmp, dpi=110, format="png")
    plt.close(fig)
    return Path(out)


def plot_leans(runs: Sequence[tuple[bool, object, object]], out: Path) -> Path:
    """Lean against time: ``(controlled, physics run, linear run)`` each; PNG."""
    plt, fig, ax = _figure(1)
    for controlled, phys, lin in runs:
        tag = "LQR" if controlled else "no control"
        ax.plot(phys.time, np.asarray(phys.lean), "-", label=f"physics, {tag}")
        ax.plot(lin.time, np.asarray(lin.lean), "--", label=f"linear model, {tag}")
    ax.set_ylim(-1.3, 1.3)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("lean [rad]")
    ax.legend(fontsize=8)
    fig.tight_layout()
    with atomic_path(out) as tmp:
        fig.savefig(tmp, dpi=110, format="png")
    plt.close(fig)
    return Path(out)
