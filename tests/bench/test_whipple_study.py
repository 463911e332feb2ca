"""The Whipple fidelity-versus-cost study: its settings, its rows and its tables."""

from __future__ import annotations

import dataclasses

from wmr_mujoco.bench import whipple_study as ws
from wmr_mujoco.robots.whipple import eigen
from wmr_mujoco.robots.whipple.params import WhippleParams


def test_configs_change_only_simulation_settings():
    base = WhippleParams()
    configs = ws.study_configs(base)
    assert configs[0] == ("default", base)
    labels = [label for label, _ in configs]
    assert len(labels) == len(set(labels)) and "implicitfast" in labels
    for _, p in configs[1:]:
        assert p.sim != base.sim
        assert dataclasses.replace(p, sim=base.sim) == base


def test_default_row_meets_all_and_tables():
    row = ws.measure_row("default", WhippleParams())
    assert row.meets_all and row.rtf > 1.0
    text = ws.table([row])
    assert text.count("|") >= 26 and "**default**" in text


def test_split_contact_pairs_reproduce_the_default_model():
    """With equal normal and frictional time constants the explicit pairs are the same
    contact as the geoms' own: the eigenvalues agree to FD noise (1e-6 1/s)."""
    p = WhippleParams()
    tau = p.sim.contact_timeconst
    split = ws.split_contact_model(p, tau, tau)
    assert split.npair == 2
    a = eigen.measure_modes(p, 5.0, split).benchmark
    b = eigen.measure_modes(p, 5.0).benchmark
    assert abs(a - b).max() < 1e-6


def test_self_stability_text_says_where_the_benchmark_cannot_meet_10_percent():
    text = ws.self_stability_text()
    lines = text.splitlines()
    assert len(lines) == 3
    assert "cannot meet the 10 % floor" in lines[2] and "5.5 m/s" in lines[2]
    assert "cannot" not in lines[0] + lines[1]
