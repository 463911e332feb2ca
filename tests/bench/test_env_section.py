"""The learning environments' section of ``wmr bench``."""

import builtins

import wmr_mujoco
from wmr_mujoco.bench import env_section, env_success


def test_section_has_both_tables(monkeypatch):
    import wmr_mujoco.envs as wenvs

    monkeypatch.setattr(wenvs, "ENV_IDS", ("wmr/Disc-GoToGoal-v0",))
    monkeypatch.setattr(env_success, "success_rate", lambda i, n, s: {
        "successes": n, "episodes": n, "failed": [], "seconds": 0.1})
    results, text = env_section.env_section(quick=True)
    assert set(results) == {"success", "throughput"}
    assert "worst success rate 100.0 % (goal >= 95 %)" in text
    assert "| wmr/Disc-GoToGoal-v0 | 10/10 |" in text
    skip = round(0.02 / wmr_mujoco.load("disc").opt.timestep)  # the 20 ms control period
    assert f"| wmr/Disc-GoToGoal-v0 | {skip} |" in text  # the throughput row, its frame skip


def test_without_gymnasium_the_section_is_left_out(monkeypatch):
    real = builtins.__import__

    def no_gym(name, *args, **kwargs):
        if name == "gymnasium":
            raise ModuleNotFoundError("No module named 'gymnasium'")
        return real(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_gym)
    results, text = env_section.env_section(quick=True)
    assert results is None and text.startswith("Left out: Gymnasium is not installed")
