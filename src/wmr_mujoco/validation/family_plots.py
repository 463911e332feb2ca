"""The spread of each family, one figure per robot: every member against its target.

One row per judged (or open) metric of each scenario of the robot; each member is a dot
at ``|value| / target`` (log scale; a member at or beyond 1 misses the target), the median
a bar, the worst a ring. Drawing only (matplotlib's Agg backend); written atomically.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from wmr_mujoco.atomic import atomic_path
from wmr_mujoco.validation.family_report import judged_spreads
from wmr_mujoco.validation.plots import fix_layout
from wmr_mujoco.validation.runner import ScenarioResult

#: Ratios below this are drawn at it (a metric ten thousand times inside its target).
FLOOR = 1e-4
#: Height of one row and the margins of the figure, inches.
ROW_HEIGHT, MARGINS = 0.28, 1.1


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
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(11.0, MARGINS + ROW_HEIGHT * len(rows)))
    rng = np.random.default_rng(0)  # jitter only: where a dot sits within its row
    top = 1.0
    for k, (_, s) in enumerate(rows):
        r = ratios(s.values, s.target or math.nan)
        shown = np.where(np.isfinite(r), r, 1e3)
        y = k + rng.uniform(-0.25, 0.25, size=r.size)
        color = "tab:gray" if s.open else ("tab:blue" if s.passed else "tab:red")
        ax.scatter(shown, y, s=9, color=color, alpha=0.7, linewidths=0)
        ax.plot([np.median(shown)] * 2, [k - 0.35, k + 0.35], color="k", lw=1.2)
        ax.scatter([shown.max()], [k], s=40, facecolors="none", edgecolors="k", lw=0.8)
        top = max(top, float(shown.max()))
    ax.axvline(1.0, color="tab:red", ls="--", lw=1.0, label="target")
    ax.set_xscale("log")
    ax.set_xlim(FLOOR / 2, max(2.0, 2 * top))
    ax.set_yticks(range(len(rows)), [label for label, _ in rows], fontsize=7)
    ax.invert_yaxis()
    ax.set_xlabel("|value| / target (dots: members; bar: median; ring: worst; "
                  "grey: open target)")
    ax.set_title(title, fontsize=9)
    fix_layout(fig)
    with atomic_path(Path(path)) as tmp:
        fig.savefig(tmp, dpi=80)
    plt.close(fig)
    return Path(path)
