"""A short PPO run on ``wmr/DiffDrive-GoToGoal-v0``: an example, not part of the test suite.

    nice -n 5 python examples/train_ppo_diffdrive.py --steps 250000 \
        --out docs/img/ppo_diffdrive.png

The learning curve is an evaluation, not the training episodes: every ``--eval-every``
environment steps (and before the first update) the current policy drives a FIXED set of
``--eval-episodes`` episodes, seeded ``EVAL_SEED + i`` (disjoint from the training seeds
``--seed + i``, ``--seed`` < ``EVAL_SEED - 256``), deterministically (the policy's mean
action), each to its end (goal reached, robot out of the arena, or the 20 s time limit).
The curve is their success rate and mean return (the sum of the reward's terms) against
environment steps. The success rate of the training episodes that finish within an update
is drawn too, for comparison only: it is biased towards success (a successful episode ends
early, a failing one runs to the time limit, so a window's finished episodes over-represent
successes) and noisy (a few episodes per update).

Writes the figure to ``--out`` (title: the command, wall and CPU time, cores, the final
success rate) and its points to ``--out`` with ``.json`` (steps, success rate, mean return,
wall and CPU seconds at each evaluation; the command; the settings; package versions),
both atomically. Needs ``torch`` (``pip install torch``) and the ``rl`` extra (gymnasium);
the arguments are checked before either is imported.

PPO (Schulman et al. 2017): clipped surrogate (ε = 0.2), GAE(λ), a Gaussian policy with a
state-independent log standard deviation, observations normalised by their running mean
and variance, rewards divided by the running standard deviation of the discounted return
(the value targets stay of order one whatever the reward's scale), the learning rate
annealed linearly to zero, a value bootstrap at the time limit (a truncated episode is not
a terminal state), actions clipped to [-1, 1] by the environment. The policy's standard
deviation is capped by a ceiling that falls geometrically from its initial ``e^-0.5 = 0.61``
to ``--final-std`` at the last update: PPO maximises the return of the noisy policy, whose
mean need not succeed on its own (without the ceiling, ``--seed 1``'s std stayed near its
start and its mean action failed on many evaluation episodes while its training episodes
all succeeded); with the noise shrinking, the policy that is optimised converges to the
one that is evaluated.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shlex
import sys
import time
from importlib import metadata
from pathlib import Path
from typing import Any

import numpy as np

from wmr_mujoco.atomic import atomic_path, write_text_atomic

ENV_ID = "wmr/DiffDrive-GoToGoal-v0"
#: First seed of the evaluation episodes (episode i: ``EVAL_SEED + i``).
EVAL_SEED = 1_000_000
#: The policy's initial log standard deviation (std 0.61 of the action range [-1, 1]).
LOG_STD0 = -0.5
#: Most worlds in one vector environment (:data:`wmr_mujoco.envs.vector.MAX_ENVS`).
MAX_ENVS = 256

#: ``(flag, type, default, low, high)``: each argument's valid range, checked before any work.
ARGS: tuple[tuple[str, type, Any, float, float], ...] = (
    ("steps", int, 250_000, 1_000, 10_000_000),
    ("envs", int, 8, 1, MAX_ENVS),
    ("horizon", int, 256, 16, 4096),
    ("epochs", int, 10, 1, 100),
    ("batch", int, 256, 16, 65_536),
    ("lr", float, 3e-4, 1e-6, 1e-1),
    ("gamma", float, 0.99, 0.0, 0.9999),
    ("lam", float, 0.95, 0.0, 1.0),
    ("final_std", float, 0.1, 0.01, 0.6),
    ("eval_every", int, 10_000, 1_000, 10_000_000),
    ("eval_episodes", int, 50, 1, MAX_ENVS),
    ("seed", int, 0, 0, EVAL_SEED - MAX_ENVS - 1),
)


def parse(argv: list[str] | None) -> argparse.Namespace:
    """The arguments; a bad one exits (code 2) naming its value and the valid range."""
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    for name, kind, default, lo, hi in ARGS:
        p.add_argument("--" + name.replace("_", "-"), type=kind, default=default,
                       help=f"{kind.__name__} in [{lo}, {hi}] (default {default})")
    p.add_argument("--out", default="docs/img/ppo_diffdrive.png",
                   help="the figure (.png); its points go beside it (.json)")
    args = p.parse_args(argv)
    for name, _, _, lo, hi in ARGS:
        value = getattr(args, name)
        if not lo <= value <= hi:  # NaN fails too
            p.error(f"--{name.replace('_', '-')}={value!r}; valid: {lo} to {hi}")
    if args.batch > args.envs * args.horizon:
        p.error(f"--batch={args.batch} exceeds the {args.envs * args.horizon} samples of an "
                f"update (--envs x --horizon); valid: 16 to {args.envs * args.horizon}")
    if Path(args.out).suffix != ".png":
        p.error(f"--out={args.out!r}; valid: a path ending in .png")
    return args


class RunningStat:
    """Running mean and variance of batches of vectors (Chan et al.'s parallel update)."""

    def __init__(self, size: int) -> None:
        self.mean, self.var, self.count = np.zeros(size), np.ones(size), 1e-4

    def update(self, x: np.ndarray) -> None:
        """Fold a batch ``x`` (N, size) in: ``M₂ = M₂ₐ + M₂ᵦ + δ² nₐ nᵦ / n``."""
        m, v, n = x.mean(0), x.var(0), len(x)
        delta, total = m - self.mean, self.count + n
        self.mean = self.mean + delta * n / total
        self.var = (self.var * self.count + v * n + delta**2 * self.count * n / total) / total
        self.count = total

    def normalize(self, x: np.ndarray) -> np.ndarray:
        """``(x − mean) / √(var + 10⁻⁸)`` clipped to ±10."""
        return np.clip((x - self.mean) / np.sqrt(self.var + 1e-8), -10, 10)


def build(n_obs: int, n_act: int, hidden: int = 64) -> Any:
    """Two tanh MLPs (the policy's mean, the value) and a state-independent log std."""
    import torch
    from torch import nn

    def mlp(out: int, gain: float) -> nn.Sequential:
        layers = [nn.Linear(n_obs, hidden), nn.Tanh(), nn.Linear(hidden, hidden), nn.Tanh(),
                  nn.Linear(hidden, out)]
        for layer, g in zip(layers[::2], (2**0.5, 2**0.5, gain), strict=True):
            nn.init.orthogonal_(layer.weight, g)  # the initialisation of Schulman's baselines
            nn.init.zeros_(layer.bias)
        return nn.Sequential(*layers)

    net = nn.Module()
    net.pi, net.v = mlp(n_act, 0.01), mlp(1, 1.0)  # small first actions: near-zero mean
    net.log_std = nn.Parameter(LOG_STD0 * torch.ones(n_act))
    return net


def evaluate(envs: Any, net: Any, norm: RunningStat) -> tuple[float, float]:
    """Success rate and mean return of the fixed evaluation episodes (module docstring).

    ``envs``: one world per episode (``NEXT_STEP`` autoreset: a world that ended keeps
    stepping a new episode, which is ignored).
    """
    import torch

    n = envs.num_envs
    obs, _ = envs.reset(seed=[EVAL_SEED + i for i in range(n)])
    alive, ret, success = np.ones(n, bool), np.zeros(n), np.zeros(n, bool)
    while alive.any():
        with torch.no_grad():
            a = net.pi(torch.as_tensor(norm.normalize(obs), dtype=torch.float32))
        obs, r, term, trunc, info = envs.step(a.numpy())
        ret += np.where(alive, r, 0.0)
        done = (term | trunc) & alive
        success |= done & info.get("is_success", np.zeros(n, bool))
        alive &= ~done
    return float(success.mean()), float(ret.mean())


def train(args: argparse.Namespace) -> dict[str, Any]:
    """Run PPO with periodic evaluations; return the curve (lists keyed by name)."""
    import gymnasium as gym
    import torch
    from torch import nn

    import wmr_mujoco.envs  # noqa: F401  (registers wmr/...)

    torch.manual_seed(args.seed)
    t0, c0 = time.perf_counter(), time.process_time()
    envs = gym.make_vec(ENV_ID, num_envs=args.envs,
                        autoreset_mode=gym.vector.AutoresetMode.SAME_STEP)
    evals = gym.make_vec(ENV_ID, num_envs=args.eval_episodes)
    obs, _ = envs.reset(seed=args.seed)
    n_obs, n_act = envs.single_observation_space.shape[0], envs.single_action_space.shape[0]
    net = build(n_obs, n_act)
    opt = torch.optim.Adam(net.parameters(), lr=args.lr, eps=1e-5)
    norm, rstat = RunningStat(n_obs), RunningStat(1)
    disc = np.zeros(args.envs)  # each world's discounted return so far (reward scaling)
    curve: dict[str, list] = {k: [] for k in ("steps", "success", "return", "policy_std",
                                              "wall_s", "cpu_s", "train_steps",
                                              "train_success")}
    finished: list[bool] = []
    per_update = args.envs * args.horizon
    updates = -(-args.steps // per_update)

    def point(steps: int) -> None:
        s, r = evaluate(evals, net, norm)
        for k, v in zip(("steps", "success", "return"), (steps, s, r), strict=True):
            curve[k].append(v)
        curve["policy_std"].append(round(float(net.log_std.detach().exp().mean()), 4))
        curve["wall_s"].append(round(time.perf_counter() - t0, 1))
        curve["cpu_s"].append(round(time.process_time() - c0, 1))
        print(f"steps {steps:8d}  eval success {s:.2f}  return {r:6.2f}  "
              f"std {curve['policy_std'][-1]:.3f}  {curve['wall_s'][-1]:6.0f} s", flush=True)

    point(0)
    steps = 0
    for update in range(updates):
        progress = update / updates
        for g in opt.param_groups:  # linear annealing to zero at the last update
            g["lr"] = args.lr * (1.0 - progress)
        with torch.no_grad():  # the std's ceiling: geometric from e^LOG_STD0 to --final-std
            net.log_std.clamp_(max=LOG_STD0 + (np.log(args.final_std) - LOG_STD0) * progress)
        buf_o, buf_a, buf_lp, buf_r, buf_d, buf_v = [], [], [], [], [], []
        for _ in range(args.horizon):
            norm.update(obs)
            o = torch.as_tensor(norm.normalize(obs), dtype=torch.float32)
            with torch.no_grad():
                d = torch.distributions.Normal(net.pi(o), net.log_std.exp())
                a = d.sample()
                lp, v = d.log_prob(a).sum(-1), net.v(o).squeeze(-1)
            obs, r, term, trunc, info = envs.step(a.numpy())
            done = term | trunc
            disc = disc * args.gamma + r
            rstat.update(disc[:, None])
            disc[done] = 0.0
            r = r / np.sqrt(rstat.var[0] + 1e-8)
            if done.any():  # same-step autoreset: the ended episodes' last info and obs
                final = info["final_info"]
                finished += [bool(s) for s, dn in zip(final["is_success"], done, strict=True)
                             if dn]
                if trunc.any():  # bootstrap the value at the time limit
                    with torch.no_grad():
                        last = norm.normalize(np.stack(info["final_obs"][trunc]))
                        fv = net.v(torch.as_tensor(last, dtype=torch.float32)).squeeze(-1)
                    r[trunc] += args.gamma * fv.numpy()
            buf_o.append(o), buf_a.append(a), buf_lp.append(lp), buf_v.append(v)
            buf_r.append(torch.as_tensor(r, dtype=torch.float32))
            buf_d.append(torch.as_tensor(done, dtype=torch.float32))
        steps += per_update
        with torch.no_grad():
            next_v = net.v(torch.as_tensor(norm.normalize(obs),
                                           dtype=torch.float32)).squeeze(-1)
        adv, gae = torch.zeros(args.horizon, args.envs), torch.zeros(args.envs)
        for t in reversed(range(args.horizon)):  # GAE(λ); a done step does not look ahead
            nxt = next_v if t == args.horizon - 1 else buf_v[t + 1]
            delta = buf_r[t] + args.gamma * nxt * (1 - buf_d[t]) - buf_v[t]
            gae = delta + args.gamma * args.lam * (1 - buf_d[t]) * gae
            adv[t] = gae
        ret = adv + torch.stack(buf_v)
        o, a = torch.cat(buf_o), torch.cat(buf_a)
        lp_old, adv, ret = torch.cat(buf_lp), adv.flatten(), ret.flatten()
        adv = (adv - adv.mean()) / (adv.std() + 1e-8)
        for _ in range(args.epochs):
            for idx in torch.randperm(len(o)).split(args.batch):
                d = torch.distributions.Normal(net.pi(o[idx]), net.log_std.exp())
                ratio = (d.log_prob(a[idx]).sum(-1) - lp_old[idx]).exp()
                surr = torch.min(ratio * adv[idx], ratio.clamp(0.8, 1.2) * adv[idx])
                loss = -surr.mean() + 0.5 * (net.v(o[idx]).squeeze(-1) - ret[idx]).pow(2).mean()
                opt.zero_grad()
                loss.backward()
                nn.utils.clip_grad_norm_(net.parameters(), 0.5)
                opt.step()
        if finished:
            curve["train_steps"].append(steps)
            curve["train_success"].append(float(np.mean(finished)))
            finished = []
        if steps // args.eval_every > (steps - per_update) // args.eval_every or \
                update == updates - 1:
            point(steps)
    envs.close()
    evals.close()
    return curve


def versions() -> dict[str, str]:
    """The versions of Python and of the packages the run used."""
    out = {"python": platform.python_version()}
    for pkg in ("wmr-mujoco", "mujoco", "numpy", "torch", "gymnasium", "matplotlib"):
        try:
            out[pkg] = metadata.version(pkg)
        except metadata.PackageNotFoundError:
            out[pkg] = "not installed"
    return out


def plot(curve: dict[str, Any], record: dict[str, Any], out: str) -> None:
    """The evaluation's success rate and mean return against environment steps."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    n = record["eval_episodes"]
    top.plot(curve["train_steps"], curve["train_success"], color="0.75", lw=0.8,
             label="training episodes finished in each update (stochastic; biased to "
                   "success: failures run to the time limit)")
    top.plot(curve["steps"], curve["success"], marker=".", color="C0",
             label=f"evaluation: {n} fixed seeded episodes, mean action")
    top.set_ylabel("success rate")
    top.set_ylim(-0.02, 1.4)  # room for the legend above the curves
    top.set_yticks(np.linspace(0.0, 1.0, 6))
    top.legend(fontsize=7, loc="upper left")
    bottom.plot(curve["steps"], curve["return"], marker=".", color="C1")
    bottom.set_ylabel(f"mean return of the {n}\nevaluation episodes")
    bottom.set_xlabel("environment steps")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    top.set_title(f"PPO on {ENV_ID}: final evaluation success {curve['success'][-1]:.2f} "
                  f"({round(curve['success'][-1] * n)}/{n})\n{record['command']}\n"
                  f"{record['wall_s'] / 60:.1f} min wall, {record['cpu_s'] / 60:.1f} min CPU "
                  f"on {record['cores']} cores (torch {record['torch_threads']} thread)",
                  fontsize=8)
    fig.tight_layout()
    with atomic_path(out) as tmp:
        fig.savefig(tmp, format="png", dpi=120)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    """Check the arguments, train, write the curve (JSON) and the figure."""
    args = parse(argv)
    import torch

    torch.set_num_threads(1)  # the environments step serially: one core for each
    t0, c0 = time.perf_counter(), time.process_time()
    curve = train(args)
    record = {
        "env": ENV_ID,
        "command": shlex.join(["python", "examples/train_ppo_diffdrive.py",
                               *(sys.argv[1:] if argv is None else argv)]),
        "wall_s": round(time.perf_counter() - t0, 1),
        "cpu_s": round(time.process_time() - c0, 1),
        "cores": len(os.sched_getaffinity(0)),
        "torch_threads": torch.get_num_threads(),
        "eval_episodes": args.eval_episodes,
        "eval_seeds": [EVAL_SEED, EVAL_SEED + args.eval_episodes - 1],
        "settings": {name: getattr(args, name) for name, *_ in ARGS},
        "final_success": curve["success"][-1],
        "final_return": curve["return"][-1],
        "curve": curve,
        "versions": versions(),
    }
    json_path = Path(args.out).with_suffix(".json")
    write_text_atomic(json_path, json.dumps(record, indent=1) + "\n")
    plot(curve, record, args.out)
    print(f"final evaluation success {record['final_success']:.2f} of {args.eval_episodes} "
          f"episodes; {record['wall_s']:.0f} s wall, {record['cpu_s']:.0f} s CPU; wrote "
          f"{json_path} and {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
