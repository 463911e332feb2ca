import math
from types import SimpleNamespace

import numpy as np
import pytest

from wmr_mujoco.envs.tasks import FollowPath, GoToGoal, StayUpright, task_class
from wmr_mujoco.envs.tasks.base import to_body, wrap


def state(x=0.0, y=0.0, psi=0.0, u=0.0, **extra):
    return SimpleNamespace(pose=np.array([x, y, psi]), twist=np.array([u, 0.0, 0.0]),
                           extra=extra)


def test_to_body_rotates_into_the_robot_frame():
    # A point 1 m along the world y axis, seen by a robot heading +y, is 1 m ahead.
    np.testing.assert_allclose(to_body(np.array([0.0, 0.0, math.pi / 2]), [0.0, 1.0]),
                               [1.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(to_body(np.array([1.0, 1.0, 0.0]), [1.0, 3.0]), [0.0, 2.0])
    assert abs(wrap(3 * math.pi)) == pytest.approx(math.pi)  # ±π: the same heading
    assert wrap(2.5 * math.pi) == pytest.approx(math.pi / 2)


def test_goal_observation_and_progress_reward():
    task = GoToGoal(scale=1.0, max_curvature=1.0)
    task.goal = np.array([2.0, 0.0, 0.5])
    obs = task.observe(state(psi=math.pi / 2))
    # Robot heading +y: the goal 2 m along +x is 2 m to its right (body y = -2).
    np.testing.assert_allclose(obs[:2], [0.0, -2.0], atol=1e-12)
    np.testing.assert_allclose(obs[2:4], [math.sin(0.5 - math.pi / 2),
                                          math.cos(0.5 - math.pi / 2)])
    assert obs[4] == pytest.approx(2.0)
    terms = task.reward_terms(state(0.0), state(0.5), np.zeros(2), 0.02)
    # Φ_d = -d/L: 0.5 m closer with L = 1 m is +0.5.
    assert terms["progress"] == pytest.approx(0.5)
    assert terms["success"] == 0.0


def test_goal_success_needs_position_and_heading():
    task = GoToGoal(scale=1.0, max_curvature=1.0)
    task.goal = np.array([1.0, 0.0, 0.0])
    assert task.outcome(state(0.95, 0.0, 0.1)) == (True, False)
    assert task.outcome(state(0.95, 0.0, 0.5)) == (False, False)   # heading off by 0.5 rad
    assert task.outcome(state(0.8, 0.0, 0.0)) == (False, False)    # 0.2 m short
    assert task.outcome(state(7.0, 0.0, 0.0)) == (False, True)     # left the 5 m arena


@pytest.mark.parametrize("seed", range(20))
def test_goal_draws_lie_in_the_stated_family(seed):
    task = GoToGoal(scale=2.0, max_curvature=1.0)
    start = task.sample(np.random.default_rng(seed))
    d = np.hypot(*task.goal[:2])
    assert 2.0 <= d <= 5.0
    bearing = math.atan2(task.goal[1], task.goal[0])
    assert abs(wrap(bearing - start[2])) <= 2 * math.pi / 3 + 1e-12
    assert abs(wrap(task.goal[2] - bearing)) <= math.pi / 3 + 1e-12


def test_follow_path_observation_on_the_path():
    task = FollowPath(scale=1.0, max_curvature=1.0)
    rng = np.random.default_rng(0)
    start = task.sample(rng)
    p0 = task.path.xy[0]
    assert np.hypot(*(start[:2] - p0)) <= 0.1 + 1e-12
    obs = task.observe(state(*p0, task.path.heading[0]))
    # On the path and aligned: no cross-track error, heading error 0, all of it ahead.
    assert obs[10] == pytest.approx(0.0, abs=1e-12)
    np.testing.assert_allclose(obs[11:13], [0.0, 1.0], atol=1e-12)
    assert obs[13] == pytest.approx(task.end)
    # The first look-ahead point, 0.25 m along a path starting straight (κ ramps up
    # over the first 10 % = 0.4 m), is nearly straight ahead.
    assert obs[0] == pytest.approx(0.25, abs=DS_TOL)
    assert abs(obs[1]) < 0.01


DS_TOL = 0.03  # one vertex spacing (0.02 m) plus the path's bending over 0.25 m


def test_follow_path_failure_beyond_max_deviation():
    task = FollowPath(scale=1.0, max_curvature=1.0)
    task.sample(np.random.default_rng(1))
    p, psi = task.path.xy[0], task.path.heading[0]
    off = 0.6 * np.array([-math.sin(psi), math.cos(psi)])
    assert task.outcome(state(*(p + off), psi)) == (False, True)


def test_unknown_task_and_options_are_named():
    with pytest.raises(ValueError, match="valid tasks: GoToGoal, FollowPath, StayUpright"):
        task_class("Park")
    with pytest.raises(ValueError, match="valid options: .*position_tolerance"):
        GoToGoal(1.0, 1.0, tolerance=0.1)
    with pytest.raises(ValueError, match="positive finite"):
        GoToGoal(1.0, 1.0, time_limit=float("nan"))
    with pytest.raises(ValueError, match="min_distance"):
        GoToGoal(1.0, 1.0, min_distance=3.0, max_distance=2.0)


def test_stay_upright_speeds_must_be_below_the_weave_speed():
    task = StayUpright(1.0, 1.0)
    # The benchmark bicycle's weave speed (Meijaard et al. 2007, Table 2: 4.292 m/s).
    assert task.weave_speed == pytest.approx(4.29, abs=0.01)
    with pytest.raises(ValueError, match="weave speed"):
        StayUpright(1.0, 1.0, max_speed=5.0)


def test_stay_upright_terms():
    task = StayUpright(1.0, 1.0)
    task.sample(np.random.default_rng(0))
    up = state(u=task.speed, lean=0.0, lean_rate=0.0, steer=0.0, steer_rate=0.0)
    fallen = state(u=task.speed, lean=0.8, lean_rate=0.0, steer=0.0, steer_rate=0.0)
    t = task.reward_terms(up, up, np.zeros(2), 0.01)
    assert t["alive"] == 0.01 and t["lean"] == 0.0 and t["speed"] == 0.0
    assert task.outcome(fallen) == (False, True)
    assert task.succeeded_at_time_limit(up)


def test_follow_path_projection_walk_equals_the_path_search():
    # The task's float walk must find the nearest point that Path.closest finds (a
    # projection onto the same polyline): a robot wandering up to 0.3 m off the path and
    # moving 2 cm per step. Equal to 1e-9 m (rounding of the two formulas only).
    task = FollowPath(scale=1.0, max_curvature=1.5)
    rng = np.random.default_rng(4)
    task.sample(rng)
    path = task.path
    for s in np.arange(0.0, task.end + 0.5, 0.02):
        p = path.at(s)
        off = 0.3 * math.sin(3.0 * s)  # sideways, both sides
        xy = p.position + off * np.array([-math.sin(p.heading), math.cos(p.heading)])
        got = task.project(state(*xy, p.heading))
        want = path.closest(xy)
        assert got.s == pytest.approx(want.s, abs=1e-9)
        assert abs(got.cross_track) == pytest.approx(np.hypot(*(xy - want.position)), abs=1e-9)
        assert math.copysign(1.0, got.cross_track) == math.copysign(1.0, off) or abs(off) < 1e-9


def test_follow_path_points_ahead_are_the_path_positions():
    # The look-ahead points interpolated on floats equal Path.positions (numpy's interp),
    # in the body frame, including beyond the far end (clipped to it).
    task = FollowPath(scale=1.0, max_curvature=1.0)
    task.sample(np.random.default_rng(2))
    path = task.path
    for s in (0.0, 1.3, task.end - 0.1, path.length - 0.2):
        p = path.at(s)
        st = state(*p.position, p.heading + 0.2)
        obs = task.observe(st)
        s_star = task.project(st).s
        world = path.positions(s_star + np.array([0.25, 0.5, 0.75, 1.0, 1.5]))
        c, sn = math.cos(p.heading + 0.2), math.sin(p.heading + 0.2)
        d = world - p.position
        body = np.column_stack([c * d[:, 0] + sn * d[:, 1], c * d[:, 1] - sn * d[:, 0]])
        np.testing.assert_allclose(obs[:10], body.ravel(), atol=1e-9)


@pytest.mark.parametrize(("robot", "task"), [("disc", "FollowPath"), ("disc", "GoToGoal"),
                                             ("whipple", "StayUpright")])
def test_evaluate_observe_is_evaluate_and_observe(robot, task):
    # The environments' one call per step must equal the two calls exactly (same floats).
    from wmr_mujoco.envs.episode import Episode

    ep = Episode(robot, task)
    ep.reset(np.random.default_rng(4))
    rng = np.random.default_rng(5)
    for _ in range(20):
        prev = ep.state
        a = rng.uniform(-0.5, 0.5, ep.n_action).tolist()
        ep.push(a)
        ep.state = state = ep.stepper.finish()
        fused = ep.task.evaluate_observe(prev, state, a, ep.dt)
        assert fused == (*ep.task.evaluate(prev, state, a, ep.dt), ep.task.observe(state))
