"""A short PPO run on ``wmr/DiffDrive-GoToGoal-v0``: an example, not part of the test suite.

    nice -n 10 python examples/train_ppo_diffdrive.py --steps 250000 \
        --out docs/img/ppo_diffdrive.png

Writes the learning curve (success rate of finished episodes vs environment steps) to
``--out`` with the command that produced it in the figure's title, and prints one line
per update. Needs ``torch`` (``pip install torch``) and the ``rl`` extra (gymnasium).

PPO (Schulman et al. 2017) with a clipped surrogate, GAE(λ), a Gaussian policy with a
state-independent log standard deviation, observation normalisation by running mean and
variance, and actions clipped to [-1, 1] by the environment.
"""

from __future__ import annotations

import argparse
import sys
import time

import gymnasium as gym
import numpy as np
import torch
from torch import nn

import wmr_mujoco.envs  # noqa: F401  (registers wmr/...)
from wmr_mujoco.atomic import atomic_path


class RunningNorm:
    """Running mean and variance of the observations (Welford, batched)."""

    def __init__(self, size: int) -> None:
        self.mean, self.var, self.count = np.zeros(size), np.ones(size), 1e-4

    def update(self, x: np.ndarray) -> None:
        """Fold a batch ``x`` (N, size) in."""
        m, v, n = x.mean(0), x.var(0), len(x)
        delta, total = m - self.mean, self.count + n
        self.mean = self.mean + delta * n / total
        self.var = (self.var * self.count + v * n + delta**2 * self.count * n / total) / total
        self.count = total

    def __call__(self, x: np.ndarray) -> np.ndarray:
        return np.clip((x - self.mean) / np.sqrt(self.var + 1e-8), -10, 10)


class ActorCritic(nn.Module):
    """Two small tanh MLPs: the policy's mean and the value."""

    def __init__(self, n_obs: int, n_act: int, hidden: int = 64) -> None:
        super().__init__()

        def mlp(out: int) -> nn.Sequential:
            return nn.Sequential(nn.Linear(n_obs, hidden), nn.Tanh(), nn.Linear(hidden, hidden),
                                 nn.Tanh(), nn.Linear(hidden, out))

        self.pi, self.v = mlp(n_act), mlp(1)
        self.log_std = nn.Parameter(-0.5 * torch.ones(n_act))

    def dist(self, obs: torch.Tensor) -> torch.distributions.Normal:
        return torch.distributions.Normal(self.pi(obs), self.log_std.exp())


def train(args: argparse.Namespace) -> tuple[list[int], list[float]]:
    """Run PPO; return (env steps, success rate of the episodes finished since last point)."""
    torch.manual_seed(args.seed)
    envs = gym.make_vec("wmr/DiffDrive-GoToGoal-v0", num_envs=args.envs,
                        vectorization_mode="sync",
                        vector_kwargs={"autoreset_mode": gym.vector.AutoresetMode.SAME_STEP})
    obs, _ = envs.reset(seed=args.seed)
    n_obs, n_act = envs.single_observation_space.shape[0], envs.single_action_space.shape[0]
    net = ActorCritic(n_obs, n_act)
    opt = torch.optim.Adam(net.parameters(), lr=3e-4)
    norm = RunningNorm(n_obs)
    steps, xs, ys = 0, [], []
    finished: list[bool] = []
    t0 = time.time()
    while steps < args.steps:
        buf_o, buf_a, buf_lp, buf_r, buf_d, buf_v = [], [], [], [], [], []
        for _ in range(args.horizon):
            norm.update(obs)
            o = torch.as_tensor(norm(obs), dtype=torch.float32)
            with torch.no_grad():
                d = net.dist(o)
                a = d.sample()
                lp, v = d.log_prob(a).sum(-1), net.v(o).squeeze(-1)
            obs, r, term, trunc, info = envs.step(a.numpy())
            done = term | trunc
            if done.any():  # same-step autoreset: the ended episodes' last info and obs
                final = info["final_info"]
                finished += [bool(s) for s, dn in zip(final["is_success"], done, strict=True)
                             if dn]
                if trunc.any():  # bootstrap the value at the time limit
                    with torch.no_grad():
                        fv = net.v(torch.as_tensor(norm(np.stack(info["final_obs"][trunc])),
                                                   dtype=torch.float32)).squeeze(-1)
                    r = r.copy()
                    r[trunc] += args.gamma * fv.numpy()
            buf_o.append(o), buf_a.append(a), buf_lp.append(lp), buf_v.append(v)
            buf_r.append(torch.as_tensor(r, dtype=torch.float32))
            buf_d.append(torch.as_tensor(done, dtype=torch.float32))
            steps += args.envs
        with torch.no_grad():
            last_v = net.v(torch.as_tensor(norm(obs), dtype=torch.float32)).squeeze(-1)
        adv, gae = torch.zeros(args.horizon, args.envs), torch.zeros(args.envs)
        for t in reversed(range(args.horizon)):
            nxt = last_v if t == args.horizon - 1 else buf_v[t + 1]
            delta = buf_r[t] + args.gamma * nxt * (1 - buf_d[t]) - buf_v[t]
            gae = delta + args.gamma * args.lam * (1 - buf_d[t]) * gae
            adv[t] = gae
        ret = adv + torch.stack(buf_v)
        o, a = torch.cat(buf_o), torch.cat(buf_a)
        lp_old, adv, ret = torch.cat(buf_lp), adv.flatten(), ret.flatten()
        adv = (adv - adv.mean()) / (adv.std() + 1e-8)
        for _ in range(args.epochs):
            for idx in torch.randperm(len(o)).split(args.batch):
                d = net.dist(o[idx])
                ratio = (d.log_prob(a[idx]).sum(-1) - lp_old[idx]).exp()
                surr = torch.min(ratio * adv[idx], ratio.clamp(0.8, 1.2) * adv[idx])
                loss = (-surr.mean() + 0.5 * (net.v(o[idx]).squeeze(-1) - ret[idx]).pow(2).mean()
                        - 0.0 * d.entropy().sum(-1).mean())
                opt.zero_grad()
                loss.backward()
                nn.utils.clip_grad_norm_(net.parameters(), 0.5)
                opt.step()
        if finished:
            xs.append(steps)
            ys.append(float(np.mean(finished)))
            print(f"steps {steps:7d}  episodes {len(finished):4d}  success {ys[-1]:.2f}  "
                  f"{time.time() - t0:.0f} s", flush=True)
            finished = []
    envs.close()
    return xs, ys


def main(argv: list[str] | None = None) -> int:
    """Train and plot."""
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--steps", type=int, default=300_000)
    p.add_argument("--envs", type=int, default=8)
    p.add_argument("--horizon", type=int, default=256)
    p.add_argument("--epochs", type=int, default=10)
    p.add_argument("--batch", type=int, default=256)
    p.add_argument("--gamma", type=float, default=0.99)
    p.add_argument("--lam", type=float, default=0.95)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--out", default="docs/img/ppo_diffdrive.png")
    args = p.parse_args(argv)
    if not (1 <= args.envs <= 64 and 1_000 <= args.steps <= 10_000_000 and
            16 <= args.horizon <= 4096):
        p.error("need 1 <= --envs <= 64, 1000 <= --steps <= 1e7, 16 <= --horizon <= 4096")
    torch.set_num_threads(1)
    xs, ys = train(args)

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(xs, ys, marker=".")
    ax.set_xlabel("environment steps")
    ax.set_ylabel("success rate of finished episodes")
    ax.set_ylim(-0.02, 1.02)
    ax.grid(alpha=0.3)
    ax.set_title("PPO on wmr/DiffDrive-GoToGoal-v0\n" + " ".join(["python", *sys.argv]),
                 fontsize=7)
    fig.tight_layout()
    with atomic_path(args.out) as tmp:
        fig.savefig(tmp, format="png", dpi=120)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
