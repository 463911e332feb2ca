"""Why MuJoCo Warp diverged on the ball-caster robots: the Newton Hessian's conditioning.

``python -m wmr_mujoco.bench.caster_conditioning [--no-write]`` builds every robot whose
floor pairs include a ball caster (:func:`~wmr_mujoco.models.builders.wheel_pairs.\
caster_collider_names`) twice: at its defaults (the caster paired with the floor like the
wheels) and with the caster's pair removed (its contact from the contact bits, the
collision class's ``d ≈ 0.95``, as before the fix). Each is settled at rest in C MuJoCo
for :data:`SETTLE` s and reports

* ``impratio · d`` of the caster's contact (``d`` the impedance MuJoCo used,
  ``efc_KBIP``): the friction rows' stiffness gain, :data:`~wmr_mujoco.models.builders.\
common.SLIDING_GRIP` for the wheels;
* the caster's friction-row stiffness ``D_f`` over the wheels' (largest);
* the condition number of Newton's Hessian ``H = M + Jᵀ D J`` over the rows in their
  quadratic state (all of them at rest), against ``1/ε`` of float32, the precision of
  MuJoCo Warp's Cholesky;
* what MuJoCo Warp (``backend="warp"``, float32) does with the robot's first kinematic
  body-frame scenario for :data:`DURATION` s from the same settled start: runs, or
  diverges (the :class:`~wmr_mujoco.sim.stepping.SimulationDivergedError` it raises).
"""

from __future__ import annotations

import copy
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.bench.batch_throughput import DOC
from wmr_mujoco.docs_sync.markers import publish, study_parser

MARKER = "caster-conditioning"
#: Seconds at rest before the Hessian is formed.
SETTLE = 0.5
#: Seconds of the scenario stepped on MuJoCo Warp.
DURATION = 1.0


@dataclass(frozen=True)
class Row:
    """One robot at one caster contact setting."""

    robot: str
    setting: str
    impratio_d: float
    stiffness_ratio: float
    condition: float
    warp: str


def variants(robot: str) -> dict[str, mujoco.MjModel]:
    """The default model and the one without caster pairs (empty: no caster pair)."""
    from wmr_mujoco.lookup import build_scene
    from wmr_mujoco.models.builders.common import to_xml
    from wmr_mujoco.models.builders.wheel_pairs import caster_collider_names
    from wmr_mujoco.robots import get_spec

    spec = get_spec(robot)
    if spec.build is None or spec.params_type is None:
        return {}
    params = spec.params_type()
    casters = set(caster_collider_names(spec.build(params)))
    scene = build_scene(robot, params)
    pairs = [p for p in scene.contact.get_children("pair")
             if getattr(p.geom2, "name", p.geom2) in casters]
    if not pairs:
        return {}
    default = mujoco.MjModel.from_xml_string(to_xml(scene))
    for p in pairs:
        p.remove()
    return {"paired (default)": default,
            "contact bits": mujoco.MjModel.from_xml_string(to_xml(scene))}


def measure(robot: str, setting: str, model: mujoco.MjModel, warp: bool = True) -> Row:
    """Settle ``model`` at rest, read the caster's contact and Newton's Hessian, run Warp.

    ``warp`` False: no Warp run (its column reads ``"not run"``).
    """
    outcome = warp_run(robot, model) if warp else "not run"
    model.opt.jacobian = mujoco.mjtJacobian.mjJAC_DENSE
    data = mujoco.MjData(model)
    for _ in range(round(SETTLE / model.opt.timestep)):
        mujoco.mj_step(model, data)
    mujoco.mj_forward(model, data)
    n, nv = data.nefc, model.nv
    jac = np.array(data.efc_J[:n * nv]).reshape(n, nv)
    full_m = np.zeros((nv, nv))
    mujoco.mj_fullM(model, data, full_m)
    quad = data.efc_state[:n] == mujoco.mjtConstraintState.mjCNSTRSTATE_QUADRATIC
    h = full_m + jac[quad].T @ (data.efc_D[:n][quad, None] * jac[quad])
    imp = np.array(data.efc_KBIP).reshape(-1, 4)[:n, 2]
    floor = model.geom("floor").id
    caster_d, wheel_f, caster_f = [], [], []
    for c in data.contact[:data.ncon]:
        if floor not in c.geom:
            continue
        other = int(c.geom[1] if c.geom[0] == floor else c.geom[0])
        body = int(model.geom_bodyid[other])
        ball = any(model.jnt_type[model.body_jntadr[body] + k] == mujoco.mjtJoint.mjJNT_BALL
                   for k in range(model.body_jntnum[body]))
        friction = data.efc_D[c.efc_address + 1:c.efc_address + c.dim]
        if ball:
            caster_d.append(imp[c.efc_address])
            caster_f.extend(friction)
        else:
            wheel_f.extend(friction)
    return Row(robot, setting, model.opt.impratio * max(caster_d),
               max(caster_f) / max(wheel_f), float(np.linalg.cond(h)), outcome)


def warp_run(robot: str, model: mujoco.MjModel) -> str:
    """``"runs"`` or the divergence: the first kinematic body-frame scenario on Warp."""
    from wmr_mujoco.batch.warp_backend import WarpBackend
    from wmr_mujoco.robots import get_spec
    from wmr_mujoco.sim.stepping import SimulationDivergedError
    from wmr_mujoco.validation.runner import prepare
    from wmr_mujoco.validation.scenarios import ScenarioKind

    if not WarpBackend.installed():
        return "not installed"
    spec = get_spec(robot)
    scenario = next(s for s in spec.scenarios
                    if s.kind is ScenarioKind.KINEMATIC and not s.world_frame)
    prep = prepare(spec, scenario, None, model=copy.copy(model))
    prep.controls = prep.controls[:round(DURATION / model.opt.timestep)]
    try:
        WarpBackend().run([prep])
    except SimulationDivergedError as err:
        return f"{scenario.name}: diverged, {str(err).split(';')[0]}"
    return f"{scenario.name}: runs {DURATION:g} s"


def rows(robots: Sequence[str] | None = None) -> list[Row]:
    """Both settings of every robot with a caster pair (all robots if None)."""
    from wmr_mujoco.robots import ROBOTS

    return [measure(robot, setting, model) for robot in (robots or ROBOTS)
            for setting, model in variants(robot).items()]


def table(found: Sequence[Row]) -> str:
    """Markdown, one row per robot and setting."""
    eps = float(np.finfo(np.float32).eps)
    lines = ["`python -m wmr_mujoco.bench.caster_conditioning`: each robot settled "
             f"{SETTLE:g} s at rest in C MuJoCo; float32 ε = {eps:.2g} (1/ε = {1 / eps:.2g}).",
             "", "| robot | caster contact | impratio · d | caster D_f / wheel D_f | "
             "cond(H) at rest | MuJoCo Warp |",
             "|---|---|---|---|---|---|"]
    lines += [f"| {r.robot} | {r.setting} | {r.impratio_d:.3g} | {r.stiffness_ratio:.3g} | "
              f"{r.condition:.2g} | {r.warp} |" for r in found]
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> None:
    """Measure, print, and paste the table into docs/batch.md (unless ``--no-write``)."""
    args = study_parser(__doc__.splitlines()[0]).parse_args(argv)
    publish(DOC, {MARKER: table(rows())}, not args.no_write)


if __name__ == "__main__":
    main()
