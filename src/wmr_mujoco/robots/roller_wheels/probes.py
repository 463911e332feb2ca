"""Per-step probes of roller-wheeled robots.

Roller, wheel and yaw rates, and the rolling radius profile.

The probes (:class:`RollerRateProbe`, :class:`WheelRateProbe`, :class:`YawRippleProbe`)
take an :class:`~wmr_mujoco.robots.roller_wheels.adapters.OmniAdapter`: an
:class:`~wmr_mujoco.validation.adapters.Adapter` that also gives its wheel layout and
the body twist its input commands.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import mujoco
import numpy as np

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.colliders import colliders
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.adapters import OmniAdapter
from wmr_mujoco.robots.roller_wheels.model_info import OmniModelInfo, layout_from_model
from wmr_mujoco.validation.adapters import Adapter
from wmr_mujoco.validation.metrics import Metric, Sample, Target, rms
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind

#: Probes start after this many seconds (ramps done, transients settled).
STEADY_AFTER = 1.0
#: Key of the roller-rate target in a robot's target table.
ROLLER_RATE_PCT = "roller rate error % (median)"


def roller_rate_errors(model: mujoco.MjModel, data: mujoco.MjData, info: OmniModelInfo,
                       slide_speeds: np.ndarray,
                       rollers: tuple[np.ndarray, np.ndarray] | None = None) -> list[float]:
    """Relative errors ``|ω_r ρ − s| / s`` of the rollers touching the floor now.

    ``s`` is the slide speed along the roller axis at each wheel's contact implied by the
    commanded twist, ``ρ`` the contact's distance from the roller axis and ``ω_r`` the
    roller's measured spin rate. Contacts of wheels sliding slower than 1 mm/s are skipped.
    ``rollers``: :func:`roller_geoms` of the model (None: read here).
    """
    got = roller_contacts(model, data, info, slide_speeds, rollers)
    return [] if got is None else rate_errors(*got)


def roller_contacts(model: mujoco.MjModel, data: mujoco.MjData, info: OmniModelInfo,
                    slide_speeds: np.ndarray,
                    rollers: tuple[np.ndarray, np.ndarray] | None = None
                    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None:
    """What :func:`roller_rate_errors` reads of the contacting rollers now (None: no contact).

    Per roller contact: its offset from the roller's hinge anchor ``rel``, the hinge's
    world axis, the wheel's slide speed ``|s|`` and the roller's spin ``|ω_r|``; rows of
    several steps stacked give :func:`rate_errors` of each step, in order.
    """
    if data.ncon == 0:
        return None
    wheel_of_geom, joint_of_geom = rollers if rollers is not None else roller_geoms(model,
                                                                                   info)
    con = data.contact
    g1, g2 = con.geom1[:data.ncon], con.geom2[:data.ncon]
    geom = np.where(model.geom_bodyid[g1] == 0, g2, g1)
    wheel = wheel_of_geom[geom]
    roller = wheel >= 0
    jnt = joint_of_geom[geom[roller]]
    rel = con.pos[:data.ncon][roller] - data.xanchor[jnt]
    return (rel, data.xaxis[jnt], np.abs(np.asarray(slide_speeds, float)[wheel[roller]]),
            np.abs(data.qvel[model.jnt_dofadr[jnt]]))


def rate_errors(rel: np.ndarray, axis: np.ndarray, slide: np.ndarray, omega: np.ndarray
                ) -> list[float]:
    """``|ω_r ρ − s| / s`` of :func:`roller_contacts`' rows, ``ρ = |rel − (rel·â) â|``.

    Row by row the same floats however many steps' rows are stacked (each row's sums
    are its own three terms, in order).
    """
    rho = np.linalg.norm(rel - axis * np.sum(rel * axis, axis=1)[:, None], axis=1)
    keep = (slide >= 1e-3) & (rho >= 1e-6)
    return (np.abs(omega * rho - slide)[keep] / slide[keep]).tolist()


def roller_geoms(model: mujoco.MjModel, info: OmniModelInfo) -> tuple[np.ndarray, np.ndarray]:
    """Per geom: the wheel whose roller it belongs to (−1: none) and that roller's hinge.

    A roller is a body with one joint whose parent is a wheel's body (``info``'s wheel
    joints, in layout order).
    """
    wheel_of = np.full(model.nbody, -1)
    for i, j in enumerate(info.wheel_joints):
        wheel_of[model.jnt_bodyid[j]] = i
    body = model.geom_bodyid
    wheel = np.where(model.body_jntnum[body] == 1, wheel_of[model.body_parentid[body]], -1)
    return wheel, model.body_jntadr[body]


def rolling_radius_profile(model: mujoco.MjModel, wheel_joint: str, roller_prefix: str,
                           samples: int = 721) -> np.ndarray:
    """Distance from the wheel axle to the floor-touching point over one revolution.

    Measured on the model's own collision geometry with ``mj_geomDistance`` between the
    floor and every roller geom (named ``roller_prefix...``), with the wheel axle held
    horizontal at a fixed height and the wheel turned through 360°.

    Returns:
        (samples,) rolling radius at wheel angles ``linspace(0, 2π, samples)``.
    """
    data = mujoco.MjData(model)
    floor = model.geom("floor").id
    jid = model.joint(wheel_joint).id
    geoms = [g for g in colliders(model) if (model.geom(g).name or "").startswith(roller_prefix)]
    if not geoms:
        raise ValueError(f"no collision geoms named {roller_prefix!r}* in the model")
    fromto = np.zeros(6)
    out = np.empty(samples)
    for i, angle in enumerate(np.linspace(0.0, 2.0 * np.pi, samples)):
        data.qpos[:] = model.qpos0
        data.qpos[2] += 0.5  # lift the free base clear of the floor
        data.qpos[model.jnt_qposadr[jid]] = angle
        mujoco.mj_kinematics(model, data)
        gap = min(mujoco.mj_geomDistance(model, data, g, floor, 2.0, fromto) for g in geoms)
        out[i] = data.xanchor[jid][2] - gap
    return out


@dataclass
class RollerRateProbe:
    """Contacting rollers' spin rates against slide speed / ρ, after :data:`STEADY_AFTER`."""

    info: OmniModelInfo
    adapter: OmniAdapter
    target: Target | None
    errors: list[float] = field(default_factory=list)
    after: float = STEADY_AFTER

    _rollers: tuple[np.ndarray, np.ndarray] | None = field(default=None, repr=False)
    _slides: dict[bytes, np.ndarray] = field(default_factory=dict, repr=False)
    _pending: list[tuple[np.ndarray, ...]] = field(default_factory=list, repr=False)

    def observe(self, sample: Sample) -> None:
        """Errors of the rollers in contact at this step."""
        if sample.t > self.after:
            if self._rollers is None:
                self._rollers = roller_geoms(sample.model, self.info)
            twist = np.asarray(self.adapter.twist(sample.u, sample.x), float)
            slide = self._slides.get(key := twist.tobytes())
            if slide is None:  # a run holds few twists: each one's speeds once
                if len(self._slides) > 4096:
                    self._slides.clear()
                slide = self._slides[key] = ok.roller_slide_speeds(self.adapter.layout,
                                                                   twist)
            got = roller_contacts(sample.model, sample.data, self.info, slide, self._rollers)
            if got is not None:  # the errors of all steps at once, when asked for
                self._pending.append(got)

    def metrics(self) -> list[Metric]:
        """Median (judged) and 95th percentile, in %."""
        if self._pending:
            self.errors += rate_errors(*(np.concatenate(p) for p in zip(*self._pending,
                                                                        strict=True)))
            self._pending.clear()
        if not self.errors:
            return []
        return [Metric("roller rate error (median)", 100.0 * float(np.median(self.errors)),
                       "%", self.target),
                Metric("roller rate error (95th percentile)",
                       100.0 * float(np.percentile(self.errors, 95)), "%")]


@dataclass
class WheelRateProbe:
    """Measured wheel rates against the commanded ``θ̇ = H ν`` (rate servos only)."""

    wheel_dofs: tuple[int, ...]
    errors: list[float] = field(default_factory=list)
    after: float = STEADY_AFTER

    def observe(self, sample: Sample) -> None:
        """``|θ̇ − θ̇_cmd| / |θ̇_cmd|`` at this step, once the commanded rates exceed 0.5."""
        if sample.t > self.after and np.linalg.norm(sample.ctrl) > 0.5:
            rates = sample.data.qvel[list(self.wheel_dofs)]
            self.errors.append(float(np.linalg.norm(rates - sample.ctrl)
                                     / np.linalg.norm(sample.ctrl)))

    def metrics(self) -> list[Metric]:
        """RMS relative error, reported."""
        return [Metric("wheel rate error vs H ν (RMS)", 100.0 * rms(self.errors), "%")
                ] if self.errors else []


@dataclass
class YawRippleProbe:
    """Standard deviation of the base's yaw rate over the steady phase, / |commanded|."""

    base_body: int
    adapter: OmniAdapter
    rates: list[float] = field(default_factory=list)
    commanded: list[float] = field(default_factory=list)
    after: float = STEADY_AFTER

    def observe(self, sample: Sample) -> None:
        """The base's world yaw rate and the commanded one at this step."""
        if sample.t > self.after:
            self.rates.append(float(sample.data.cvel[self.base_body][2]))
            self.commanded.append(float(self.adapter.twist(sample.u, sample.x)[2]))

    def metrics(self) -> list[Metric]:
        """``std(r) / |r_cmd|`` in %, where a constant yaw rate is commanded."""
        cmd = np.asarray(self.commanded)
        if not cmd.size or np.ptp(cmd) > 1e-9 or abs(cmd[0]) < 1e-9:
            return []
        return [Metric("yaw-rate ripple", 100.0 * float(np.std(self.rates)) / abs(cmd[0]),
                       "% of commanded")]


def omni_probes(scenario: Scenario, model: mujoco.MjModel, adapter: Adapter,
                targets: Mapping[str, Target]) -> _OmniProbes | None:
    """The roller, wheel-rate and yaw-ripple probes of a kinematic omni-wheel run."""
    if scenario.kind is not ScenarioKind.KINEMATIC or not isinstance(adapter, OmniAdapter):
        return None
    info = layout_from_model(model, adapter.wheel_joints)
    probes: list[RollerRateProbe | WheelRateProbe | YawRippleProbe] = [
        RollerRateProbe(info, adapter, targets.get(ROLLER_RATE_PCT)),
        YawRippleProbe(info.base_body, adapter)]
    if adapter.mode is ActuationMode.RATE:
        probes.insert(0, WheelRateProbe(tuple(int(model.jnt_dofadr[j])
                                              for j in info.wheel_joints)))
    return _OmniProbes(probes)


@dataclass
class _OmniProbes:
    """Several probes as one."""

    probes: list[RollerRateProbe | WheelRateProbe | YawRippleProbe]

    @property
    def after(self) -> float:
        """The earliest of its probes' ``after``: samples up to it are read by none."""
        return min(p.after for p in self.probes)

    def observe(self, sample: Sample) -> None:
        """Pass the sample to each probe."""
        for p in self.probes:
            p.observe(sample)

    def metrics(self) -> list[Metric]:
        """Every probe's metrics, in order."""
        return [m for p in self.probes for m in p.metrics()]
