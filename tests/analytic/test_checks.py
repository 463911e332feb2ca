"""The analytic layer's argument checks: each names the argument and what is valid."""

import numpy as np
import pytest

from wmr_mujoco.analytic.checks import as_array, non_negative, positive


def test_as_array_accepts_any_length_where_asked():
    out = as_array("t", [0.0, 1.0, 2.5], (None,))
    assert out.dtype == np.float64 and out.shape == (3,)
    fast = np.array([[1.0, 2.0]])
    assert as_array("m", fast, (1, 2)) is fast  # the fast path returns the array itself


@pytest.mark.parametrize("value, shape, match", [
    ([1.0, 2.0], (3,), r"q must have shape \(3,\), got \(2,\)"),
    ([[1.0, 2.0]], (None, 3), r"q must have shape \(N, 3\), got \(1, 2\)"),
    ([1.0, np.inf, 0.0], (3,), "q contains non-finite values"),
    (np.array([np.nan, 0.0, 0.0]), (3,), "q contains non-finite values"),
])
def test_as_array_refuses_with_the_name(value, shape, match):
    with pytest.raises(ValueError, match=match):
        as_array("q", value, shape)


@pytest.mark.parametrize("check, ok, bad", [
    (positive, 1e-9, [0.0, -1.0, float("inf"), float("nan"), "1"]),
    (non_negative, 0.0, [-1e-12, float("nan"), None]),
])
def test_scalar_checks(check, ok, bad):
    assert check("x", ok) == ok
    for value in bad:
        with pytest.raises(ValueError, match=r"^x = "):
            check("x", value)


def test_as_array_small_fast_path_tells_overflow_from_non_finite():
    # A small array's finiteness is read from its Python sum: a sum that overflows to inf
    # (finite entries) must still pass, and a NaN or an inf anywhere must still be named.
    big = np.array([1e308, 1e308, -0.0])
    assert as_array("w", big, (3,)) is big
    for bad in ([1e308, np.inf, 0.0], [np.inf, -np.inf, 1.0], [0.0, 0.0, np.nan]):
        with pytest.raises(ValueError, match="w contains non-finite values"):
            as_array("w", np.array(bad), (3,))
