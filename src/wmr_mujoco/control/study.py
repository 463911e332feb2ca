"""Closing the loop: the tables of ``docs/control.md``.

Runs every controller task on both backends over seeded families, the Whipple bicycle's
push runs, and the Lie-bracket sweep; prints the tables and pastes them between the
markers of ``docs/control.md`` (``--no-write``: print only). Usage::

    python -m wmr_mujoco.control.study [--no-write] [--draws N]
"""

from __future__ import annotations

from collections.abc import Sequence

from wmr_mujoco.control import closed_loop, lie_bracket, whipple_upright
from wmr_mujoco.docs_sync.markers import fixed, publish, study_parser
from wmr_mujoco.models.paths import REPO_ROOT

DOC = REPO_ROOT / "docs" / "control.md"
#: The tasks of the tracking table: (robot, controller, path).
TASKS = (
    ("diffdrive", "go_to_pose", "line"),
    ("diffdrive", "pure_pursuit", "figure_eight"),
    ("diffdrive", "stanley", "lane_change"),
    ("diffdrive", "kanayama", "random_spline"),
    ("bicycle", "pure_pursuit", "random_spline"),
    ("bicycle", "stanley", "lane_change"),
    ("bicycle", "kanayama", "figure_eight"),
    ("omni3", "holonomic", "figure_eight"),
)
#: Draws of each family (the project's rule: at least 20 for a dynamic claim).
DRAWS = 20


def mm(x: float) -> str:
    """Metres as millimetres, one decimal."""
    return fixed(1000.0 * x, 1)


def tracking_table(draws: int = DRAWS) -> str:
    """Worst and median tracking figures per task, physics | model."""
    head = ("| robot | controller | path | worst cross-track, mm | settled worst "
            "cross-track, mm | RMS cross-track, mm | final position error, mm | "
            "physics-model deviation, mm |\n|---|---|---|---|---|---|---|---|")
    rows = [head]
    for robot, controller, path in TASKS:
        s = closed_loop.family(robot, controller, path, draws)
        cells = []
        for key in ("worst cross-track [m]", "settled worst cross-track [m]",
                    "RMS cross-track [m]", "final position error [m]"):
            (pw, mw), (pm, mmed) = s.worst[key], s.median[key]
            cells.append(f"{mm(pw)} \\| {mm(mw)} ({mm(pm)} \\| {mm(mmed)})")
        dev_w, dev_m = s.worst["physics-model deviation [m]"][0], \
            s.median["physics-model deviation [m]"][0]
        cells.append(f"{mm(dev_w)} ({mm(dev_m)})")
        rows.append(f"| {robot} | {controller} | {path} | " + " | ".join(cells) + " |")
        print(rows[-1], flush=True)
    return "\n".join(rows) + (
        f"\n\nEach cell: worst over {draws} seeded draws, physics \\| model, and in "
        "brackets the medians. Draw k starts ``default_rng(k)``-offset from the path's "
        f"start: lateral ±{closed_loop.LATERAL:g} m, heading ±{closed_loop.HEADING:g} rad; "
        "the random spline is seed k. Control period "
        f"{closed_loop.PERIOD:g} s, path speed 0.5 m/s.")


def whipple_table(draws: int = DRAWS) -> str:
    """Upright time after the push at 3 and 2 m/s, and the controlled family."""
    rows = ["| speed, m/s | law | upright time, s (physics \\| linear model) | peak lean, "
            "rad (physics \\| linear model) |", "|---|---|---|---|"]
    for v in whipple_upright.SPEEDS:
        for controlled in (False, True):
            p = whipple_upright.physics(v, controlled=controlled)
            m = whipple_upright.linear(v, controlled=controlled)
            law = "LQR steer into the lean" if controlled else "none (torques 0)"
            rows.append(f"| {v:g} | {law} | {fixed(p.upright_time)} \\| "
                        f"{fixed(m.upright_time)} | {fixed(p.peak_lean, 3)} \\| "
                        f"{fixed(m.peak_lean, 3)} |")
    f = whipple_upright.family(draws)
    lo, hi = whipple_upright.SPEED_RANGE
    plo, phi = whipple_upright.PUSH_RANGE
    rows.append(
        f"\nFamily, LQR on: {f.draws} seeded draws of speed in [{lo:g}, {hi:g}] m/s and "
        f"push ±[{plo:g}, {phi:g}] rad/s: shortest upright time {fixed(f.min_upright[0])} s "
        f"(physics) \\| {fixed(f.min_upright[1])} s (linear model) of "
        f"{whipple_upright.DURATION:g} s; worst peak lean {fixed(f.worst_peak[0], 3)} \\| "
        f"{fixed(f.worst_peak[1], 3)} rad (median {fixed(f.median_peak[0], 3)} \\| "
        f"{fixed(f.median_peak[1], 3)} rad). Fallen: |lean| > "
        f"{whipple_upright.FALLEN:g} rad; push {whipple_upright.PUSH:g} rad/s in the table; "
        f"control period {whipple_upright.PERIOD:g} s.")
    return "\n".join(rows)


def bracket_table(draws: int = DRAWS) -> str:
    """The Lie-bracket sweep on diffdrive and disc."""
    rows = ["| robot | ε | exact net step, mm | second-order error | kinematic backend "
            "error | physics error, worst (median) | physics net heading change, rad |",
            "|---|---|---|---|---|---|---|"]
    for robot in ("diffdrive", "disc"):
        for r in lie_bracket.sweep(robot, lie_bracket.EPSILONS, draws):
            rows.append(f"| {robot} | {r.eps:g} | {mm(r.exact_net)} | "
                        f"{100 * r.bracket_error:.1f} % | {100 * r.model_error:.2g} % | "
                        f"{100 * r.physics_worst:.2g} % ({100 * r.physics_median:.2g} %) | "
                        f"{r.physics_heading:.1e} |")
            print(rows[-1], flush=True)
    return "\n".join(rows) + (
        f"\n\nErrors relative to the exact net step; worst over {draws} seeded draws of "
        f"speed {lie_bracket.SPEED_RANGE} m/s, turn rate {lie_bracket.RATE_RANGE} rad/s "
        "and start heading. Target: physics within 5 %.")


def main(argv: Sequence[str] | None = None) -> None:
    """Run the study, print the tables and paste them into ``docs/control.md``."""
    parser = study_parser(__doc__)
    parser.add_argument("--draws", type=int, default=DRAWS,
                        help=f"draws per family (default {DRAWS})")
    args = parser.parse_args(argv)
    if not 1 <= args.draws <= 1000:
        parser.error(f"--draws {args.draws}: must be in [1, 1000]")
    texts = {"control tracking": tracking_table(args.draws),
             "control whipple": whipple_table(args.draws),
             "control lie bracket": bracket_table(args.draws)}
    publish(DOC, texts, not args.no_write)


if __name__ == "__main__":
    main()
