"""A plot per dynamic omni scenario: the physics over the kinematic and dynamic predictions.

``python -m wmr_mujoco.omni_dynamic_plots OUTDIR`` runs every scenario of
:mod:`wmr_mujoco.omni_dynamic_scenarios` and writes one PNG each.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from wmr_mujoco.omni_dynamic_scenarios import ScenarioResult, all_scenarios

MODELS = (("physics", "k", "-"), ("kinematic", "tab:blue", ":"),
          ("dynamic", "tab:red", "--"), ("lagrange", "tab:green", "-."))
COMPONENTS = (("u", "m/s"), ("v", "m/s"), ("r", "rad/s"))


def plot_scenario(result: ScenarioResult, path: Path) -> Path:
    """Twist components (each in its own unit) and the path, every model present.

    Raises:
        ValueError: the result carries no physics twist series (e.g. the slip bisection).
    """
    series = result.series
    if "physics_twist" not in series or "t" not in series:
        raise ValueError(f"scenario {result.name!r} has no time series of the physics twist")
    t = series["t"]
    fig, axes = plt.subplots(1, 4, figsize=(16, 3.6))
    for j, (name, unit) in enumerate(COMPONENTS):
        for model, colour, style in MODELS:
            if f"{model}_twist" in series:
                axes[j].plot(t, series[f"{model}_twist"][:, j], color=colour, ls=style,
                             label=model)
        axes[j].set(xlabel="t [s]", ylabel=f"{name} [{unit}]")
    for model, colour, style in MODELS:
        if f"{model}_pose" in series:
            pose = series[f"{model}_pose"]
            axes[3].plot(pose[:, 0], pose[:, 1], color=colour, ls=style, label=model)
    axes[3].set(xlabel="x [m]", ylabel="y [m]", aspect="equal")
    axes[0].legend(fontsize=8)
    fig.suptitle(result.name)
    fig.tight_layout()
    path = Path(path)
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path


def main(argv: list[str] | None = None) -> None:  # pragma: no cover - a few minutes
    """Write a PNG per scenario into the directory given as the first argument."""
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        raise SystemExit("usage: python -m wmr_mujoco.omni_dynamic_plots OUTDIR")
    out = Path(args[0])
    out.mkdir(parents=True, exist_ok=True)
    for res in all_scenarios():
        if "physics_twist" in res.series:
            name = re.sub(r"[^A-Za-z0-9]+", "_", res.name).strip("_")
            print(plot_scenario(res, out / f"{name}.png"))


if __name__ == "__main__":  # pragma: no cover
    main()
