"""The spread figure: every member of every judged metric against its target."""

import math

import matplotlib.pyplot as plt
import numpy as np
import pytest

from wmr_mujoco.validation.family_plots import (
    FLOOR,
    colour,
    plot_spreads,
    ratios,
    spread_figure,
)
from wmr_mujoco.validation.worst import Spread


@pytest.fixture(autouse=True)
def _close_figures():
    """Close every figure a test drew (pyplot keeps them open)."""
    yield
    plt.close("all")


def test_ratios_are_value_over_target_floored_and_inf_where_not_finite():
    got = ratios([0.5, -2.0, 0.0, math.nan, math.inf], 2.0)
    # |0.5|/2, |-2|/2, 0 clipped to the floor, NaN and inf drawn past the target
    np.testing.assert_array_equal(got, [0.25, 1.0, FLOOR, math.inf, math.inf])


def test_a_row_is_grey_when_open_blue_when_met_red_when_missed():
    def spread(open_, passed):
        return Spread("m", "m", (0.1,), 1.0, open_, passed)

    assert colour(spread(True, False)) == "tab:gray"
    assert colour(spread(False, True)) == "tab:blue"
    assert colour(spread(False, False)) == "tab:red"


def _rows(n, grow=1):
    """``n`` rows whose labels grow longer down the figure, the last one the widest."""
    rng = np.random.default_rng(1)
    return [("family " + "x" * (grow * k) + f": metric {k} (N=20)",
             Spread(f"m{k}", "m", tuple(rng.uniform(0.01, 0.9, 20)), 1.0, False, True))
            for k in range(n)]


@pytest.mark.parametrize("n", [1, 12, 60])
def test_every_row_label_fits_in_the_figure_and_the_first_row_is_on_top(n):
    """The margins come from the widest label (no ``tight_layout``): every label's box
    must lie inside the figure and left of the axes, whatever the number of rows."""
    fig = spread_figure(_rows(n), "title")
    (ax,) = fig.axes
    renderer = fig.canvas.get_renderer()
    fig.draw(renderer)
    labels = ax.get_yticklabels()
    assert [t.get_text() for t in labels] == [label for label, _ in _rows(n)]
    axes_left = ax.get_window_extent(renderer).x0
    for t in labels:
        box = t.get_window_extent(renderer)
        assert box.x0 >= 0.0 and box.x1 <= axes_left, t.get_text()
    bottom, top = ax.get_ylim()
    assert top < bottom  # row 0 (y = 0) is drawn at the top


def test_the_figure_draws_three_artists_whatever_the_rows():
    """Dots, medians and rings: one artist each (a figure of 60 rows is as cheap to lay
    out as one of 6), besides the target line."""
    for n in (6, 60):
        (ax,) = spread_figure(_rows(n), "t").axes
        assert len(ax.collections) == 3 and len(ax.lines) == 1
        dots, medians, rings = ax.collections
        assert len(dots.get_offsets()) == 20 * n
        assert len(medians.get_segments()) == n and len(rings.get_offsets()) == n


def test_plot_spreads_writes_a_png_or_nothing(tmp_path):
    from wmr_mujoco.lookup import validation_jobs
    from wmr_mujoco.validation.members import run_families

    assert plot_spreads([], "t", tmp_path / "none.png") is None
    results = run_families(validation_jobs(["single_steer"])[:1], draws=2, jobs=1)
    path = plot_spreads(results, "t", tmp_path / "spread.png")
    assert path == tmp_path / "spread.png"
    assert path.read_bytes().startswith(b"\x89PNG")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["spread.png"]  # no temporary


def test_labels_wider_than_the_figure_widen_it_and_still_fit():
    """A label of 300 characters (no metric has one) widens the figure; the plot keeps
    its least width beside it."""
    from wmr_mujoco.validation.family_plots import PLOT_WIDTH, WIDTH

    fig = spread_figure(_rows(60, grow=5), "t")
    (ax,) = fig.axes
    renderer = fig.canvas.get_renderer()
    fig.draw(renderer)
    assert fig.get_figwidth() > WIDTH
    assert ax.get_position().width * fig.get_figwidth() >= PLOT_WIDTH - 1e-9
    assert min(t.get_window_extent(renderer).x0 for t in ax.get_yticklabels()) >= 0.0
    xlabel = ax.xaxis.label.get_window_extent(renderer)  # the axis label fits under it
    assert 0.0 <= xlabel.x0 and xlabel.x1 <= fig.bbox.width
