"""The report's figures."""

import pytest


def test_plot_series_draws_points_and_curves(tmp_path):
    import numpy as np

    from wmr_mujoco.validation.metrics import Series
    from wmr_mujoco.validation.plots import plot_series

    x = np.linspace(0.0, 1.0, 11)
    series = [Series("curve", x, x ** 2, "v", "s", style="k-"),
              Series("_hidden", x, -x, "v", "s"),
              Series("points", x[::5], x[::5] ** 2, "v", "s", style="o", color="tab:red")]
    path = plot_series(series, tmp_path / "f.png", "title")
    assert path.stat().st_size > 5_000


def _pose_trace(x, y):
    import numpy as np

    from wmr_mujoco.validation.metrics import Trace

    states = [np.array([a, b, 0.0]) for a, b in zip(x, y, strict=True)]
    return Trace(time=list(np.arange(len(x)) * 0.1), sim=states, analytic=states,
                 slip=[np.zeros(0)] * len(x), state_names=("x", "y", "heading"),
                 state_units=("m", "m", "rad"))


def test_a_measurement_with_one_kind_of_curve_fills_one_panel_not_a_third_of_three():
    import numpy as np

    from wmr_mujoco.validation.metrics import Series
    from wmr_mujoco.validation.plots import PANEL_WIDTH, trace_figure

    x = np.linspace(0.0, 1.0, 11)
    trace = _pose_trace(x, x)
    trace.series = [Series("a", x, x, "v [m/s]", "τ [N·m]"), Series("b", x, -x,
                                                                    "v [m/s]", "τ [N·m]")]
    fig = trace_figure(trace, "one panel")
    assert len(fig.axes) == 1 and fig.get_figwidth() == PANEL_WIDTH
    assert all(ax.lines for ax in fig.axes)  # no blank panel


def test_a_lane_change_is_drawn_at_unequal_scale_a_square_at_equal_scale():
    """A 0.4 m shift over 16 m (the bicycle's lane change) would be a flat line at equal
    scale; a square path keeps equal scale (its shape is the point)."""
    import numpy as np

    from wmr_mujoco.validation.plots import trace_figure

    x = np.linspace(-8.0, 8.0, 81)
    lane = trace_figure(_pose_trace(x, 0.2 * np.tanh(x)), "lane change").axes[0]
    assert lane.get_aspect() == "auto" and "not to scale" in lane.get_title()
    y_low, y_high = lane.get_ylim()
    assert y_high - y_low < 1.0  # the y axis spans the shift, not the 16 m of x
    t = np.linspace(0.0, 2 * np.pi, 81)
    square = trace_figure(_pose_trace(np.cos(t), np.sin(t)), "circle").axes[0]
    assert square.get_aspect() == 1.0
    assert all(ax.lines for ax in square.figure.axes)


def test_a_trace_draws_to_png_bytes_or_to_nothing():
    """``trace_png`` gives a PNG file's bytes; under two samples there is nothing to draw."""
    import numpy as np

    from wmr_mujoco.validation.plots import trace_png

    x = np.linspace(0.0, 1.0, 11)
    png = trace_png(_pose_trace(x, x ** 2), "t")
    assert png is not None and png.startswith(b"\x89PNG\r\n\x1a\n")
    assert trace_png(_pose_trace(x[:1], x[:1]), "t") is None


def test_plot_trace_leaves_no_file_when_nothing_to_plot(tmp_path):
    import numpy as np

    from wmr_mujoco.validation.plots import plot_trace

    assert plot_trace(_pose_trace(np.zeros(1), np.zeros(1)), "t", tmp_path / "g.png") is None
    assert list(tmp_path.iterdir()) == []


def test_a_figure_the_run_drew_is_written_as_it_is_not_drawn_again(tmp_path, monkeypatch):
    """``plot_scenario`` writes ``result.figure``'s bytes (a sentinel here, not a PNG) and
    draws only where the run drew nothing."""
    import numpy as np

    from wmr_mujoco.validation import plots
    from wmr_mujoco.validation.runner import ScenarioResult

    x = np.linspace(0.0, 1.0, 11)
    result = ScenarioResult(None, [], _pose_trace(x, x), figure=b"sentinel")

    def no_drawing(*_):
        raise AssertionError("drawn again")

    monkeypatch.setattr(plots, "trace_png", no_drawing)
    assert plots.plot_scenario(result, tmp_path / "f.png").read_bytes() == b"sentinel"


def test_a_failed_write_leaves_neither_the_file_nor_a_temporary_one(tmp_path, monkeypatch):
    from pathlib import Path

    from wmr_mujoco.validation.plots import write_png

    def full_disk(self, data):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(Path, "write_bytes", full_disk)
    with pytest.raises(OSError, match="No space"):
        write_png(b"x", tmp_path / "f.png")
    assert list(tmp_path.iterdir()) == []
