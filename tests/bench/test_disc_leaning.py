"""The leaning-start contact study: its refsafe premise against MuJoCo, and its table."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from wmr_mujoco.bench import disc_leaning as dl
from wmr_mujoco.robots.disc_free import measurements as ms
from wmr_mujoco.robots.disc_free.state import FreeRun


def _rows(setting: dl.Setting, seconds: float = 0.5) -> np.ndarray:
    model = setting.model()
    disc = FreeRun(model, np.zeros(8), seconds).disc
    state = disc.initial_state(*ms.LEANING_START)
    return FreeRun(model, state, seconds).rows()


def test_effective_timeconst_is_what_mujoco_simulates() -> None:
    # MuJoCo's refsafe: a time constant below 2 Δt runs as 2 Δt. Two models that differ
    # only there must step identically (bit for bit: the same numbers enter the solver),
    # while a time constant above 2 Δt must change the run (the premise is not vacuous).
    clamped = _rows(dl.rk4_setting(0.002, 0.001))
    at_limit = _rows(dl.rk4_setting(0.002, 0.004))
    softer = _rows(dl.rk4_setting(0.002, 0.008))
    assert dl.effective_timeconst(0.002, 0.001) == pytest.approx(0.004)
    assert dl.effective_timeconst(0.002, 0.008) == pytest.approx(0.008)
    np.testing.assert_array_equal(clamped, at_limit)
    # 0.5 s of a leaning start: the 8 ms contact sinks and lags more; its lean differs by
    # far more than round-off (1e-9 rad is ~1e6 ulps of 0.15 rad).
    assert np.abs(softer[:, 4] - at_limit[:, 4]).max() > 1e-9


def test_the_default_row_is_the_shipped_free_disc() -> None:
    # The study's first row must be the model users get: the same leaning start, step
    # for step (bit for bit: the same compiled numbers).
    from wmr_mujoco.models.loading import load
    from wmr_mujoco.robots import disc_free

    shipped = load(disc_free.SPEC)
    disc = FreeRun(shipped, np.zeros(8), 0.2).disc
    state = disc.initial_state(*ms.LEANING_START)
    np.testing.assert_array_equal(FreeRun(shipped, state, 0.2).rows(),
                                  _rows(dl.SETTINGS[0], 0.2))


def test_refsafe_is_on_in_the_free_disc() -> None:
    # The study's premise holds only while the model keeps MuJoCo's refsafe flag.
    model = dl.rk4_setting(0.004, 0.004).model()
    assert not model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_REFSAFE


def test_evaluate_takes_the_worst_draw() -> None:
    # The family's worst of each column is the largest of the single draws' figures.
    setting = dl.rk4_setting(0.004, 0.004)
    draws = [{"lean": 0.15, "speed": 1.0}, {"lean": 0.13, "speed": 0.85}]
    model = setting.model()
    singles = [{m.name: abs(m.value) for m in ms.leaning_start(model, d["lean"],
                                                               d["speed"]).metrics}
               for d in draws]
    row = dl.evaluate(setting, draws)
    for head, name, _ in dl.COLUMNS:
        assert row[head] == max(s[name] for s in singles)
    assert row["evals"] == pytest.approx(1000.0)  # RK4: 4 evaluations a 4 ms step


def test_family_draws_are_the_scenarios() -> None:
    # Seeded like every family: the same seed gives the same draws, within ±20 %.
    draws = dl.family_draws(0)
    assert draws == dl.family_draws(0)
    assert len(draws) >= 20
    for d in draws:
        assert 0.8 * ms.LEANING_START[0] <= d["lean"] <= 1.2 * ms.LEANING_START[0]
        assert 0.8 * ms.LEANING_START[1] <= d["speed"] <= 1.2 * ms.LEANING_START[1]


def test_table_names_targets_and_rows() -> None:
    row = {"path": 1.0, "lean": 2.0, "energy": 0.3, "speed": 0.85, "evals": 1000.0,
           "path target": 1.0, "lean target": 1.0, "energy target": 0.5}
    text = dl.table([(dl.rk4_setting(0.004, 0.004), row)], 20)
    assert "target 0.5" in text and "effective 8 ms" in text and "20 draws" in text
