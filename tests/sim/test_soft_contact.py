"""MuJoCo's soft contact in closed form, checked against MuJoCo itself."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.sim import soft_contact as sc


def _block(timestep: float, timeconst: float, solimp, impratio: float
           ) -> tuple[mujoco.MjModel, mujoco.MjData]:
    """A 1 kg sphere on x and z slides (no rotation) resting on a floor of friction 10,
    settled for 0.5 s: one contact, its friction far from the cone's edge."""
    imp = " ".join(str(v) for v in solimp)
    xml = f"""<mujoco><option timestep="{timestep}" cone="elliptic" impratio="{impratio}"/>
      <worldbody><geom type="plane" size="1 1 .1" priority="1" solref="{timeconst} 1"
        solimp="{imp}" friction="10 0.005 0.0001"/>
      <body pos="0 0 0.05"><joint type="slide" axis="1 0 0"/><joint type="slide" axis="0 0 1"/>
        <geom type="sphere" size="0.05" mass="1"/></body></worldbody></mujoco>"""
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    for _ in range(round(0.5 / timestep)):
        mujoco.mj_step(model, data)
    return model, data


def test_impedance_sigmoid_by_hand():
    # x = 0: d0; x = mid: d0 + mid (dw − d0) (y(mid) = mid^p / mid^(p−1) = mid);
    # x ≥ 1: dw; the two branches meet at mid.
    solimp = (0.9, 0.95, 0.002, 0.5, 2.0)
    assert sc.impedance(0.0, solimp) == 0.9
    assert sc.impedance(0.001, solimp) == pytest.approx(0.9 + 0.5 * 0.05, abs=1e-15)
    assert sc.impedance(0.01, solimp) == 0.95
    below, above = sc.impedance(0.001 - 1e-12, solimp), sc.impedance(0.001 + 1e-12, solimp)
    assert abs(above - below) < 1e-9


@pytest.mark.parametrize("width", [1e-3, 4e-6])
def test_impedance_is_mujocos_at_the_resting_penetration(width):
    """The normal row's impedance MuJoCo reports (efc_KBIP[:, 2]) at the contact's own
    penetration, with a width far beyond it (x ≪ mid) and one near it (x > mid)."""
    solimp = (0.9, 0.95, width, 0.5, 2.0)
    _, data = _block(0.001, 0.002, solimp, 1.0)
    penetration = -data.contact[0].dist
    assert sc.impedance(penetration, solimp) == pytest.approx(data.efc_KBIP[0, 2], abs=1e-12)


@pytest.mark.parametrize("timestep", [0.001, 0.0005, 0.00025])
@pytest.mark.parametrize("impratio", [1.0, 10.0])
@pytest.mark.parametrize("solimp", [(0.95, 0.99, 0.001, 0.5, 2.0), (0.9, 0.95, 4e-6, 0.5, 2.0)])
def test_slip_relaxation_is_mujocos_per_step_decay(timestep, impratio, solimp):
    """A resting block given 1 cm/s along the floor: MuJoCo's slip shrinks by the same
    factor every step, and that factor is ρ = 1 − Δt d_f b. Tolerance 2e-3: the normal
    row is coupled to the friction rows only through the cone (the block neither rises nor
    sinks measurably over four steps), which is what the closed form leaves out."""
    model, data = _block(timestep, 0.002, solimp, impratio)
    penetration = -data.contact[0].dist
    data.qvel[0] = 0.01
    speeds = [data.qvel[0]]
    for _ in range(4):
        mujoco.mj_step(model, data)
        speeds.append(data.qvel[0])
    ratios = np.array(speeds[1:]) / np.array(speeds[:-1])
    rho = sc.slip_relaxation(timestep, 0.002, solimp, penetration, impratio)
    np.testing.assert_allclose(ratios, rho, rtol=0, atol=2e-3)


def test_friction_impedance_limits():
    # impratio 1 leaves d unchanged; a large impratio drives d_f to 1.
    assert sc.friction_impedance(0.9, 1.0) == pytest.approx(0.9, abs=1e-15)
    assert sc.friction_impedance(0.9, 1e9) == pytest.approx(1.0, abs=1e-8)


@pytest.mark.parametrize("call, match", [
    (lambda: sc.impedance(-1e-3, (0.9, 0.95, 0.001, 0.5, 2)), "violation"),
    (lambda: sc.impedance(math.nan, (0.9, 0.95, 0.001, 0.5, 2)), "violation"),
    (lambda: sc.impedance(0.0, (0.9, 1.5, 0.001, 0.5, 2)), "solimp"),
    (lambda: sc.friction_impedance(1.0, 1.0), "d = 1.0"),
    (lambda: sc.friction_impedance(0.9, 0.0), "impratio"),
    (lambda: sc.slip_relaxation(0.0, 0.002, (0.9, 0.95, 0.001, 0.5, 2), 0.0), "timestep"),
    (lambda: sc.slip_relaxation(0.001, -1.0, (0.9, 0.95, 0.001, 0.5, 2), 0.0), "timeconst"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
