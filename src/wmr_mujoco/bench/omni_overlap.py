"""omni3's roller-row overlaps measured in the physics: load sharing, friction, duration.

``python -m wmr_mujoco.bench.omni_overlap`` (part of ``make study`` through
:mod:`~wmr_mujoco.bench.omni_energy_study`, which pastes the table into
``docs/omni-dynamics.md``).

The hybrid model's overlap friction (``OmniHybrid.overlap_impulse``) assumes, while two
rollers of a wheel touch: a window of ``Δφ_w = δ / |x_c|`` of wheel turn (δ the static
penetration, ``x_c`` the contact's offset at the switch), the load moving linearly from
the old roller to the new one (so the lighter contact carries on average a quarter of
the pair's load), and a friction force no larger than the lighter contact's Coulomb
limit. This module measures those three in a coast of the physics, per wheel, from the
contacts MuJoCo solves at every step (:func:`overlap_windows`):

* episode length: consecutive steps with two rollers of the wheel in contact, against
  the static window ``Δφ_w / (|θ̇| Δt)`` in steps at the wheel's mean rate;
* the lighter contact's share ``min(N₁, N₂) / (N₁ + N₂)`` over the steps where the pair
  carries load (linear sharing: 1/4 on average);
* the share of loaded contacts at the Coulomb limit, ``|f_t| ≥ 0.95 μ N`` (``f_t`` the
  friction force along the wheel's drive direction), and the share of steps on which the
  two friction forces point in opposite directions.
"""

from __future__ import annotations

import argparse
import math

import mujoco
import numpy as np

from wmr_mujoco.robots.omni3.runs import WHEELS, coast_start, contact_wheels, hybrid
from wmr_mujoco.sim.stepping import check_healthy

#: |f_t| / (μ N) from which a contact counts as sliding at the Coulomb limit.
COULOMB = 0.95


def _contacts(model: mujoco.MjModel, data: mujoco.MjData, floor: int,
              drive: np.ndarray) -> list[list[tuple[float, float]]]:
    """(N, f_t) of every roller contact, per wheel, for the contacts of the current state."""
    out: list[list[tuple[float, float]]] = [[] for _ in WHEELS]
    frame = data.xmat[1].reshape(3, 3)
    force = np.zeros(6)
    for ci, wheel in enumerate(contact_wheels(model, data)):
        if wheel < 0:
            continue
        c = data.contact[ci]
        mujoco.mj_contactForce(model, data, ci, force)
        world = c.frame.reshape(3, 3).T @ force[:3]
        if c.geom2 == floor:  # the force on the robot
            world = -world
        out[wheel].append((float(force[0]), float(world @ (frame @ drive[wheel]))))
    return out


def overlap_windows(twist: tuple[float, float, float] = (0.3, 0.0, 1.0),
                    drive_time: float = 1.5, duration: float = 3.0
                    ) -> list[dict[str, float]]:
    """Per wheel: measured overlap episodes of a coast and the model's assumptions.

    Drive at ``twist`` (rate servo, 0.5 s ramp) for ``drive_time``, then coast (torque
    mode, zero torque) for ``duration``; at every step of the coast, the contacts of the
    state about to be stepped and the forces MuJoCo solves for them.

    Raises:
        ValueError: non-finite twist or bad durations.
    """
    if not (math.isfinite(duration) and 0 < duration <= 30):
        raise ValueError(f"duration = {duration!r} s; valid range is (0, 30] s")
    model, data = coast_start(twist, drive_time)
    hy = hybrid(None)
    dt = model.opt.timestep
    floor = model.geom("floor").id
    dofs = [model.jnt_dofadr[model.joint(w).id] for w in WHEELS]
    steps = round(duration / dt)
    pairs: list[list[list[tuple[float, float]]]] = [[] for _ in WHEELS]
    rates = np.zeros((steps, 3))
    for n in range(steps):
        mujoco.mj_forward(model, data)
        for i, cs in enumerate(_contacts(model, data, floor, hy.drive_dirs)):
            pairs[i].append(cs)
        rates[n] = data.qvel[dofs]
        mujoco.mj_step(model, data)
    check_healthy(model, data)
    g = hy.rollers
    x_switch = abs(float(g.contact_ahead(math.pi / (g.angles.size))))  # |x_c| at π/12
    out = []
    for i in range(3):
        double = np.array([len(cs) >= 2 for cs in pairs[i]])
        edges = np.diff(np.concatenate([[0], double.astype(int), [0]]))
        lengths = np.flatnonzero(edges == -1) - np.flatnonzero(edges == 1)
        loaded = [cs[:2] for cs in pairs[i] if len(cs) >= 2 and min(c[0] for c in cs[:2]) > 0]
        share = [min(a[0], b[0]) / (a[0] + b[0]) for a, b in loaded]
        at_limit = [abs(f) >= COULOMB * hy.friction * n for pair in loaded for n, f in pair]
        opposed = [a[1] * b[1] < 0 for a, b in loaded]
        rate = float(np.mean(np.abs(rates[:, i])))
        out.append({"wheel": i + 1, "mean wheel rate magnitude (rad/s)": rate,
                    "episodes": float(lengths.size),
                    "mean episode (steps)": float(lengths.mean()) if lengths.size else 0.0,
                    "static window (steps)": hy.penetration / x_switch / max(rate, 1e-9) / dt,
                    "loaded pair steps": float(len(loaded)),
                    "lighter contact's share": float(np.mean(share)) if share else math.nan,
                    "contacts at the Coulomb limit": float(np.mean(at_limit)) if at_limit
                    else math.nan,
                    "friction forces opposed": float(np.mean(opposed)) if opposed
                    else math.nan})
    return out


def table(rows: list[dict[str, float]]) -> str:
    """Markdown table of :func:`overlap_windows` rows, ``n/a`` where a wheel had no loaded pair.

    The model's assumption (linear sharing) is named in the header.
    """
    keys = list(rows[0])
    head = [k.replace("lighter contact's share",
                      "lighter contact's share (linear sharing: 0.25)") for k in keys]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(keys)]
    for row in rows:
        lines.append("| " + " | ".join(f"{row[k]:.3g}" if math.isfinite(row[k]) else "n/a"
                                       for k in keys) + " |")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:  # pragma: no cover - a few seconds
    """Print the overlap table of the default coast."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.parse_args(argv)
    print(table(overlap_windows()))


if __name__ == "__main__":  # pragma: no cover
    main()
