"""The fidelity-versus-cost study: its settings and its table."""

from __future__ import annotations

import dataclasses

from wmr_mujoco import whipple_study as ws
from wmr_mujoco.whipple_params import WhippleParams


def test_configs_change_only_simulation_settings():
    base = WhippleParams()
    configs = ws.study_configs(base)
    assert configs[0] == ("default", base)
    labels = [label for label, _ in configs]
    assert len(labels) == len(set(labels))
    for _, p in configs[1:]:
        assert p.sim != base.sim
        assert dataclasses.replace(p, sim=base.sim) == base


def test_default_row_meets_all_and_tables():
    row = ws.measure_row("default", WhippleParams())
    assert row.meets_all and row.rtf > 1.0
    text = ws.table([row])
    assert text.count("|") >= 26 and "**default**" in text
