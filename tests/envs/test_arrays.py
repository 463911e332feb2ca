"""The tasks' step math over worlds (``envs.tasks.arrays``) against the scalar tasks.

Each array class must give, world by world, the floats of its scalar task's
``evaluate_observe``: the same operations in the same order (numpy's elementwise
arithmetic rounds as Python's floats; the transcendental functions are :mod:`math`'s), so
the comparisons are exact. The states are synthetic, placed where the vector environment's
short episodes rarely go: far along a path in one step, backwards, beside a goal.
"""

import math
from typing import NamedTuple

import numpy as np
import pytest

from wmr_mujoco.envs.profiles import profile
from wmr_mujoco.envs.tasks import task_class
from wmr_mujoco.envs.tasks.arrays import ARRAYS, effort
from wmr_mujoco.envs.worlds import States, each


class Fake(NamedTuple):
    """The parts of a snapshot the tasks read."""

    xyh: tuple[float, float, float]
    uvr: tuple[float, float, float]
    extra: dict


def _tasks(name, robot, n, seed):
    prof = profile(robot)
    tasks = [task_class(name)(prof.scale, prof.max_curvature,
                              **prof.task_options.get(name, {})) for _ in range(n)]
    rng = np.random.default_rng(seed)
    starts = [t.sample(rng) for t in tasks]
    return tasks, starts


def _states(fakes):
    xyh = np.array([f.xyh for f in fakes])
    uvr = np.array([f.uvr for f in fakes])
    extra = {k: np.array([f.extra[k] for f in fakes]) for k in fakes[0].extra}
    return States(np.zeros(len(fakes)), xyh[:, 0], xyh[:, 1], xyh[:, 2], uvr,
                  np.zeros((len(fakes), 0)), extra)


def _reset(tasks, arrays, starts):
    """Each world at rest at its start: the scalar task's first observation (a full
    search, as at a reset) and the arrays loaded from the same state."""
    states = [Fake(tuple(s.tolist()), (0.0, 0.0, 0.0), {}) for s in starts]
    for i, task in enumerate(tasks):
        task.observe(states[i])
        arrays.load(i, states[i])
    return states


def _compare(tasks, arrays, prev, new, actions, dt):
    out = np.zeros((len(tasks), tasks[0].size))
    terms, success, failure = arrays.step(_states(new), actions, dt, out)
    for i, task in enumerate(tasks):
        t, s, f, obs = task.evaluate_observe(prev[i], new[i], actions[i].tolist(), dt)
        assert out[i].tolist() == obs, i
        assert {k: v[i] for k, v in terms.items()} == t, i
        assert (bool(success[i]), bool(failure[i])) == (s, f), i


def _path_pose(task, s, side, dpsi):
    """A pose at arc length s of the task's path, ``side`` m to its left."""
    p = task.path
    x, y = np.interp(s, p.s, p.xy[:, 0]), np.interp(s, p.s, p.xy[:, 1])
    h = np.interp(s, p.s, p.heading)
    return (float(x - side * math.sin(h)), float(y + side * math.cos(h)), float(h + dpsi))


@pytest.mark.parametrize("robot", ["disc", "bicycle"])
def test_follow_path_arrays_equal_the_scalar_task_far_walks_included(robot):
    n, dt = 5, 0.02
    tasks, starts = _tasks("FollowPath", robot, n, 3)
    arrays = ARRAYS["FollowPath"](tasks)
    rng = np.random.default_rng(4)
    prev = _reset(tasks, arrays, starts)
    # Arc-length jumps per step: small, many segments forward (past the first pass's
    # four segments), backward, and beyond the path's end (the look-ahead clipped).
    s_now = np.array([task.project(p).s for task, p in zip(tasks, prev, strict=True)])
    for jump in (0.01, 0.3, -0.2, 0.05, -0.01, 2.0, 50.0):
        s_now = np.maximum(s_now + jump * tasks[0].scale, 0.0)
        new = [Fake(_path_pose(t, s, rng.uniform(-0.2, 0.2) * t.scale, rng.uniform(-3, 3)),
                    (0.0, 0.0, 0.0), {}) for t, s in zip(tasks, s_now, strict=True)]
        _compare(tasks, arrays, prev, new, rng.uniform(-1, 1, (n, 2)), dt)
        prev = new


def test_go_to_goal_arrays_equal_the_scalar_task():
    n, dt = 6, 0.02
    tasks, starts = _tasks("GoToGoal", "diffdrive", n, 5)
    arrays = ARRAYS["GoToGoal"](tasks)
    prev = _reset(tasks, arrays, starts)
    rng = np.random.default_rng(6)
    for k in range(6):
        # last steps: at the goal (success), then far outside the arena (failure)
        near = [tuple(t.goal.tolist()) for t in tasks] if k == 4 else None
        new = [Fake(near[i] if near else (float(rng.uniform(-3, 3)) * (10 if k == 5 else 1),
                                          float(rng.uniform(-3, 3)), float(rng.uniform(-9, 9))),
                    (0.0, 0.0, 0.0), {}) for i in range(n)]
        _compare(tasks, arrays, prev, new, rng.uniform(-1, 1, (n, 3)), dt)
        prev = new


def test_stay_upright_arrays_equal_the_scalar_task():
    n, dt = 4, 0.01
    tasks, _ = _tasks("StayUpright", "whipple", n, 7)
    arrays = ARRAYS["StayUpright"](tasks)
    rng = np.random.default_rng(8)
    states = [Fake((0.0, 0.0, 0.0), (float(rng.uniform(1, 4)), 0.0, 0.0),
                   {"lean": float(rng.uniform(-1, 1)), "lean_rate": float(rng.normal()),
                    "steer": float(rng.normal()), "steer_rate": float(rng.normal())})
              for _ in range(n)]
    for i in range(n):
        arrays.load(i, states[i])
    _compare(tasks, arrays, states, states, rng.uniform(-1, 1, (n, 2)), dt)
    ok = arrays.succeeded_at_time_limit(_states(states))
    assert ok.tolist() == [t.succeeded_at_time_limit(s) for t, s in zip(tasks, states, strict=True)]


def test_effort_and_each_are_the_scalar_sums_and_functions():
    a = np.random.default_rng(9).uniform(-1, 1, (7, 3))
    expected = [-0.01 * (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) / 3 for r in a.tolist()]
    assert effort(a).tolist() == expected
    x = np.linspace(-7.0, 7.0, 11)
    assert each(math.atan2, x, x[::-1]).tolist() == [math.atan2(p, q) for p, q in
                                                     zip(x.tolist(), x[::-1].tolist(), strict=True)]
    assert each(math.remainder, x, math.tau).tolist() == [math.remainder(v, math.tau) for v in x]


@pytest.mark.parametrize("error", [-5, 0, 3])
def test_the_look_ahead_search_is_bisect_whatever_its_guess(error):
    # The search guesses each query's sample from a sample at or before it (the walk's
    # segment) plus the look-ahead distance over the mean spacing, and counts the samples
    # <= q in a window of 4 around the guess; a query outside it goes to bisect. A wrong
    # guess (off by `error` samples: most queries outside their window) must change
    # nothing, nor may a query on a sample or at the path's end.
    import bisect

    tasks, starts = _tasks("FollowPath", "disc", 3, 11)
    arrays = ARRAYS["FollowPath"](tasks)
    for i, (task, start) in enumerate(zip(tasks, starts, strict=True)):
        state = Fake(tuple(start.tolist()), (0.0, 0.0, 0.0), {})
        task.observe(state)
        arrays.load(i, state)
    arrays.skip += error
    rng = np.random.default_rng(12)
    i = np.array([rng.integers(0, len(t._s) - 1) for t in tasks])
    s_i = np.array([t._s[k] for t, k in zip(tasks, i, strict=True)])
    q = np.minimum(s_i[:, None] + rng.uniform(0, 3, (3, 5)), arrays.send)
    q[0, 0] = s_i[0]  # on the sample guessed from
    # exactly on samples (bisect_right counts a tie), on the last sample (k stops at the
    # last segment), between the last two
    last = len(tasks[1]._s) - 1
    q[1, :3] = [tasks[1]._s[min(j, last)] for j in (i[1], i[1] + 7, i[1] + 30)]
    q[2, 3:] = [tasks[2]._s[-1], 0.5 * (tasks[2]._s[-2] + tasks[2]._s[-1])]
    k = arrays._search(q, arrays.base + i) - arrays.base[:, None]
    for w, task in enumerate(tasks):
        assert k[w].tolist() == [min(bisect.bisect_right(task._s, v) - 1, len(task._s) - 2)
                                 for v in q[w].tolist()]
