"""The report's figures."""


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


def test_a_figure_drawn_in_memory_is_the_file_plot_trace_writes(tmp_path):
    """``trace_png`` (what the worker processes draw) and ``plot_trace`` (the report's own
    drawing) give the same bytes, so a report does not depend on where it was drawn; a
    trace of fewer than two samples has nothing to draw and writes no file."""
    import numpy as np

    from wmr_mujoco.validation.plots import plot_trace, trace_png

    x = np.linspace(0.0, 1.0, 11)
    png = trace_png(_pose_trace(x, x ** 2), "t")
    assert png is not None and png.startswith(b"\x89PNG")
    path = plot_trace(_pose_trace(x, x ** 2), "t", tmp_path / "f.png")
    assert path.read_bytes() == png
    assert trace_png(_pose_trace(x[:1], x[:1]), "t") is None
    assert plot_trace(_pose_trace(x[:1], x[:1]), "t", tmp_path / "g.png") is None
    assert not (tmp_path / "g.png").exists()
