"""Splitting a batch's members over devices and joining their results in member order."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TypeVar

T = TypeVar("T")


def split(members: int, shards: int) -> list[range]:
    """Contiguous member ranges, one per shard, sizes differing by at most one.

    The first ``members mod shards`` shards take one member more; shards beyond the
    member count are left out (no empty shard), so ``len(result) = min(members, shards)``.

    Raises:
        ValueError: ``members < 1`` or ``shards < 1``.
    """
    if members < 1 or shards < 1:
        raise ValueError(f"members = {members}, shards = {shards}; both must be >= 1")
    shards = min(shards, members)
    base, extra = divmod(members, shards)
    out, start = [], 0
    for s in range(shards):
        size = base + (s < extra)
        out.append(range(start, start + size))
        start += size
    return out


def join(parts: Sequence[Sequence[T]], ranges: Sequence[range]) -> list[T]:
    """The shards' per-member results back in member order.

    Raises:
        ValueError: a shard returned a different number of results than it had members,
            or the ranges do not tile ``0..members-1``.
    """
    if len(parts) != len(ranges):
        raise ValueError(f"{len(parts)} shard results for {len(ranges)} shards")
    members = sum(len(r) for r in ranges)
    out: list[T | None] = [None] * members
    for part, r in zip(parts, ranges, strict=True):
        if len(part) != len(r):
            raise ValueError(f"shard {r} returned {len(part)} results for {len(r)} members")
        for i, value in zip(r, part, strict=True):
            if out[i] is not None:
                raise ValueError(f"member {i} is in two shards")
            out[i] = value
    return out  # type: ignore[return-value]
