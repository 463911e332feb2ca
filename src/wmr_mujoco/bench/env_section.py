"""The learning environments in ``wmr bench``: scripted success rates and throughput.

Runs :mod:`wmr_mujoco.bench.env_success` on every environment (100 seeded episodes each,
10 with ``--quick``) and :mod:`wmr_mujoco.bench.env_throughput` on every environment
(5 rounds of 1 s runs, each ratio the median of the rounds' paired ratios; 1 round of
0.2 s with ``--quick``), and writes both tables
with the worst figures and the goals beside them. Without Gymnasium (the ``rl`` extra)
the section says so and is left out.
"""

from __future__ import annotations

import sys


def env_section(quick: bool) -> tuple[dict[str, object] | None, str]:
    """``(results, Markdown)`` of the section (results None without Gymnasium)."""
    try:
        import gymnasium  # noqa: F401
    except ModuleNotFoundError:
        return None, ("Left out: Gymnasium is not installed (pip install 'wmr-mujoco[rl]'; "
                      "the test extra has it).")
    import wmr_mujoco.envs as wenvs
    from wmr_mujoco.bench import env_success, env_throughput

    episodes = 10 if quick else 100
    seconds, repeats = (0.2, 1) if quick else (1.0, 5)
    success = {}
    for env_id in wenvs.ENV_IDS:
        print(f"  scripted {env_id} ...", file=sys.stderr, flush=True)
        success[env_id] = env_success.success_rate(env_id, episodes, 0)
    speed = {}
    for env_id in wenvs.ENV_IDS:  # every environment: each task costs its own
        print(f"  throughput {env_id} ...", file=sys.stderr, flush=True)
        speed[env_id] = env_throughput.measure(env_id, seconds, repeats)
    worst = min(r["successes"] / r["episodes"] for r in success.values())
    worst_env = min(m["env_ratio"] for m in speed.values())
    worst_vec = env_throughput.worst(speed)  # the native vector env at 16 worlds
    worst_64 = min(m["vector64_ratio"] for m in speed.values())
    worst_sync = min(m["sync_ratio"] for m in speed.values())
    text = "\n\n".join([
        f"Scripted controllers ({episodes} seeded episodes per environment, seeds 0 to "
        f"{episodes - 1}; `python -m wmr_mujoco.bench.env_success`): worst success rate "
        f"{100 * worst:.1f} % (goal >= {100 * env_success.GOAL:.0f} %).",
        env_success.HEADER + "\n" + "\n".join(env_success.row(i, r) for i, r in success.items()),
        f"Steps per second in one process against a bare `mj_step` loop with the same frame "
        f"skip, replaying a scripted episode (`python -m wmr_mujoco.bench.env_throughput`; "
        f"{repeats} rounds of {seconds:g} s runs, each ratio the median over the rounds of the "
        f"ratio within a round, the bare loop timed first and last in it; resets timed "
        f"apart): worst "
        f"env / bare "
        f"{100 * worst_env:.0f} % (single env); worst native vector environment "
        f"(`gymnasium.make_vec`, batched step) / bare at {env_throughput.JUDGED} worlds "
        f"{100 * worst_vec:.0f} % (goal >= {100 * env_throughput.GOAL:.0f} %), at 64 worlds "
        f"{100 * worst_64:.0f} %; Gymnasium's generic sync vectorisation of 4, for "
        f"comparison: worst {100 * worst_sync:.0f} %.",
        env_throughput.table(speed)])
    return {"success": success, "throughput": speed}, text
