"""examples/train_ppo_diffdrive.py: its arguments are checked before any work, without torch.

The example itself (a PPO run of minutes) is outside the test suite by design; what is
tested is that ``--help`` and a bad argument answer at once, naming the bad value and the
valid range, before ``torch`` is imported: ``torch`` is made unimportable here, so the
test runs (and cannot be skipped) whether or not torch is installed.
"""

import importlib.util
import sys
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[2] / "examples" / "train_ppo_diffdrive.py"


@pytest.fixture
def example(monkeypatch: pytest.MonkeyPatch):
    """The example as a module, with ``import torch`` raising ImportError."""
    monkeypatch.setitem(sys.modules, "torch", None)
    spec = importlib.util.spec_from_file_location("train_ppo_diffdrive", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_help_lists_every_range(example, capsys) -> None:
    with pytest.raises(SystemExit) as exit_:
        example.main(["--help"])
    assert exit_.value.code == 0
    out = capsys.readouterr().out
    for name, kind, _, lo, hi in example.ARGS:
        assert f"--{name.replace('_', '-')}" in out
        assert f"{kind.__name__} in [{lo}, {hi}]" in out


@pytest.mark.parametrize(("argv", "named", "valid"), [
    (["--steps", "5"], "--steps=5", "valid: 1000 to 10000000"),
    (["--envs", "0"], "--envs=0", "valid: 1 to 256"),
    (["--envs", "100000"], "--envs=100000", "valid: 1 to 256"),
    (["--gamma", "nan"], "--gamma=nan", "valid: 0.0 to 0.9999"),
    (["--lr", "inf"], "--lr=inf", "valid: 1e-06 to 0.1"),
    (["--eval-episodes", "0"], "--eval-episodes=0", "valid: 1 to 256"),
    (["--final-std", "0"], "--final-std=0.0", "valid: 0.01 to 0.6"),
    (["--seed", "999999"], "--seed=999999", "valid: 0 to 999743"),
    (["--envs", "2", "--horizon", "16", "--batch", "64"], "--batch=64", "valid: 16 to 32"),
    (["--out", "curve.jpg"], "--out='curve.jpg'", "a path ending in .png"),
])
def test_bad_argument_named_with_its_range(example, capsys, argv, named, valid) -> None:
    with pytest.raises(SystemExit) as exit_:  # before torch: importing it would raise
        example.main(argv)
    assert exit_.value.code == 2
    err = capsys.readouterr().err
    assert named in err and valid in err, err


def test_eval_seeds_disjoint_from_training(example) -> None:
    """Training worlds are seeded ``--seed + i`` (i < --envs); evaluation from EVAL_SEED."""
    highest_seed = next(hi for name, _, _, _, hi in example.ARGS if name == "seed")
    most_envs = next(hi for name, _, _, _, hi in example.ARGS if name == "envs")
    assert highest_seed + most_envs - 1 < example.EVAL_SEED
