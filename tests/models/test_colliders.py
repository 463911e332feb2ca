"""Colliders by contact bits or by explicit pairs."""

import mujoco
import pytest

from wmr_mujoco.models.colliders import colliders, is_collider, pair_geoms, pair_with

XML = """<mujoco><worldbody>
  <geom name="floor" type="plane" size="1 1 .1"/>
  <body pos="0 0 1"><freejoint/>
    <geom name="bits" type="sphere" size=".1" contype="0" conaffinity="1"/>
    <geom name="paired" type="sphere" size=".1" pos=".3 0 0" contype="0" conaffinity="0"/>
    <geom name="visual" type="sphere" size=".1" pos=".6 0 0" contype="0" conaffinity="0"
      density="0"/>
  </body></worldbody>
  <contact><pair geom1="paired" geom2="floor"/></contact></mujoco>"""


@pytest.fixture(scope="module")
def model():
    return mujoco.MjModel.from_xml_string(XML)


def test_bits_or_a_pair_make_a_collider(model):
    ids = {n: model.geom(n).id for n in ("floor", "bits", "paired", "visual")}
    assert pair_geoms(model) == {ids["floor"], ids["paired"]}
    assert colliders(model) == sorted([ids["floor"], ids["bits"], ids["paired"]])
    assert not is_collider(model, ids["visual"])
    assert pair_with(model, ids["floor"], ids["paired"]) == 0  # either order
    assert pair_with(model, ids["bits"], ids["floor"]) is None


def test_the_pair_makes_the_contact_the_helpers_report(model):
    # The physics agrees: dropped on the floor, the paired sphere touches it and the
    # non-collider never does (the bits sphere touches it too: floor contype 1).
    data = mujoco.MjData(model)
    for _ in range(2000):
        mujoco.mj_step(model, data)
    touching = {int(c.geom[i]) for c in data.contact[:data.ncon] for i in (0, 1)}
    assert model.geom("paired").id in touching and model.geom("bits").id in touching
    assert model.geom("visual").id not in touching
