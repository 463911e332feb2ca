"""The stepping API's two backends side by side: MuJoCo against the kinematic model.

``python -m wmr_mujoco.bench.drive_accuracy [--draws 5]`` prints one Markdown table: for
each family of driven runs, the worst position error of the ``"mujoco"`` backend against
the ``"kinematic"`` backend under the same commands (one per 20 ms period, from the same
start pose and wheel phase), in % of the kinematic path, over seeded draws, beside the
robot's validation requirement (``POSITION_PCT`` of its registry entry).

Families (each inside its robot's validated envelope):

* **diffdrive arcs**: ``(v, ω)`` drawn in [0.2, 0.8] m/s × [−1.5, 1.5] rad/s, reached by the
  validation's 0.5 s ramp (a step from rest asks more than the wheels' traction), 2 s;
* **bicycle turns**: 2 m/s after a 1 s ramp (its validation speed), a steering angle
  drawn in ±0.5 rad (its steady turns' range) commanded from the start, 3 s.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

#: Control period of the runs, s.
PERIOD = 0.02
#: ``draw(rng) -> (command(t), start pose)``.
Draw = Callable[[np.random.Generator], tuple[Callable[[float], tuple[float, ...]], np.ndarray]]


@dataclass(frozen=True)
class Family:
    """Runs of one robot: how each is drawn and how long it lasts."""

    robot: str
    draw: Draw
    steps: int


def _arc(rng: np.random.Generator) -> tuple[Callable[[float], tuple[float, ...]], np.ndarray]:
    v, w = rng.uniform(0.2, 0.8), rng.uniform(-1.5, 1.5)
    return (lambda t: (v * min(t / 0.5, 1.0), w * min(t / 0.5, 1.0))), rng.uniform(-1, 1, 3)


def _turn(rng: np.random.Generator) -> tuple[Callable[[float], tuple[float, ...]], np.ndarray]:
    phi = rng.uniform(-0.5, 0.5)
    return (lambda t: (2.0 * min(t, 1.0), phi)), rng.uniform(-1, 1, 3)


FAMILIES = {
    "diffdrive arcs": Family("diffdrive", _arc, 100),
    "bicycle turns": Family("bicycle", _turn, 150),
}


def _poses(robot: str, backend: str, command: Callable[[float], tuple[float, ...]],
           steps: int, pose: np.ndarray, seed: int) -> np.ndarray:
    from wmr_mujoco.drive import make

    r = make(robot, backend=backend, control_period=PERIOD)
    r.reset(pose, seed)
    for k in range(steps):
        r.step(command(k * PERIOD))
    return np.array([s.pose for s in r.history])


def worst_position_pct(family: Family, draws: int = 5, seed: int = 0) -> float:
    """Worst over ``draws`` runs of the largest MuJoCo-to-model distance, % of model path.

    Raises:
        ValueError: ``draws`` below 1.
    """
    from wmr_mujoco.analytic.planar import path_length

    if draws < 1:
        raise ValueError(f"draws = {draws!r}; must be >= 1")
    rng = np.random.default_rng(seed)
    worst = 0.0
    for _ in range(draws):
        command, pose = family.draw(rng)
        phase = int(rng.integers(1000))
        sim = _poses(family.robot, "mujoco", command, family.steps, pose, phase)
        kin = _poses(family.robot, "kinematic", command, family.steps, pose, phase)
        error = np.max(np.linalg.norm(sim[:, :2] - kin[:, :2], axis=1))
        worst = max(worst, 100.0 * float(error) / path_length(kin[:, :2]))
    return worst


def main(argv: Sequence[str] | None = None) -> int:
    """Print the table of the module docstring."""
    from wmr_mujoco.robots import get_spec
    from wmr_mujoco.validation import metrics as mt

    parser = argparse.ArgumentParser(prog="python -m wmr_mujoco.bench.drive_accuracy",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("--draws", type=int, default=5, help="runs per family (1..100)")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    if not 1 <= args.draws <= 100:
        parser.error(f"--draws {args.draws}: use 1..100")
    print(f"`python -m wmr_mujoco.bench.drive_accuracy --draws {args.draws} --seed "
          f"{args.seed}`: mujoco vs kinematic backend, worst over the draws.\n")
    print("| family | draws | worst position error, % of path | requirement | met |")
    print("|---|---|---|---|---|")
    for name, family in FAMILIES.items():
        worst = worst_position_pct(family, args.draws, args.seed)
        target = get_spec(family.robot).targets[mt.POSITION_PCT].value
        print(f"| {name} | {args.draws} | {worst:.3f} | {target:g} | "
              f"{'yes' if worst <= target else 'NO'} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
