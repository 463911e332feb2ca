"""Families whose spread is not small judge 20 draws (issue 24: fewer only where it is).

A kinematic family may judge :data:`~wmr_mujoco.validation.variations.KINEMATIC_DRAWS`
draws only where its spread is small: every member within half of each judged target
(:data:`wmr_mujoco.bench.family_spread.SMALL`), so that a few draws judge a family whose
worst still keeps a twofold margin. The families below were declared with 3 draws, yet
a member at the edge of their ranges (every input 1.2 times its nominal: the faster,
tighter turn slides the wheels most) is beyond half a target; at seeds 7 and 42 their
3 draws already judged 0.64-0.67 of a target. Each such member is run here: beyond half
its target (so 3 draws do not do) and within the target (the family, judged on 20
draws, still passes at that edge).
"""

import pytest

from wmr_mujoco.bench.family_spread import SMALL
from wmr_mujoco.robots import get_spec
from wmr_mujoco.validation.members import run_batched
from wmr_mujoco.validation.variations import DYNAMIC_DRAWS, INPUT_SCALE, WHEEL_PHASE, input_scale

_SCALED = {input_scale(0): 1.2, input_scale(1): 1.2}
EDGES = (
    ("bicycle", "steady turn 0.5 rad", _SCALED),
    ("tricycle", "steady turn 0.4 rad", _SCALED),
    ("tricycle", "figure eight", _SCALED),
    # omni3: speeds 1.2 times, the wheels a quarter of a roller pitch on (the phase whose
    # row change ripples the yaw rate most among the quarter pitches).
    ("omni3", "translate+rotate", {INPUT_SCALE: 1.2, WHEEL_PHASE: 0.2618}),
)


@pytest.mark.parametrize(("robot", "name", "draw"), EDGES, ids=lambda x: str(x))
def test_a_wide_family_judges_twenty_draws_and_its_edge_meets_the_target(robot, name, draw):
    spec = get_spec(robot)
    s = spec.scenario(name)
    assert s.family is not None and set(draw) <= {v.name for v in s.family.vary}
    result = run_batched(spec, [s.member(draw)], None, None)[0]
    assert result.error is None
    judged = [r for r in result.rows if r.passed is not None]
    worst = max(abs(r.value) / r.target for r in judged)
    assert worst > SMALL  # the spread is not small: 3 draws would not do
    assert s.family.draws >= DYNAMIC_DRAWS
    assert all(r.passed for r in judged), [(r.metric, r.value, r.target) for r in judged]
