"""The batched path's reward is Python's ``sum`` of the terms, on any Python version."""

import sys

import numpy as np

from wmr_mujoco.envs.batched import COMPENSATED, total


def test_total_is_the_builtin_sum_of_each_worlds_terms():
    # The contract, on the Python that runs the tests: per world, exactly what the single
    # environment's ``sum(terms.values())`` gives (compensated from 3.12 on, plain
    # additions before), on terms of mixed magnitudes where the two differ in the last
    # bit for some worlds. The default branch is the one this Python takes.
    rng = np.random.default_rng(0)
    terms = {k: rng.normal(0, 1, 200) * 10.0 ** rng.integers(-8, 2, 200)
             for k in ("progress", "heading", "effort", "success", "failure")}
    rows = list(zip(*(v.tolist() for v in terms.values()), strict=True))
    assert total(terms).tolist() == [sum(r) for r in rows]
    assert COMPENSATED == (sys.version_info >= (3, 12))
