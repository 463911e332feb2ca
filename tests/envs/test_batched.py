"""The batched path's reward is Python's ``sum`` of the terms, on any Python version."""

import numpy as np
import pytest

from wmr_mujoco.envs.batched import total


@pytest.mark.parametrize("compensated", [False, True])
def test_total_is_the_builtin_sum_of_each_worlds_terms(compensated):
    # Terms of mixed magnitudes, where a compensated sum (Python >= 3.12) and plain
    # additions differ in the last bit for some worlds: the compensated branch must give
    # sum() itself; the plain branch is sum() where sum adds plainly (Python < 3.12).
    rng = np.random.default_rng(0)
    terms = {k: rng.normal(0, 1, 200) * 10.0 ** rng.integers(-8, 2, 200)
             for k in ("progress", "heading", "effort", "success", "failure")}
    rows = list(zip(*(v.tolist() for v in terms.values()), strict=True))
    if compensated:
        assert total(terms, True).tolist() == [sum(r) for r in rows]
    else:
        plain = []
        for r in rows:
            acc = 0
            for v in r:
                acc = acc + v
            plain.append(acc)
        assert total(terms, False).tolist() == plain
