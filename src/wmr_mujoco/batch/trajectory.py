""":class:`BatchTrajectory`: many members' trajectories on one time grid, member first."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr_mujoco.api import NamedStates, Trajectory


@dataclass(frozen=True)
class BatchTrajectory(NamedStates):
    """States of every member at every physics step, the start included.

    Attributes:
        time: ``(N + 1,)`` seconds after the settle, shared by all members.
        states: ``(members, N + 1, n)`` the analytic state's quantities (``state_names``).
        inputs: ``(members, N, m)`` the input held over each step.
        state_names: e.g. ``("x", "y", "heading")``.
        state_units: e.g. ``("m", "m", "rad")``.
        backend: the engine that produced it (``"rollout"`` or ``"warp"``).
    """

    time: np.ndarray
    states: np.ndarray
    inputs: np.ndarray
    state_names: tuple[str, ...]
    state_units: tuple[str, ...]
    backend: str

    def __len__(self) -> int:
        """The number of members."""
        return len(self.states)

    def member(self, i: int) -> Trajectory:
        """Member ``i`` as the :class:`~wmr_mujoco.api.Trajectory` ``wmr.simulate`` returns.

        Raises:
            IndexError: ``i`` is not in ``[-members, members)``.
        """
        if not -len(self) <= i < len(self):
            raise IndexError(f"member {i}; valid members are 0..{len(self) - 1}")
        return Trajectory(self.time, self.states[i], self.inputs[i], self.state_names,
                          self.state_units)
