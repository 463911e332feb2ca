"""The viewer's loop, with a stand-in for MuJoCo's window (no display needed)."""

import contextlib

import numpy as np

from wmr_mujoco.render import viewer


class FakeHandle:
    """Runs for ``frames`` syncs, recording the viewer's data at each."""

    def __init__(self, data, frames):
        self.data, self.left, self.seen = data, frames, []

    def is_running(self):
        return self.left > 0

    def sync(self):
        self.left -= 1
        self.seen.append((self.data.time, self.data.qpos.copy()))


def test_a_measurement_plays_its_film_into_the_viewer(monkeypatch):
    handles = []

    @contextlib.contextmanager
    def launch_passive(model, data):
        handles.append(FakeHandle(data, 300))
        yield handles[-1]

    monkeypatch.setattr(viewer.mujoco.viewer, "launch_passive", launch_passive)
    monkeypatch.setattr(viewer.time, "sleep", lambda s: None)
    viewer.view("disc_free", "steady precession")
    seen = handles[0].seen
    times = np.array([t for t, _ in seen])
    assert len(seen) == 300 and np.all(np.diff(times) > 0)
    # The disc moves: the free joint's position changes between the first and last frame.
    assert np.linalg.norm(seen[-1][1][:2] - seen[0][1][:2]) > 0.1
