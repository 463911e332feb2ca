"""The rolling-radius ripple of ``mecanum4``'s roller colliders (a measurement scenario).

Measured on the compiled collision geometry: the distance from wheel FL's axle to the
floor-touching point over one revolution
(:func:`wmr_mujoco.robots.roller_wheels.rolling_radius_profile`), peak to peak over its
mean. The ideal profile has none (docs/mecanum.md §5); the ellipsoids osculate it at
each roller's middle and depart from it towards the hand-overs.
"""

from __future__ import annotations

import numpy as np

from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots.mecanum4.builder import WHEEL_NAMES
from wmr_mujoco.robots.roller_wheels import rolling_radius_profile
from wmr_mujoco.validation.metrics import Metric, Series, Target
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario

#: Requirement (issue 15) on the rolling-radius ripple, % of the mean radius.
RIPPLE = Target.requirement(0.3, "smooth rolling asked of the roller envelope: "
                                     "rolling-radius ripple ≤ 0.3 %")


def ripple(scenario: Scenario, params: RobotParams | None) -> MeasurementResult:
    """Peak-to-peak rolling radius of wheel FL over a revolution, % of its mean."""
    from wmr_mujoco.models.loading import load
    from wmr_mujoco.robots.mecanum4 import SPEC  # the entry imports this module

    model = load(SPEC, params)
    wheel = WHEEL_NAMES[0]
    profile = rolling_radius_profile(model, wheel, f"{wheel}_roller", samples=721)
    angle = np.degrees(np.linspace(0.0, 2.0 * np.pi, profile.size))
    pct = 100.0 * float(np.ptp(profile) / np.mean(profile))
    return MeasurementResult(
        [Metric("rolling-radius ripple", pct, "% of mean", RIPPLE,
                f"peak to peak over 721 wheel angles; mean {1000 * np.mean(profile):.3f} mm"),
         Metric("mean rolling radius", float(np.mean(profile)), "m")],
        [Series("rolling radius", angle, 1000.0 * profile, "wheel angle [deg]",
                "axle height over the contact [mm]")])

