"""The textbook models: kinematics, non-holonomic constraints and dynamics.

Conventions (all modules): world frame x, y on the floor, z up; angles in radians,
counter-clockwise positive about z; a wheel rate θ̇ > 0 rolls the wheel forward along its
heading. Symbols follow ``docs/analytical.md``.
"""
