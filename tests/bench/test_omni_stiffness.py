"""omni3's contact-stiffness study: parameters, and the table's layout."""

import math

import pytest

from wmr_mujoco.bench import omni_stiffness as st


def test_shipped_setting_is_the_models_default_and_comes_first():
    """The table's first rows are what ``wmr validate`` judges: OmniParams' own contact
    time constant and step, built by :func:`stiff` into the defaults unchanged."""
    assert st.SETTINGS[0] == st.SHIPPED
    assert st.stiff(*st.SHIPPED) == st.OmniParams()


def test_stiff_parameters_change_only_the_contact_and_the_step():
    p = st.stiff(0.003, 0.001)
    assert (p.sim.contact_timeconst, p.sim.timestep) == (0.003, 0.001)
    assert p.wheel_radius == st.OmniParams().wheel_radius


# (0.0025, 0.001): 2.5 steps, under the roller-floor pairs' least 3 (WHEEL_PAIR_STEPS).
@pytest.mark.parametrize("timeconst, step", [(0.002, 0.0015), (0.0025, 0.001), (0.0, 0.001),
                                             (math.nan, 0.001), (0.002, -1.0)])
def test_stiff_bad_input(timeconst, step):
    with pytest.raises(ValueError, match="step"):
        st.stiff(timeconst, step)


def test_table_has_a_row_per_setting_and_model():
    """Two synthetic rows: the header names every torque run, each row every figure."""
    row = {"timeconst": 0.008, "step": 0.004, "met": 30.0, "rows": 39.0,
           "step position": 0.1, "step heading": 0.05, "coast yaw-rate decay": 1.0,
           "coast turn rate": 2.0, "coast energy loss": 3.0, "kinematic position": 0.1,
           "slip": math.nan, "wall": 0.01}
    for spec in st.TORQUE_SPECS:
        key = spec.name.removeprefix("torque ")
        row |= {f"{key} twist": 0.5, f"{key} position": 0.2}
    shipped = {"timeconst": st.SHIPPED[0], "step": st.SHIPPED[1]}
    text = st.table([row | shipped | {"arc": True}, row | shipped | {"arc": False},
                     row | {"arc": True}])
    lines = text.splitlines()
    assert len(lines) == 5
    assert all(line.count("|") == lines[0].count("|") for line in lines)
    assert "30 of 39" in lines[2] and "with the arc's moment (as judged)" in lines[2]
    assert "without the arc's moment" in lines[3]
    # Only the shipped setting's model is the judged one.
    assert "8 ms / 4 ms" in lines[4] and "as judged" not in lines[4]
    assert "n/a" in lines[2]
