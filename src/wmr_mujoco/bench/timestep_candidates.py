"""The candidate settings of the timestep study (:mod:`wmr_mujoco.bench.timestep_choice`).

A candidate is a robot's defaults at a longer step that divides every control period
users drive with (:data:`STEPS`), its floor contact either scaled with the step
(:func:`at_step`: ``t_c/Δt`` kept, ζ the robot's or another) or kept
(:func:`at_step_same_stiffness`: the contact's stiffness and rest depth kept).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from fractions import Fraction

import mujoco

from wmr_mujoco.models.loading import load
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots.spec import RobotSpec

#: The control periods users drive with, s (``wmr_mujoco.drive``, the environments).
PERIODS = (Fraction(1, 50), Fraction(1, 20), Fraction(1, 10))
#: Steps considered, s: those from 1 to 5 ms, in quarter milliseconds, that divide every
#: period of :data:`PERIODS` (1, 1.25, 2, 2.5 and 5 ms).
STEPS = tuple(float(s) for s in (Fraction(k, 4000) for k in range(4, 21))
              if all((p / s).denominator == 1 for p in PERIODS))


@dataclasses.dataclass(frozen=True)
class Candidate:
    """A robot's default parameters at another step and damping ratio.

    Attributes:
        timestep: the step, s.
        dampratio: the floor pairs' ζ.
        params: the robot's defaults with these (``t_c/Δt`` kept, or with
            ``stiffness_kept`` the contact's own ``t_c``).
        stiffness_kept: made by :func:`at_step_same_stiffness`.
    """

    timestep: float
    dampratio: float
    params: RobotParams
    stiffness_kept: bool = False


def at_step(spec: RobotSpec, timestep: float, dampratio: float | None = None) -> Candidate:
    """The robot's defaults at ``timestep`` (``t_c/Δt`` kept) and ``dampratio`` (None: its own).

    Raises:
        ValueError: a robot without parameters; a step or ζ its parameters refuse.
    """
    if spec.params_type is None:
        raise ValueError(f"robot {spec.name!r} has no parameters to change")
    base = spec.params_type()
    sim = base.sim
    zeta = sim.floor_dampratio if dampratio is None else dampratio
    new_sim = dataclasses.replace(
        sim, timestep=timestep, floor_dampratio=zeta,
        contact_timeconst=sim.contact_timeconst * timestep / sim.timestep)
    return Candidate(timestep, zeta, dataclasses.replace(base, sim=new_sim))


def candidates(spec: RobotSpec, dampratios: Sequence[float] = ()) -> list[Candidate]:
    """The default step at each other ζ, then every longer step of :data:`STEPS` at each ζ.

    ζ: the robot's own, then each of ``dampratios``. ζ does not change a step's cost: the
    default step's rows show why the robot's ζ is chosen, the longer steps' whether a
    cheaper setting keeps every target.
    """
    assert spec.params_type is not None
    own = spec.params_type().sim
    zetas = list(dict.fromkeys([own.floor_dampratio, *dampratios]))
    same = [at_step(spec, own.timestep, z) for z in zetas if z != own.floor_dampratio]
    return same + [at_step(spec, dt, z) for dt in STEPS if dt > own.timestep for z in zetas]


#: The least floor ζ the parameters take (``SimParams.floor_dampratio``).
LEAST_DAMPRATIO = 0.1


class DampratioTooSmallError(ValueError):
    """A stiffness-kept step would need a ζ' under :data:`LEAST_DAMPRATIO`."""


def pair_timeconst(spec: RobotSpec, params: RobotParams) -> float:
    """The floor pairs' effective ``solref`` time constant in the compiled model, s.

    MuJoCo runs a time constant under ``2 Δt`` at ``2 Δt`` (its ``refsafe`` flag, on by
    default): the figure is ``max(t_c, 2 Δt)`` unless the model turns the flag off.

    Raises:
        ValueError: the model has no floor pairs, or pairs of different time constants.
    """
    model = load(spec, params)
    tc = model.pair_solref[:, 0]
    if tc.size == 0 or tc.max() != tc.min():
        raise ValueError(f"robot {spec.name!r}: its floor pairs' time constants are "
                         f"{tc.tolist()}; a stiffness-kept step needs one")
    if model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_REFSAFE:
        return float(tc[0])
    return max(float(tc[0]), 2.0 * model.opt.timestep)


def at_step_same_stiffness(spec: RobotSpec, timestep: float) -> Candidate:
    """The robot's defaults at ``timestep`` with its floor contact's stiffness kept.

    The contact's own ``t_c`` is kept (``contact_timeconst`` unchanged); the builder raises
    the pairs' to its least ``steps · Δt`` (the bound of a soft contact's stability). MuJoCo
    gives a pair of impedance ``d`` the stiffness ``k = 1/(d ζ² t_c²)`` and the damping
    ``b = 2/(d t_c)``, so with the pairs' time constant ``t_c'`` at the new step,

        ζ' = ζ t_c / t_c'

    keeps ``k``, and with it the rest depth ``(1 − d) g ζ² t_c²`` and the rolling radius;
    only ``b`` falls, as ``t_c/t_c'``: the contact is the default's spring, less damped.

    Raises:
        ValueError: a robot without parameters or floor pairs; a ``ζ'`` under 0.1 (the
            parameters' least).
    """
    if spec.params_type is None:
        raise ValueError(f"robot {spec.name!r} has no parameters to change")
    base = spec.params_type()
    trial = dataclasses.replace(base, sim=dataclasses.replace(base.sim, timestep=timestep))
    zeta = base.sim.floor_dampratio * pair_timeconst(spec, base) / pair_timeconst(spec, trial)
    if zeta < LEAST_DAMPRATIO:
        raise DampratioTooSmallError(f"robot {spec.name!r} at {timestep!r} s: ζ' = {zeta:.3g} is "
                                f"under the parameters' least, {LEAST_DAMPRATIO}")
    params = dataclasses.replace(trial, sim=dataclasses.replace(trial.sim, floor_dampratio=zeta))
    return Candidate(timestep, zeta, params, stiffness_kept=True)


def stiffness_candidates(spec: RobotSpec) -> list[Candidate]:
    """:func:`at_step_same_stiffness` at every longer step of :data:`STEPS` (ζ' ≥ 0.1).

    Raises:
        ValueError: the robot has no floor pairs (:func:`pair_timeconst`).
    """
    assert spec.params_type is not None
    pair_timeconst(spec, spec.params_type())  # no pairs: refused here, not skipped below
    own = spec.params_type().sim.timestep
    out = []
    for dt in STEPS:
        if dt > own:
            try:
                out.append(at_step_same_stiffness(spec, dt))
            except DampratioTooSmallError:  # no such contact; any other refusal raises
                continue
    return out
