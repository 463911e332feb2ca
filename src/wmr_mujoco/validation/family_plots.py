"""The spread of each family, one figure per robot: every member against its target.

One row per judged (or open) metric of each scenario of the robot; each member is a dot
at ``|value| / target`` (log scale; a member at or beyond 1 misses the target), the median
a bar, the worst a ring. Drawing only (matplotlib's Agg backend); written atomically.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from wmr_mujoco.atomic import atomic_path
from wmr_mujoco.validation.family_report import judged_spreads
from wmr_mujoco.validation.runner import ScenarioResult
from wmr_mujoco.validation.worst import Spread

if TYPE_CHECKING:
    from matplotlib.figure import Figure

#: Ratios below this are drawn at it (a metric ten thousand times inside its target).
FLOOR = 1e-4
#: Height of one row, the figure's least width and its top and bottom margins (the sum:
#: ``MARGINS``), inches; the gap beside the row labels and at the right edge, inches.
ROW_HEIGHT, WIDTH, TOP, BOTTOM, PAD = 0.28, 11.0, 0.35, 0.75, 0.15
MARGINS = TOP + BOTTOM
#: Least width of the plot itself, inches (a figure whose labels leave less is wider):
#: room for its 10-point axis label under it.
PLOT_WIDTH = 6.0
#: Font size of the row labels, points; resolution of the file, dots per inch.
LABEL_SIZE, DPI = 7, 80


def ratios(values: Sequence[float], target: float) -> np.ndarray:
    """``|value| / target`` clipped below at :data:`FLOOR`; a non-finite value as inf."""
    v = np.abs(np.asarray(values, float)) / target
    v[~np.isfinite(v)] = np.inf
    return np.maximum(v, FLOOR)


def plot_spreads(results: Sequence[ScenarioResult], title: str, path: Path) -> Path | None:
    """Strip plot of every judged or open metric over its family (None: nothing to plot)."""
    rows = [(f"{res.scenario.name}: {s.metric} (N={s.n})", s)
            for res in results for s in judged_spreads(res)]
    if not rows:
        return None
    fig = spread_figure(rows, title)  # selects the Agg backend
    import matplotlib.pyplot as plt

    try:
        with atomic_path(Path(path)) as tmp:
            fig.savefig(tmp, dpi=DPI, format="png")
    finally:
        plt.close(fig)
    return Path(path)


def spread_figure(rows: Sequence[tuple[str, Spread]], title: str) -> Figure:
    """The figure of :func:`plot_spreads`: one row per ``(label, spread)``, top down.

    Three artists for all the rows (the members' dots, the medians' bars, the worst
    members' rings) besides the target's line, and margins set from the widest row label
    (measured, not laid out by ``tight_layout``, which draws every label twice): a
    robot's figure has a hundred rows.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    height = MARGINS + ROW_HEIGHT * len(rows)
    fig, ax = plt.subplots(figsize=(WIDTH, height))
    rng = np.random.default_rng(0)  # jitter only: where a dot sits within its row
    shown: list[np.ndarray] = []
    ys: list[np.ndarray] = []
    colours: list[str] = []
    for k, (_, s) in enumerate(rows):
        r = ratios(s.values, s.target or math.nan)
        shown.append(np.where(np.isfinite(r), r, 1e3))
        ys.append(k + rng.uniform(-0.25, 0.25, size=r.size))
        colours += [colour(s)] * r.size
    k = np.arange(len(rows))
    ax.scatter(np.concatenate(shown), np.concatenate(ys), s=9, color=colours, alpha=0.7,
               linewidths=0)
    ax.vlines([np.median(x) for x in shown], k - 0.35, k + 0.35, color="k", lw=1.2)
    worst = [float(x.max()) for x in shown]
    ax.scatter(worst, k, s=40, facecolors="none", edgecolors="k", lw=0.8)
    ax.axvline(1.0, color="tab:red", ls="--", lw=1.0, label="target")
    ax.set_xscale("log")
    ax.set_xlim(FLOOR / 2, max(2.0, 2 * max(1.0, *worst)))
    labels = [label for label, _ in rows]
    ax.set_yticks(k, labels, fontsize=LABEL_SIZE)
    ax.set_ylim(len(rows) - 0.5, -0.5)  # the first row on top
    ax.set_xlabel("|value| / target (dots: members; bar: median; ring: worst; "
                  "grey: open target)")
    ax.set_title(title, fontsize=9)
    ticks = (matplotlib.rcParams["ytick.major.size"] + matplotlib.rcParams["ytick.major.pad"])
    left = label_width(fig, labels) + ticks / 72 + PAD  # labels sit a tick and a pad off
    width = max(WIDTH, left + PLOT_WIDTH + PAD)  # labels too long widen the figure
    fig.set_size_inches(width, height)
    fig.subplots_adjust(left=left / width, right=1 - PAD / width,
                        bottom=BOTTOM / height, top=1 - TOP / height)
    return fig


def colour(s: Spread) -> str:
    """A row's colour: grey for an open target, blue for a met one, red for a missed one."""
    return "tab:gray" if s.open else ("tab:blue" if s.passed else "tab:red")


def label_width(fig: Figure, labels: Sequence[str]) -> float:
    """Width of the widest of ``labels`` at :data:`LABEL_SIZE` points, inches."""
    from matplotlib.font_manager import FontProperties

    renderer = fig.canvas.get_renderer()
    font = FontProperties(size=LABEL_SIZE)
    widths = [renderer.get_text_width_height_descent(t, font, ismath=False)[0]
              for t in set(labels)]
    return max(widths) / fig.dpi
