"""omni3's coasting energy budget: the contact work closes the energy balance."""

import pytest

from wmr_mujoco.bench import omni_energy_study as es


def test_contact_work_closes_the_energy_balance():
    """A short pure-translation coast: the contact rows' work, summed over every step,
    equals the change of kinetic + potential energy to within 5 % (the per-step
    midpoint rule for f · J q̇ against MuJoCo's own energy), and energy is lost."""
    m = {x.name: x.value for x in es.coast_energy_budget((0.3, 0.0, 0.0), drive_time=0.8,
                                                          duration=0.4)}
    assert m["mechanical energy change per second"] < 0
    assert m["closure: |work − change| / |change|"] < 0.05


@pytest.mark.parametrize("kwargs, match", [({"twist": (0.3, float("nan"), 0.0)}, "twist"),
                                           ({"duration": 0.0}, "duration"),
                                           ({"contact_timeconst": 0.0}, "contact_timeconst")])
def test_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        es.coast_energy_budget(**kwargs)
