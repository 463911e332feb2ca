"""MuJoCo's soft contact in closed form, checked against MuJoCo itself."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.sim import soft_contact as sc


def _block(timestep: float, timeconst: float, solimp, impratio: float, free: bool = False
           ) -> tuple[mujoco.MjModel, mujoco.MjData]:
    """A 1 kg sphere resting on a floor of friction 10, settled for 0.5 s: one contact,
    its friction far from the cone's edge. On x and z slides (no rotation: a point mass
    on the contact), or free (it also rolls)."""
    imp = " ".join(str(v) for v in solimp)
    joints = ('<freejoint/>' if free else
              '<joint type="slide" axis="1 0 0"/><joint type="slide" axis="0 0 1"/>')
    xml = f"""<mujoco><option timestep="{timestep}" cone="elliptic" impratio="{impratio}"/>
      <worldbody><geom type="plane" size="1 1 .1" priority="1" solref="{timeconst} 1"
        solimp="{imp}" friction="10 0.005 0.0001"/>
      <body pos="0 0 0.05">{joints}
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


def _slips(model: mujoco.MjModel, data: mujoco.MjData, free: bool) -> np.ndarray:
    """The contact point's slip, m/s, at a 1 cm/s push and after each of four steps."""
    data.qvel[0] = 0.01
    radius = 0.05

    def slip() -> float:  # contact point velocity along x: v_x − ω_y R (free) or v_x
        return float(data.qvel[0] - (radius * data.qvel[4] if free else 0.0))

    speeds = [slip()]
    for _ in range(4):
        mujoco.mj_step(model, data)
        speeds.append(slip())
    return np.array(speeds)


@pytest.mark.parametrize("timestep", [0.002, 0.001, 0.0005, 0.00025])
@pytest.mark.parametrize("impratio", [1.0, 10.0])
@pytest.mark.parametrize("solimp", [(0.95, 0.99, 0.001, 0.5, 2.0), (0.9, 0.95, 4e-6, 0.5, 2.0)])
def test_slip_relaxation_is_mujocos_per_step_decay(timestep, impratio, solimp):
    """A resting point mass given 1 cm/s along the floor: MuJoCo's slip shrinks by the same
    factor every step, and that factor is ρ = 1 − Δt d_f b, the exact case (the row's
    inverse inertia is MuJoCo's diagonal approximation of it); at Δt = t_c MuJoCo's
    refsafe raises t_c to 2 Δt. The slips are ρⁿ times the push to 1e-10 m/s (rounding
    of centimetre-per-second speeds)."""
    model, data = _block(timestep, 0.002, solimp, impratio)
    penetration = -data.contact[0].dist
    rho = sc.slip_relaxation(timestep, 0.002, solimp, penetration, impratio)
    np.testing.assert_allclose(_slips(model, data, free=False), 0.01 * rho ** np.arange(5),
                               rtol=0, atol=1e-10)


@pytest.mark.parametrize("timestep", [0.001, 0.0005])
@pytest.mark.parametrize("impratio", [1.0, 10.0])
def test_slip_relaxation_bounds_a_rolling_body(timestep, impratio):
    """A free sphere (it also rolls, so the row's inverse inertia is 7/2 of MuJoCo's
    diagonal approximation): over the first step its slip decays faster than the closed
    form's ρ, by at most Δt b (1 − d_f) (module docstring), a small bound at impratio 10.
    (Afterwards the sphere rolls and the slip is rounding.)"""
    solimp = (0.9, 0.95, 0.001, 0.5, 2.0)
    model, data = _block(timestep, 0.002, solimp, impratio, free=True)
    penetration = -data.contact[0].dist
    rho = sc.slip_relaxation(timestep, 0.002, solimp, penetration, impratio)
    d_f = sc.friction_impedance(sc.impedance(penetration, solimp), impratio)
    bound = timestep * 2.0 / (solimp[1] * max(0.002, 2 * timestep)) * (1.0 - d_f)
    slips = _slips(model, data, free=True)
    first = slips[1] / slips[0]
    assert rho - bound - 1e-8 <= first <= rho + 1e-8


def test_friction_impedance_limits():
    # impratio 1 leaves d unchanged; a large impratio drives d_f to 1.
    assert sc.friction_impedance(0.9, 1.0) == pytest.approx(0.9, abs=1e-15)
    assert sc.friction_impedance(0.9, 1e9) == pytest.approx(1.0, abs=1e-8)


@pytest.mark.parametrize("call, match", [
    (lambda: sc.impedance(-1e-3, (0.9, 0.95, 0.001, 0.5, 2)), "violation"),
    (lambda: sc.impedance(math.nan, (0.9, 0.95, 0.001, 0.5, 2)), "violation"),
    (lambda: sc.impedance(0.0, (0.9, 1.5, 0.001, 0.5, 2)), "solimp"),
    (lambda: sc.impedance(0.0, (0.9, 0.95, 0.001)), "5 numbers"),
    (lambda: sc.friction_impedance(1.0, 1.0), "d = 1.0"),
    (lambda: sc.friction_impedance(0.9, 0.0), "impratio"),
    (lambda: sc.slip_relaxation(0.0, 0.002, (0.9, 0.95, 0.001, 0.5, 2), 0.0), "timestep"),
    (lambda: sc.slip_relaxation(0.001, -1.0, (0.9, 0.95, 0.001, 0.5, 2), 0.0), "timeconst"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def _paired_block(timestep: float, d: float, impratio: float) -> tuple[mujoco.MjModel,
                                                                        mujoco.MjData]:
    """The point-mass sphere of :func:`_block` on a floor ``<pair>`` with the sliding
    remedy's parameters (``builders.common.sliding_pair_kwargs``): impedance d, time
    constant 3 Δt, friction reference in the direct form ``(0, −d/Δt)``."""
    xml = f"""<mujoco><option timestep="{timestep}" cone="elliptic" impratio="{impratio}"/>
      <worldbody><geom name="floor" type="plane" size="1 1 .1"/>
      <body pos="0 0 0.05"><joint type="slide" axis="1 0 0"/>
        <joint type="slide" axis="0 0 1"/>
        <geom name="ball" type="sphere" size="0.05" mass="1"/></body></worldbody>
      <contact><pair geom1="floor" geom2="ball" condim="3" friction="10 10 0.005 0.0001 0.0001"
        solref="{3 * timestep} 1" solimp="{d} {d} 0.001 0.5 2"
        solreffriction="0 {-d / timestep}"/></contact></mujoco>"""
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    for _ in range(round(0.5 / timestep)):
        mujoco.mj_step(model, data)
    return model, data


@pytest.mark.parametrize("timestep", [0.002, 0.001])
@pytest.mark.parametrize("d", [0.01, 0.001])
def test_slip_relaxation_of_a_pair_with_its_own_friction_reference(timestep, d):
    """A pair's solreffriction (direct form, b = B/d_w = 1/Δt) sets the friction rows'
    damping, not its solref: MuJoCo's slip shrinks by ρ = 1 − Δt d_f b = 1 − d_f per step
    (the exact case of a point mass, to 1e-10 m/s rounding), with d_f of impratio = 10/d."""
    impratio = 10.0 / d
    model, data = _paired_block(timestep, d, impratio)
    penetration = -data.contact[0].dist
    solimp = (d, d, 0.001, 0.5, 2.0)
    rho = sc.slip_relaxation(timestep, 3 * timestep, solimp, penetration, impratio,
                             friction_ref=(0.0, -d / timestep))
    assert rho == pytest.approx(1.0 - sc.friction_impedance(d, impratio), abs=1e-12)
    np.testing.assert_allclose(_slips(model, data, free=False), 0.01 * rho ** np.arange(5),
                               rtol=0, atol=1e-10)


def test_friction_damping_forms():
    # (t_c, ζ): 2/(d_w t_c), t_c raised to 2 Δt by refsafe; direct (−K, −B): B/d_w.
    solimp = (0.9, 0.95, 0.001, 0.5, 2.0)
    assert sc.friction_damping(0.001, (0.004, 1.0), solimp) == pytest.approx(2 / (0.95 * 0.004))
    assert sc.friction_damping(0.001, (0.001, 1.0), solimp) == pytest.approx(2 / (0.95 * 0.002))
    assert sc.friction_damping(0.001, (0.0, -50.0), solimp) == pytest.approx(50 / 0.95)
    with pytest.raises(ValueError, match="solref"):
        sc.friction_damping(0.001, (0.0, 1.0), solimp)
