"""``wmr demo``: each robot's line states what its run did (path, end pose, errors)."""

import dataclasses
import math

import numpy as np

from wmr_mujoco import demo
from wmr_mujoco.robots import get_spec
from wmr_mujoco.validation.runner import run_scenario


def test_the_line_reports_the_run(monkeypatch):
    spec = get_spec("disc")
    monkeypatch.setattr(demo, "ROBOTS", {"disc": spec})
    lines = demo.run_demo().splitlines()
    assert len(lines) == 2 and lines[0].startswith("robot")
    sim = run_scenario(spec, spec.scenario(spec.demo_scenario)).trace.arrays()["sim"]
    path = float(np.sum(np.hypot(*np.diff(sim[:, :2], axis=0).T)))
    x, y, heading = sim[-1, :3]
    fields = lines[1].replace(",", " ").replace("°", " ").replace("%", " ").split()
    name_words = len(spec.demo_scenario.split())
    numbers = [float(f) for f in fields[1 + name_words:]]
    assert fields[0] == "disc"
    assert numbers[0] == round(path, 3)
    assert numbers[1:3] == [round(x, 3), round(y, 3)]
    assert numbers[3] == round(math.degrees(heading), 1)
    assert 0.0 <= numbers[5] <= numbers[4]  # the final error is never above the worst


def test_a_failed_run_is_shown_not_raised(monkeypatch):
    from wmr_mujoco.validation import runner

    spec = get_spec("disc")
    monkeypatch.setattr(demo, "ROBOTS", {"disc": spec})
    real = runner.run_scenario

    def failing(spec, scenario):
        return dataclasses.replace(real(spec, scenario), error="diverged at t=0.1 s")

    monkeypatch.setattr(demo, "run_scenario", failing)
    assert "failed: diverged at t=0.1 s" in demo.run_demo()
