"""Stepping with divergence checks, the batched rollout engine, timing and thread scaling."""
