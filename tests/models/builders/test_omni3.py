"""omni3's layout: three wheels at L, 120° apart, axles radial; rollers tangent, staggered."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.models.params import OmniParams


@pytest.fixture(scope="module")
def compiled():
    model = load("omni3")
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    return model, data


def test_wheels_sit_at_the_wheel_distance_with_radial_axles(compiled):
    model, data = compiled
    p = OmniParams()
    centre = data.xpos[model.body("platform").id]
    for i in range(3):
        offset = data.xpos[model.body(f"wheel{i + 1}").id] - centre
        angle = 2.0 * math.pi * i / 3.0
        radial = np.array([math.cos(angle), math.sin(angle), 0.0])
        np.testing.assert_allclose(offset, p.wheel_distance * radial, atol=1e-9)
        np.testing.assert_allclose(data.xaxis[model.joint(f"wheel{i + 1}").id], -radial,
                                   atol=1e-12)


def test_rollers_are_tangent_at_one_axis_distance_in_two_staggered_rows(compiled):
    model, data = compiled
    p = OmniParams()
    for i in range(1, 4):
        wheel = model.body(f"wheel{i}").id
        axle = data.xaxis[model.joint(f"wheel{i}").id]
        names = [model.joint(j).name for j in range(model.njnt)
                 if model.joint(j).name.startswith(f"wheel{i}_roller")]
        assert len(names) == 2 * p.rollers_per_row
        rows: dict[float, list[float]] = {}
        ref = None
        for name in names:
            j = model.joint(name).id
            arm = data.xanchor[j] - data.xpos[wheel]
            axial = float(arm @ axle)
            radial = arm - axial * axle
            axis = data.xaxis[j]
            assert abs(axis @ axle) < 1e-12 and abs(axis @ radial) < 1e-9
            ref = ref if ref is not None else np.linalg.norm(radial)
            assert np.linalg.norm(radial) == pytest.approx(ref, rel=1e-9)
            if not rows:
                basis = (radial / np.linalg.norm(radial), np.cross(axle, radial) /
                         np.linalg.norm(radial))
            rows.setdefault(round(axial, 9), []).append(
                math.atan2(radial @ basis[1], radial @ basis[0]))
        assert len(rows) == 2 and sum(rows) == pytest.approx(0.0, abs=1e-12)  # ±e
        pitch = 2.0 * math.pi / p.rollers_per_row
        a, b = (np.sort(np.mod(v, 2.0 * math.pi)) for v in rows.values())
        np.testing.assert_allclose(np.diff(a), pitch, atol=1e-9)
        np.testing.assert_allclose(np.diff(b), pitch, atol=1e-9)
        stagger = math.remainder(b[0] - a[0], pitch)
        assert abs(stagger) == pytest.approx(pitch / 2.0, abs=1e-9)
