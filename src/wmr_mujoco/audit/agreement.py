"""Agreement of the audit with ``wmr validate`` on every robot of this package.

``python -m wmr_mujoco.audit.agreement [--no-write] [ROBOT ...]`` audits each registered
robot's scene as a foreign file (no registry knowledge: wheels, Jacobian, servos all
found from the compiled model) and runs the robot's own kinematic validation scenarios
(its analytic model, its inputs, its metric "worst position error % of path"), then
pastes the table into docs/audit.md between the ``audit agreement`` markers, and one
audit's summary between the ``audit example`` markers there (and in the README, where it
has them).

The two drive different manoeuvres (speeds, durations, paths) through different models
of the same kinematics, so they agree when both call the robot's kinematics faithful or
both do not: :data:`TOLERANCE` percentage points between the worst figures, or both
under the audit's "follows" threshold.
"""

from __future__ import annotations

from collections.abc import Sequence

from wmr_mujoco.audit.anchors import anchor_scene
from wmr_mujoco.audit.core import audit, judged
from wmr_mujoco.audit.errors import NotWheeledError
from wmr_mujoco.audit.figures import FOLLOWS
from wmr_mujoco.audit.limits import DRAWS
from wmr_mujoco.audit.report import summary_text
from wmr_mujoco.docs_sync.markers import has_markers, publish, replace_between, study_parser
from wmr_mujoco.models.paths import README_PATH, REPO_ROOT
from wmr_mujoco.robots import ROBOTS
from wmr_mujoco.validation.metrics import POSITION_PCT
from wmr_mujoco.validation.runner import run_all
from wmr_mujoco.validation.scenarios import ScenarioKind

#: Largest difference of the worst position errors (percentage points) called agreement.
TOLERANCE = 3.0
DOC = REPO_ROOT / "docs" / "audit.md"
KEY = "audit agreement"
EXAMPLE_KEY = "audit example"


def _validate_worst(robot: str, only: Sequence[str] | None = None
                    ) -> tuple[float | None, str]:
    scen = [s for s in ROBOTS[robot].scenarios if s.kind == ScenarioKind.KINEMATIC
            and (only is None or s.name in only)]
    if not scen:
        return None, "no kinematic scenario"
    worst, where = None, ""
    for res in run_all([(ROBOTS[robot], s) for s in scen]):
        for r in res.rows:
            if f"{r.metric} {r.unit}" == POSITION_PCT and (worst is None or r.value > worst):
                worst, where = r.value, r.scenario
    return worst, where


def row(robot: str, duration: float = 2.0, draws: int = DRAWS,
        only: Sequence[str] | None = None) -> str:
    """One table row for ``robot``.

    The audit's worst over ``draws`` seeded draws beside the worst of the robot's
    kinematic validation scenarios (``only`` those named, default all).
    """
    spec = ROBOTS[robot]
    try:
        a = audit(spec.scene_path, duration=duration, diagnose=False, draws=draws)
    except NotWheeledError as err:
        return f"| {robot} | not audited: {err} | | | | |"
    o = a.worst()
    ours = judged(o.figures, a.span)
    theirs, where = _validate_worst(robot, only)
    if theirs is None:
        return (f"| {robot} | ({a.robot_class[0]},{a.robot_class[1]}) | {o.manoeuvre.name}: "
                f"{ours:.1f} | {where} | | |")
    agree = abs(ours - theirs) <= TOLERANCE or max(ours, theirs) <= FOLLOWS[0]
    return (f"| {robot} | ({a.robot_class[0]},{a.robot_class[1]}) | {o.manoeuvre.name}: "
            f"{ours:.1f} | {where}: {theirs:.1f} | {abs(ours - theirs):.1f} | "
            f"{'yes' if agree else 'NO'} |")


def table(robots: Sequence[str] | None = None) -> str:
    """The agreement table (module docstring)."""
    head = ["| robot | class (audit) | audit worst, % of path (a spin: drift, % of span) | "
            "validate worst kinematic, % of path | difference, points | agree |",
            "|---|---|---|---|---|---|"]
    return "\n".join(head + [row(r) for r in (robots or list(ROBOTS))])


def example(duration: float = 2.0) -> str:
    """The summary of one audit (the peer omni robot, else this package's omni3), fenced."""
    scene = anchor_scene("robot_soccer_kit") or ROBOTS["omni3"].scene_path
    a = audit(scene, duration=duration)
    name = "robot_soccer_kit/scene.xml" if "robot_soccer_kit" in str(scene) else "omni3"
    return f"```\n$ wmr audit {name} --out audit/\n{summary_text(a)}\n```"


def main(argv: Sequence[str] | None = None) -> int:
    """Print the tables and paste them into docs/audit.md."""
    parser = study_parser(__doc__.splitlines()[0])
    parser.add_argument("robots", nargs="*")
    args = parser.parse_args(argv)
    snippet = example()
    publish(DOC, {EXAMPLE_KEY: snippet, KEY: table(args.robots or None)}, not args.no_write)
    if not args.no_write and has_markers(README_PATH, EXAMPLE_KEY):
        replace_between(README_PATH, EXAMPLE_KEY, snippet)
        print(f"wrote {README_PATH}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
