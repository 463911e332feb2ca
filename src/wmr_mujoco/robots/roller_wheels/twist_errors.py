"""Twist errors of the roller-wheel robots' torque runs, with jumps allowed to land late.

The body twist of a robot on rollers jumps as contact passes from roller to roller;
:func:`twist_metrics` judges a model's twist against the physics' with those jumps allowed
to land up to a few samples apart (:func:`event_aligned_error`).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from wmr_mujoco.validation.metrics import Metric, Target, rms


def event_aligned_error(ref: np.ndarray, other: np.ndarray, shift: int,
                        scale: Sequence[float] | np.ndarray | None = None) -> np.ndarray:
    """Per-sample error of two sampled traces whose jumps may land ``shift`` samples apart.

    The (τ, ε)-closeness of hybrid traces (H. Abbas, H. Mittelmann, G. Fainekos,
    "Formal property verification in a conformance testing framework", MEMOCODE 2014),
    on a common grid with τ = ``shift`` samples (s): each sample of either trace is
    matched with the nearest sample of the other within s, one match for all its
    components (the trace is retimed as a whole),

        j*_k = argmin_{|j| ≤ s} max_c |x_{k,c} − y_{k+j,c}| / σ_c,
        e_k  = max( |x_k − y_{k+j*_k}|,  |y_k − x_{k+j'*_k}| )   (per component),

    ``j'*`` the same match from y to x, indices clipped to the run, σ_c ``scale``; ``max_k
    e_k ≤ ε`` exactly when each trace is (τ, ε)-close to the other. It relaxes the
    Skorokhod distance (J. Deshmukh, R. Majumdar, V. Prabhu, CAV 2015) with its retiming
    bounded by τ: the matches need not be monotone. ``s = 0`` is the pointwise
    ``|x_k − y_k|``. A jump of either trace that the other makes within s samples adds
    nothing; one made later, or of another size, adds its full mismatch. Along a smooth
    stretch ``e_k`` is below the pointwise error by at most ``s · max |x_{k+1} − x_k|``.

    Args:
        ref: (N,) or (N, m) samples x_k.
        other: y_k, the same shape and grid.
        shift: s ≥ 0, samples.
        scale: (m,) σ_c > 0 weighing the components when choosing a match (None: 1).

    Raises:
        ValueError: a negative or non-integer shift, arrays of different shapes, or a
            non-positive scale.
    """
    if isinstance(shift, bool) or not isinstance(shift, int | np.integer) or shift < 0:
        raise ValueError(f"shift = {shift!r}; give a whole number of samples ≥ 0")
    x, y = np.asarray(ref, float), np.asarray(other, float)
    if x.shape != y.shape or x.ndim not in (1, 2) or not len(x):
        raise ValueError(f"ref {x.shape} and other {y.shape} must be the same (N,) or "
                         "(N, m) shape, N ≥ 1")
    flat = x.ndim == 1
    if flat:
        x, y = x[:, None], y[:, None]
    sigma = np.ones(x.shape[1]) if scale is None else np.asarray(scale, float)
    if sigma.shape != (x.shape[1],) or not np.all(np.isfinite(sigma) & (sigma > 0)):
        raise ValueError(f"scale = {scale!r}; give {x.shape[1]} positive numbers")
    n = len(x)
    rows = np.arange(n)

    def matched(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        offsets = np.arange(-shift, shift + 1)
        idx = np.clip(rows[:, None] + offsets[None, :], 0, n - 1)  # (N, 2s + 1)
        diff = np.abs(a[:, None, :] - b[idx])  # (N, 2s + 1, m)
        best = np.argmin(np.max(diff / sigma, axis=2), axis=1)
        return diff[rows, best]

    err = np.maximum(matched(x, y), matched(y, x))
    return err[:, 0] if flat else err


def twist_metrics(model: str, ref: np.ndarray, other: np.ndarray, distance: float,
                  targets: dict[str, Target | None] | None = None,
                  shift: int = 0) -> list[Metric]:
    """Worst error of u, v (m/s) and r (rad/s), each in % of its scale, and RMS.

    ``ref`` and ``other``: body twists ``(u, v, r)`` over the run, shape (N, 3). Scales,
    with ``L`` = ``distance`` the lever of ``r`` at the wheels: u and v,
    ``max(peak |(u, v)|, L · peak |r|)``; r, that over L (a component that stays zero is
    judged against the speed the run's motion gives the wheels). Each worst error is
    judged against ``targets[name]`` where given.

    ``shift`` > 0: the worst errors are :func:`event_aligned_error` with jumps allowed
    ``shift`` samples apart (a hybrid model's events against a time-stepping simulator's,
    which resolves an event only to its step; one match per sample for the whole twist,
    components weighed by their scales), and the pointwise worst error of each component
    is reported beside (``worst u error, sample by sample``). RMS errors are pointwise.
    """
    targets = targets or {}
    speed = float(np.max(np.linalg.norm(ref[:, :2], axis=1)))
    peak_r = float(np.max(np.abs(ref[:, 2])))
    lin = max(speed, distance * peak_r, 1e-9)
    scales = (lin, lin, lin / distance)
    aligned = event_aligned_error(ref, other, shift, scales)
    out = []
    for j, (name, unit, scale) in enumerate(zip(("u", "v", "r"), ("m/s", "m/s", "rad/s"),
                                                scales, strict=True)):
        err = aligned[:, j]
        point = np.abs(other[:, j] - ref[:, j])
        what = (f"(τ, ε)-closeness error, jumps up to {shift} sample"
                f"{'s' if shift > 1 else ''} apart" if shift else f"|{name} − {name}_{model}|")
        note = f"max {what} = {err.max():.3g} {unit}; scale {scale:.3g} {unit}"
        out += [Metric(f"{model}: worst {name} error", 100 * float(err.max()) / scale,
                       "% of peak", targets.get(name), note),
                Metric(f"{model}: RMS {name} error", rms(point), unit)]
        if shift:
            out.append(Metric(f"{model}: worst {name} error, sample by sample",
                              100 * float(point.max()) / scale, "% of peak",
                              note="the same samples compared at the same instant: a "
                                   "jump landing one sample apart counts whole"))
    return out
