"""``wmr validate --seed/--draws/--quick``: checked before any work, passed to the runner."""

import pytest

from wmr_mujoco.cli import main
from wmr_mujoco.family_cli import QUICK_DRAWS
from wmr_mujoco.validation.family import DEFAULT_SEED, MAX_DRAWS


@pytest.mark.parametrize("args", [["--seed", "-1"], ["--seed", "abc"], ["--seed", "1.5"],
                                  ["--draws", "0"], ["--draws", str(MAX_DRAWS + 1)],
                                  ["--draws", "3", "--quick"]])
def test_a_bad_seed_or_draw_count_is_exit_2_before_any_work(tmp_path, capsys, args):
    out = tmp_path / "r"
    with pytest.raises(SystemExit) as exit_:
        main(["validate", "disc", "--out", str(out), *args])
    assert exit_.value.code == 2
    err = capsys.readouterr().err
    assert "--seed" in err or "--draws" in err or "--quick" in err
    assert not out.exists()


@pytest.mark.parametrize(("args", "seed", "draws"), [
    ([], DEFAULT_SEED, None), (["--seed", "12345678901234567890"], 12345678901234567890, None),
    (["--seed", "7", "--draws", "4"], 7, 4), (["--quick"], DEFAULT_SEED, QUICK_DRAWS)])
def test_seed_and_draws_reach_the_runner(tmp_path, monkeypatch, args, seed, draws):
    from wmr_mujoco.validation import members

    seen = []

    def fake(work, **kwargs):
        seen.append((kwargs["seed"], kwargs["draws"]))
        raise KeyboardInterrupt  # stop before any work

    monkeypatch.setattr(members, "run_families", fake)
    assert main(["validate", "disc", "--out", str(tmp_path / "r"), "-q", *args]) == 130
    assert seen == [(seed, draws)]
