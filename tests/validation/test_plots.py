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
