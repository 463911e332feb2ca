"""The (2,1) sleigh's mass data from single_steer's parameters.

:func:`sleigh_inertia` reduces :class:`~wmr_mujoco.robots.single_steer.params.\
SingleSteerParams` to the :class:`~wmr_mujoco.robots.steered.analytic.SleighInertia`
that the steered family's Chaplygin-sleigh model integrates.
"""

from __future__ import annotations

import numpy as np

from wmr_mujoco.models.solids import box_inertia, fork_yaw_inertia
from wmr_mujoco.robots.single_steer.params import SingleSteerParams
from wmr_mujoco.robots.steered.analytic import SleighInertia


def sleigh_inertia(params: SingleSteerParams) -> SleighInertia:
    """Mass data of :class:`SingleSteerParams` (fork and wheel are point masses at P).

    ``M = m_ch + m_f + m_w + 2·(7/5) m_c``,  ``M c = m_ch c_ch + Σ (7/5) m_c p_c``,
    ``I_P = I_ch,zz + m_ch |c_ch|² + Σ (7/5) m_c |p_c|²``,
    ``I_f = I_fork,zz + m_w R²/4 + m_w w²/12`` (wheel diametral inertia).
    """
    p = params
    mb = p.caster.effective_mass
    balls = [np.array([p.caster_x, y]) for y in (p.caster_y, -p.caster_y)]
    ch = np.array([p.chassis_com_x, 0.0])
    mass = p.chassis_mass + p.fork_mass + p.wheel.mass + 2.0 * mb
    first = p.chassis_mass * ch + mb * sum(balls)
    inertia = (box_inertia(p.chassis_mass, p.chassis_size)[2] + p.chassis_mass * ch @ ch
               + mb * sum(b @ b for b in balls))
    fork = fork_yaw_inertia(p.fork_mass) + p.wheel.diametral_inertia
    return SleighInertia(float(mass), (float(first[0] / mass), float(first[1] / mass)),
                         float(inertia), float(fork))
