"""Per-step probes of roller-wheeled robots.

Roller, wheel and yaw rates, and the rolling radius profile.

The probes (:class:`RollerRateProbe`, :class:`WheelRateProbe`, :class:`YawRippleProbe`)
take an :class:`~wmr_mujoco.robots.roller_wheels.adapters.OmniAdapter`: an
:class:`~wmr_mujoco.validation.adapters.Adapter` that also gives its wheel layout and
the body twist its input commands.
"""

from __future__ import annotations

import math
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
#: The roller-rate probe copies each step's contacts and frames (a few kB) and reads this
#: many steps' errors at once (a bounded buffer, whatever the run's length).
PENDING_STEPS = 256


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
    index = roller_index(model, info, rollers)
    return _rows(index, [_snapshot(data, np.asarray(slide_speeds, float))])


@dataclass(frozen=True)
class RollerIndex:
    """Per geom what :func:`roller_contacts` reads of the model: built once per model.

    Attributes:
        world: (ngeom,) whether the geom is on the world body (the floor's side).
        columns: (ngeom, 3) the geom's wheel (−1: not a roller), its roller's hinge and
            that hinge's dof (−1: not a roller).
    """

    world: np.ndarray
    columns: np.ndarray


def roller_index(model: mujoco.MjModel, info: OmniModelInfo,
                 rollers: tuple[np.ndarray, np.ndarray] | None = None) -> RollerIndex:
    """The :class:`RollerIndex` of a model (``rollers``: its :func:`roller_geoms`, or None)."""
    wheel, joint = rollers if rollers is not None else roller_geoms(model, info)
    dof = np.where(wheel >= 0, model.jnt_dofadr[np.where(wheel >= 0, joint, 0)], -1)
    return RollerIndex(model.geom_bodyid == 0, np.stack([wheel, joint, dof], axis=1))


#: What :func:`_snapshot` copies of a step: the contacts' geom pairs and positions, every
#: joint's anchor and axis, the dof velocities, and the wheels' slide speeds.
Snapshot = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]


def _snapshot(data: mujoco.MjData, slide: np.ndarray) -> Snapshot | None:
    """Copies of what :func:`_rows` reads of ``data`` now (None: no contact)."""
    ncon = data.ncon
    if ncon == 0:
        return None
    con = data.contact
    return (con.geom[:ncon].copy(), con.pos[:ncon].copy(), data.xanchor.copy(),
            data.xaxis.copy(), data.qvel.copy(), slide)


def _rows(index: RollerIndex, snaps: list[Snapshot]
          ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """:func:`roller_contacts`' rows of several steps' snapshots, stacked in order."""
    pair = np.concatenate([sn[0] for sn in snaps])
    step = np.repeat(np.arange(len(snaps)), [len(sn[0]) for sn in snaps])
    cols = index.columns[np.where(index.world[pair[:, 0]], pair[:, 1], pair[:, 0])]
    roller = cols[:, 0] >= 0  # a contact of a non-roller geom: left out
    cols, step = cols[roller], step[roller]
    pos = np.concatenate([sn[1] for sn in snaps])[roller]
    jnt = cols[:, 1]
    anchor, axis, qvel, slide = (np.stack([sn[i] for sn in snaps]) for i in range(2, 6))
    return (pos - anchor[step, jnt], axis[step, jnt], np.abs(slide[step, cols[:, 0]]),
            np.abs(qvel[step, cols[:, 2]]))


def rate_errors(rel: np.ndarray, axis: np.ndarray, slide: np.ndarray, omega: np.ndarray
                ) -> list[float]:
    """``|ω_r ρ − s| / s`` of :func:`roller_contacts`' rows, ``ρ = |rel − (rel·â) â|``.

    Row by row the same floats however many steps' rows are stacked (each row's sums
    are its own three terms, in order).
    """
    rho = np.linalg.norm(rel - axis * np.sum(rel * axis, axis=1)[:, None], axis=1)
    keep = (slide >= 1e-3) & (rho >= 1e-6)
    return (np.abs(omega * rho - slide)[keep] / slide[keep]).tolist()


def _norm(x: np.ndarray) -> float:
    """``np.linalg.norm`` of a 1-D float array, the same float: ``√(x·x)``."""
    return math.sqrt(x.dot(x))


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
class SampleTwist:
    """The body twist an adapter commands at a sample, computed once for all its probes.

    Holds the last sample it was asked about (a runner makes a new one per step).
    """

    adapter: OmniAdapter
    _sample: Sample | None = field(default=None, repr=False, compare=False)
    _twist: np.ndarray = field(default_factory=lambda: np.zeros(3), repr=False,
                               compare=False)

    def __call__(self, sample: Sample) -> np.ndarray:
        """``adapter.twist(sample.u, sample.x)`` as a float array."""
        if sample is not self._sample:
            self._twist = np.asarray(self.adapter.twist(sample.u, sample.x), float)
            self._sample = sample
        return self._twist


@dataclass
class RollerRateProbe:
    """Contacting rollers' spin rates against slide speed / ρ, after :data:`STEADY_AFTER`.

    ``twists``: the commanded twist of a sample (None: the adapter's, its own).
    """

    info: OmniModelInfo
    adapter: OmniAdapter
    target: Target | None
    errors: list[float] = field(default_factory=list)
    after: float = STEADY_AFTER
    twists: SampleTwist | None = None

    _index: RollerIndex | None = field(default=None, repr=False, compare=False)
    _slides: dict[bytes, np.ndarray] = field(default_factory=dict, repr=False, compare=False)
    _pending: list[Snapshot] = field(default_factory=list, repr=False, compare=False)

    def __post_init__(self) -> None:
        if self.twists is None:
            self.twists = SampleTwist(self.adapter)

    def observe(self, sample: Sample) -> None:
        """Errors of the rollers in contact at this step."""
        if sample.t > self.after:
            if self._index is None:
                self._index = roller_index(sample.model, self.info)
            twist = self.twists(sample)
            slide = self._slides.get(key := twist.tobytes())
            if slide is None:  # a run holds few twists: each one's speeds once
                if len(self._slides) > 4096:
                    self._slides.clear()
                slide = self._slides[key] = ok.roller_slide_speeds(self.adapter.layout,
                                                                   twist)
            got = _snapshot(sample.data, slide)
            if got is not None:  # the errors of many steps at once
                self._pending.append(got)
                if len(self._pending) >= PENDING_STEPS:
                    self._flush()

    def _flush(self) -> None:
        """The errors of the pending steps, in order (rows of steps stacked)."""
        if self._pending:
            self.errors += rate_errors(*_rows(self._index, self._pending))
            self._pending.clear()

    def metrics(self) -> list[Metric]:
        """Median (judged) and 95th percentile, in %."""
        self._flush()
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
    _dofs: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        self._dofs = np.array(self.wheel_dofs, dtype=np.intp)

    def observe(self, sample: Sample) -> None:
        """``|θ̇ − θ̇_cmd| / |θ̇_cmd|`` at this step, once the commanded rates exceed 0.5."""
        if sample.t > self.after:
            ctrl = np.asarray(sample.ctrl, float)
            commanded = _norm(ctrl)
            if commanded > 0.5:
                rates = sample.data.qvel[self._dofs]
                self.errors.append(_norm(rates - ctrl) / commanded)

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
    twists: SampleTwist | None = None

    def __post_init__(self) -> None:
        if self.twists is None:
            self.twists = SampleTwist(self.adapter)

    def observe(self, sample: Sample) -> None:
        """The base's world yaw rate and the commanded one at this step."""
        if sample.t > self.after:
            self.rates.append(float(sample.data.cvel[self.base_body][2]))
            self.commanded.append(float(self.twists(sample)[2]))

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
    twists = SampleTwist(adapter)  # one twist per sample for both
    probes: list[RollerRateProbe | WheelRateProbe | YawRippleProbe] = [
        RollerRateProbe(info, adapter, targets.get(ROLLER_RATE_PCT), twists=twists),
        YawRippleProbe(info.base_body, adapter, twists=twists)]
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
