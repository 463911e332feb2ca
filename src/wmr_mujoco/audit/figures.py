"""The figures of one manoeuvre, from its :class:`~wmr_mujoco.audit.run.Record`.

* worst position error: ``max_t |p_sim − p_ideal| / L`` with ``L`` the ideal path length
  of the reference point (as ``wmr validate`` measures it); below :data:`MIN_PATH` of
  path (a spin about the reference point) the worst drift in metres instead;
* worst heading error, degrees;
* lateral slip: RMS over the held part (after the ramp) of each wheel's slip along its
  constrained direction (the axle for a standard wheel, the roller axis for a Swedish
  one), the worst wheel, m/s and % of the largest commanded wheel ground speed;
* rolling-radius ripple: ``(max − min)/mean`` of each wheel's axle height, worst wheel;
* share of wheel samples off the floor (no contact between the wheel and the floor);
* deepest penetration into the floor, mm;
* coasting energy drift: the largest rise of the total energy during the free coast above
  its lowest value so far, ``max_t (E(t) − min_{s≤t} E(s))``, over the kinetic energy
  when the coast began (a passive system only loses energy: a rise is the integrator's), %;
* real-time factor: simulated over wall-clock seconds of the stepping.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from wmr_mujoco.analytic.planar import wrap_angle
from wmr_mujoco.audit.run import RAMP, Record
from wmr_mujoco.validation.metrics import MIN_PATH

#: Worst position error (% of path) and heading error (deg) up to which a manoeuvre
#: "follows the ideal model", and up to which it "drifts from it" (beyond: "fails").
FOLLOWS = (5.0, 5.0)
DRIFTS = (20.0, 20.0)
#: A spin in place is judged by its drift in % of the robot's span (at least 5 cm).
MIN_SPAN = 0.05


@dataclass(frozen=True)
class Figures:
    """The figures of one manoeuvre (module docstring).

    ``position_pct`` is None for a spin in place (then ``drift_m`` is the judged figure).
    """

    position_pct: float | None
    drift_m: float
    heading_deg: float
    path_m: float
    slip_ms: float
    slip_pct: float
    ripple_pct: float
    off_floor_pct: float
    penetration_mm: float
    energy_drift_pct: float
    real_time_factor: float

    def as_dict(self) -> dict[str, float | None]:
        """For the JSON report."""
        return asdict(self)

    def error_label(self) -> str:
        """``"12.3 % of path"`` or ``"4.1 mm drift"``."""
        if self.position_pct is not None:
            return f"{self.position_pct:.1f} % of path"
        return f"{1000 * self.drift_m:.1f} mm drift"


def wrap(angle: np.ndarray) -> np.ndarray:
    """Angles wrapped to (−π, π] (:func:`wmr_mujoco.analytic.planar.wrap_angle`)."""
    return wrap_angle(angle)


def figures(rec: Record) -> Figures:
    """The figures of ``rec`` (module docstring)."""
    err = np.linalg.norm(rec.sim[:, :2] - rec.ideal[:, :2], axis=1)
    steps = np.linalg.norm(np.diff(rec.ideal[:, :2], axis=0), axis=1)
    path = float(steps.sum())
    heading = np.degrees(np.abs(wrap(rec.sim[:, 2] - rec.ideal[:, 2])))
    held = rec.time >= RAMP
    rolling = [i for i in range(rec.slip.shape[1]) if np.any(rec.slip[:, i])]
    slip = max((float(np.sqrt(np.mean(rec.slip[held, i] ** 2))) for i in rolling),
               default=0.0)
    h = rec.height[held]
    ripple = float(np.max((h.max(axis=0) - h.min(axis=0)) / h.mean(axis=0)))
    rise = float(np.max(rec.energy - np.minimum.accumulate(rec.energy)))
    return Figures(
        position_pct=100.0 * float(err.max()) / path if path > MIN_PATH else None,
        drift_m=float(err.max()), heading_deg=float(heading.max()), path_m=path,
        slip_ms=slip, slip_pct=100.0 * slip / rec.wheel_speed if rec.wheel_speed else 0.0,
        ripple_pct=100.0 * ripple, off_floor_pct=100.0 * float(1.0 - rec.on_floor.mean()),
        penetration_mm=1000.0 * rec.depth,
        energy_drift_pct=100.0 * max(rise, 0.0) / rec.kinetic0 if rec.kinetic0 > 0 else 0.0,
        real_time_factor=rec.simulated / rec.wall if rec.wall > 0 else float("inf"))


def verdict(f: Figures, span: float) -> str:
    """Follows, drifts from, or fails to follow the ideal model (thresholds above).

    A spin in place is judged by its drift in % of the robot's ``span``.
    """
    pos = f.position_pct if f.position_pct is not None else \
        100.0 * f.drift_m / max(span, MIN_SPAN)
    if pos <= FOLLOWS[0] and f.heading_deg <= FOLLOWS[1]:
        return "follows the ideal model"
    if pos <= DRIFTS[0] and f.heading_deg <= DRIFTS[1]:
        return "drifts from the ideal model"
    return "fails to follow the ideal model"
