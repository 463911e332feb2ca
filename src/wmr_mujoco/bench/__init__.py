"""Benchmarks (``wmr bench``), the omni trials and the omni roller design study."""
