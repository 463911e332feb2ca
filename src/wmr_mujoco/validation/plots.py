"""The report's figures: a scenario's states against the model, or a measurement's curves.

Drawing only (matplotlib's Agg backend, imported when a figure is drawn); every file is
written atomically. `wmr validate` draws each scenario's figure as its family is done
(``run_families``' ``draw``: :func:`scenario_png`, in the worker process that ran it), and
the report (:func:`wmr_mujoco.validation.report.write_report`) writes those and draws
any other.
"""

from __future__ import annotations

import io
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from wmr_mujoco.analytic.planar import wrap_angle
from wmr_mujoco.atomic import atomic_path

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from wmr_mujoco.validation.metrics import Series, Trace
    from wmr_mujoco.validation.runner import ScenarioResult

#: A path whose shorter extent is under this fraction of its longer one is drawn on axes
#: of unequal scale: at equal scale a lane change of 0.4 m over 16 m is a flat line.
EQUAL_SCALE_MIN = 0.1
#: Width of one panel and height of a figure, inches.
PANEL_WIDTH, FIGURE_HEIGHT = 4.33, 3.8
#: Margins of a figure, inches (room for the axis labels and the title).
LEFT, RIGHT, BOTTOM, TOP = 0.85, 0.13, 0.53, 0.65


def _equal_scale(points: Sequence[np.ndarray]) -> bool:
    """Whether planar ``(N, 2)`` paths look right at equal scale (see EQUAL_SCALE_MIN)."""
    xy = np.concatenate([np.asarray(p)[:, :2] for p in points])
    extent = np.ptp(xy, axis=0)
    return bool(extent.min() >= EQUAL_SCALE_MIN * extent.max())


def _panels(trace: Trace, tr: dict[str, np.ndarray]) -> int:
    """How many panels a scenario's figure fills (never an empty one)."""
    if trace.series:
        return min(3, len({(s.xlabel, s.ylabel) for s in trace.series}))
    slip = tr["slip"].ndim == 2 and tr["slip"].shape[1] > 0
    return 3 if trace.is_pose or len(trace.state_names) > 3 or slip else 2


def _plot_states(axes: Sequence[Axes], tr: dict[str, np.ndarray], trace: Trace) -> None:
    """Panels of a kinematic or dynamic run, chosen by the adapter's state."""
    t, sim, ana = tr["time"], tr["sim"], tr["analytic"]
    names, units = trace.state_names, trace.state_units
    if trace.is_pose:
        axes[0].plot(sim[:, 0], sim[:, 1], label="MuJoCo")
        axes[0].plot(ana[:, 0], ana[:, 1], "--", label="analytic")
        axes[0].set(xlabel="x [m]", ylabel="y [m]", title="trajectory")
        if _equal_scale([sim, ana]):
            axes[0].set_aspect("equal", adjustable="datalim")
        else:  # a long, narrow path: each axis scaled to its own extent
            axes[0].set_title("trajectory (x and y not to scale)")
        axes[1].plot(t, 1000 * np.linalg.norm(sim[:, :2] - ana[:, :2], axis=1))
        axes[1].set(xlabel="t [s]", ylabel="position error [mm]", title="error over time")
        rest = range(3, len(names))
    else:
        axes[0].plot(t, sim[:, 0], label="MuJoCo")
        axes[0].plot(t, ana[:, 0], "--", label="analytic")
        axes[0].set(xlabel="t [s]", ylabel=f"{names[0]} [{units[0]}]", title=names[0])
        axes[1].plot(t, sim[:, 1:] - ana[:, 1:])
        axes[1].set(xlabel="t [s]", title="MuJoCo − model",
                    ylabel=", ".join(f"{n} [{u}]" for n, u in zip(names[1:], units[1:],
                                                                   strict=True)))
        rest = range(len(names), len(names))
    axes[0].legend()
    if len(axes) < 3:
        return
    if len(rest):
        for i in rest:
            axes[2].plot(t, sim[:, i], label=f"{names[i]} [{units[i]}] MuJoCo")
            axes[2].plot(t, ana[:, i], "--", label=f"{names[i]} model")
        axes[2].set(xlabel="t [s]", title="further states")
        axes[2].legend(fontsize=7)
    elif tr["slip"].ndim == 2 and tr["slip"].shape[1]:
        axes[2].plot(t, 1000 * tr["slip"])
        axes[2].set(xlabel="t [s]", ylabel="lateral slip [mm/s]", title="slip at wheel contacts")
    elif trace.is_pose:
        axes[2].plot(t, np.degrees(wrap_angle(sim[:, 2] - ana[:, 2])))
        axes[2].set(xlabel="t [s]", ylabel="heading error [deg]", title="heading error")
    else:
        axes[2].set_axis_off()


def _plot_series(axes: Sequence[Axes], series: Sequence[Series]) -> None:
    """A measurement's own curves, one panel per pair of axis labels (three at most)."""
    groups: dict[tuple[str, str], list[Series]] = {}
    for s in series:
        groups.setdefault((s.xlabel, s.ylabel), []).append(s)
    for ax, ((xlabel, ylabel), members) in zip(axes, list(groups.items())[:len(axes)],
                                                strict=False):
        for s in members:
            colour = {} if s.color is None else {"color": s.color}
            ax.plot(s.x, s.y, s.style, label=s.label, ms=4, **colour)
        ax.set(xlabel=xlabel, ylabel=ylabel)
        ax.legend(fontsize=7)
    for ax in axes[len(groups):]:
        ax.set_axis_off()


def fix_layout(fig: Figure) -> None:
    """Lay the figure out once (``tight_layout``) and keep that layout for saving.

    ``tight_layout`` leaves a placeholder layout engine behind, which makes ``savefig``
    draw the whole figure once more before drawing it to the file; the layout is final
    here, so the engine goes and the figure is drawn once.
    """
    fig.tight_layout()
    fig.set_layout_engine(None)


def plot_series(series: Sequence[Series], path: Path, title: str = "") -> Path:
    """One figure of curves alone (e.g. a measurement's series for a model README).

    One panel per pair of axis labels, as in the report (three at most).
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = min(3, max(1, len({(s.xlabel, s.ylabel) for s in series})))
    fig, axes = plt.subplots(1, panels, figsize=(7 * panels, 4.5), squeeze=False)
    _plot_series(axes[0], series)
    if title:
        fig.suptitle(title)
    fix_layout(fig)
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=100)
    plt.close(fig)
    return path


def trace_figure(trace: Trace, title: str) -> Figure:
    """The figure of :func:`plot_trace`: as many panels as there are curves to show.

    Panels of one fixed size, figures as wide as their panels (no blank panel):
    fixed margins in inches, a third of the figure's cost less than laying it out with
    ``tight_layout`` (the report draws about a hundred).
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    tr = trace.arrays()
    n = _panels(trace, tr)
    width = n * PANEL_WIDTH
    # Titles at a fixed height: nothing is drawn above an axes, so matplotlib's search
    # for a free height (the bounding boxes of every tick label) finds the same place,
    # at a seventh of the figure's cost (the same PNG bytes).
    with matplotlib.rc_context({"axes.titley": 1.0}):
        fig, axes = plt.subplots(1, n, figsize=(width, FIGURE_HEIGHT), squeeze=False)
    if trace.series:
        _plot_series(axes[0], trace.series)
    else:
        _plot_states(axes[0], tr, trace)
    fig.suptitle(title)
    fig.subplots_adjust(left=LEFT / width, right=1 - RIGHT / width,
                        bottom=BOTTOM / FIGURE_HEIGHT, top=1 - TOP / FIGURE_HEIGHT,
                        wspace=0.3)
    return fig


def trace_png(trace: Trace, title: str) -> bytes | None:
    """The PNG file of :func:`plot_trace`'s figure, in memory (None: nothing to plot).

    What ``wmr validate`` draws as each family is done (``ScenarioResult.figure``), for
    the report to write: the bytes :func:`plot_trace` writes.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    tr = trace.arrays()
    if tr["time"].size < 2 and not trace.series:
        return None
    fig = trace_figure(trace, title)
    try:
        buffer = io.BytesIO()
        fig.savefig(buffer, format="png", dpi=80)
    finally:  # a failed drawing leaves no open figure behind in a long-lived process
        plt.close(fig)
    return buffer.getvalue()


def write_png(png: bytes, path: Path) -> Path:
    """Write a PNG file's bytes to ``path`` atomically."""
    with atomic_path(path) as tmp:
        tmp.write_bytes(png)
    return path


def plot_trace(trace: Trace, title: str, path: Path) -> Path | None:
    """A scenario's figure: trajectory (physics over analytic), error, slip or states.

    A measurement's own curves (``trace.series``) are plotted instead. The file is a PNG
    whatever ``path``'s suffix. Returns None when there is nothing to plot.
    """
    png = trace_png(trace, title)
    return None if png is None else write_png(png, path)


def plot_scenario(result: ScenarioResult, path: Path) -> Path | None:
    """Trajectory (physics over analytic), error over time, slip or further states.

    A measurement scenario's own curves are plotted instead (see :func:`plot_trace`).
    Returns None when there is nothing to plot. A figure the run drew
    (``result.figure``) is written as it is.
    """
    png = result.figure if result.figure is not None else scenario_png(result)
    return None if png is None else write_png(png, path)


def scenario_png(result: ScenarioResult) -> bytes | None:
    """:func:`plot_scenario`'s figure as a PNG file's bytes (None: nothing to plot)."""
    return trace_png(result.trace, result.scenario.key)
