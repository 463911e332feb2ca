"""Units of work: a robot's families prepared together give what each gives alone."""

import dataclasses

import pytest

from wmr_mujoco.robots import get_spec
from wmr_mujoco.validation.members import run_family
from wmr_mujoco.validation.units import run_unit, unit_hint, units


def test_units_group_a_specs_prepared_together_families_in_declared_order():
    spec = get_spec("omni3")
    work = [(spec, s) for s in spec.scenarios]
    grouped = units(work)
    together = [i for i, (_, s) in enumerate(work) if s.name in spec.prepared_together]
    assert len(together) == 14  # 10 step and 4 torque families
    assert together in grouped
    assert sorted(i for u in grouped for i in u) == list(range(len(work)))
    assert all(len(u) == 1 for u in grouped if u != together)
    assert [u[0] for u in grouped] == sorted(u[0] for u in grouped)
    hints = {s.key: 1.0 for _, s in work}
    assert unit_hint(work, together, hints) == 14.0
    assert unit_hint(work, together, {}) is None


def test_a_spec_without_prepare_cannot_name_families_together():
    spec = get_spec("omni3")
    with pytest.raises(ValueError, match="prepared_together"):
        dataclasses.replace(spec, prepare=None)
    with pytest.raises(ValueError, match="no such"):
        dataclasses.replace(spec, prepared_together=("no such",))


def test_a_unit_gives_each_familys_own_result():
    # Two step families of two draws each, prepared in one batch, against each run alone
    # (its own batch of two): the same rows, to the bit; every draw judged.
    spec = get_spec("omni3")
    names = ("step 0°", "torque along y")
    calls = []

    def prepare(members, params):  # the robot's own prepare, its calls counted
        calls.append(len(members))
        spec.prepare(members, params)

    work = [(dataclasses.replace(spec, prepare=prepare), s) for s in spec.scenarios
            if s.name in names]
    together = run_unit(work, [0, 1], seed=3, draws=2)
    assert calls[0] == 4  # the unit prepared both families' members in one call first
    for (i, result), (sp, s) in zip(together, work, strict=True):
        assert work[i][1] is s
        alone = run_family(sp, s, 3, 2)
        assert [r.value for r in result.rows] == [r.value for r in alone.rows]
        assert [m.scenario.draw for m in result.members] == \
            [m.scenario.draw for m in alone.members]
        assert len(result.members) == 2 and result.seconds > 0
