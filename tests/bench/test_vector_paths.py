"""The vector paths benchmark reports each loop and finds the crossover (no timing asserts)."""

import pytest

from wmr_mujoco.bench import vector_paths


def test_measure_reports_every_loop_at_every_size():
    modes = ["native", "sync", "serial", "batched"]
    r = vector_paths.measure("wmr/Disc-GoToGoal-v0", [1, 3], modes, seconds=0.05, repeats=1)
    assert set(r) == {(m, n) for m in modes for n in (1, 3)}
    assert all(v > 0 for v in r.values())
    text = vector_paths.table("wmr/Disc-GoToGoal-v0", r, [1, 3], modes)
    assert "| worlds | native / bare | sync / bare | serial / bare | batched / bare |" in text
    assert text.count("\n| ") == 3  # header and two sizes


def test_crossover_is_the_fewest_worlds_from_which_batched_stays_ahead():
    def ratios(serial, batched):
        return {**{("serial", n): v for n, v in zip((4, 8, 16), serial, strict=True)},
                **{("batched", n): v for n, v in zip((4, 8, 16), batched, strict=True)}}

    assert vector_paths.crossover(ratios((0.6, 0.6, 0.6), (0.5, 0.7, 0.8)), (4, 8, 16)) == 8
    # ahead at 4 but behind at 8: the crossover is where it stays ahead
    assert vector_paths.crossover(ratios((0.6, 0.6, 0.6), (0.7, 0.5, 0.8)), (4, 8, 16)) == 16
    assert vector_paths.crossover(ratios((0.6, 0.6, 0.6), (0.5, 0.5, 0.5)), (4, 8, 16)) is None


def test_bad_sizes_exit_2():
    with pytest.raises(SystemExit) as e:
        vector_paths.main(["wmr/Disc-GoToGoal-v0", "--sizes", "0,4"])
    assert e.value.code == 2


def test_crossing_lines_give_the_span_and_the_constant():
    text = vector_paths.crossing_lines({"a": 8, "b": 12, "c": None}, [4, 8, 12, 64])
    lines = text.splitlines()
    assert lines[:3] == ["a: batched >= serial from 8 worlds on",
                         "b: batched >= serial from 12 worlds on",
                         "c: batched slower than serial at 64 worlds"]
    assert lines[3] == (f"crossover over these 3 environments: 8 to 12 worlds (the latest: b; "
                        f"1 never); BATCHED_FROM = {vector_paths.BATCHED_FROM}")
