"""Does a cheaper solver setting still meet every target? (solver_cost's validation).

The validation half of :mod:`wmr_mujoco.bench.solver_cost`. A setting
(:class:`~wmr_mujoco.bench.solver_cost.Setting`) that a robot's parameters express is
validated as ``wmr validate ROBOT --seed S`` would, but with the setting's parameters:
every registered scenario of the robot (:func:`wmr_mujoco.lookup.validation_jobs`) runs
its whole family (:func:`wmr_mujoco.validation.members.run_family`, the family's declared
draws) and is judged by its worst member. The robot's default parameters run the same
families at the same seed beside it, and the two are compared row by row
(:func:`compare`):

* **lost**: the rows the defaults meet and the setting does not (:func:`meets`: a judged
  row that passes, or an open target's row whose figure is within it, so that a setting
  cannot hide behind a target that is open for another draw), and any failed row of
  the setting's own (a member whose run failed or diverged); the setting is rejected if
  any, at any seed;
* **worst change**: the largest rise of a judged figure as a share of its target,
  ``max (|v_setting| − |v_default|) / target`` over the judged rows (positive: the
  setting comes closer to failing).
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import math
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from wmr_mujoco.atomic import write_text_atomic
from wmr_mujoco.docs_sync.export import scene_xml
from wmr_mujoco.docs_sync.markers import replace_between
from wmr_mujoco.lookup import validation_jobs
from wmr_mujoco.models.builders.common import to_xml
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.models.paths import DOCS_DIR
from wmr_mujoco.robots.spec import RobotSpec
from wmr_mujoco.validation.members import run_family
from wmr_mujoco.validation.pool import run_calls
from wmr_mujoco.validation.targets import Row

if TYPE_CHECKING:
    from wmr_mujoco.bench.solver_cost import Setting

#: Where :mod:`wmr_mujoco.bench.solver_cost` publishes its tables, and its marker.
DOC = DOCS_DIR / "benchmarks.md"
MARKER = "solver-cost"

#: Where the figures of each (robot, setting, seed) are kept between runs.
CACHE = Path("reports") / "solver_cost"

#: Rows by (scenario, metric, unit): a metric can be reported in two units.
Figures = dict[tuple[str, str, str], Row]


def _key(r: Row) -> tuple[str, str, str]:
    return (r.scenario, r.metric, r.unit)


def family_rows(spec: RobotSpec, key: int, seed: int, params: RobotParams) -> list[Row]:
    """The judged rows of the robot's ``key``-th scenario's family (worst member)."""
    _, s = validation_jobs([spec.name])[key]
    return list(run_family(spec, s, seed, params=params).rows)


def cache_file(spec: RobotSpec, params: RobotParams, seed: int, folder: Path) -> Path:
    """The file of the figures of ``params`` at ``seed``.

    Named by the digest of the model files the parameters build (robot and scene), so a
    changed model runs again.
    """
    assert spec.build is not None
    text = to_xml(spec.build(params)) + scene_xml(spec, params)
    digest = hashlib.sha256(text.encode()).hexdigest()[:16]
    return folder / f"{spec.name}-seed{seed}-{digest}.json"


def kept(spec: RobotSpec, params: RobotParams, seed: int, cache: Path | None
         ) -> Figures | None:
    """The figures of ``params`` at ``seed`` kept in ``cache`` (None: not there)."""
    path = None if cache is None else cache_file(spec, params, seed, cache)
    if path is None or not path.exists():
        return None
    rows = [Row(**r) for r in json.loads(path.read_text())]
    return {_key(r): r for r in rows}


def figures(spec: RobotSpec, params: RobotParams, seed: int, jobs: int = 1,
            cache: Path | None = None) -> Figures:
    """Every row of ``wmr validate ROBOT --seed SEED`` with ``params`` (:data:`Figures`).

    ``cache``: a folder keeping the rows of each model and seed (:func:`cache_file`); rows
    found there are read instead of run. The validation code is not part of the key:
    clear the folder after changing it.
    """
    found = kept(spec, params, seed, cache)
    if found is not None:
        return found
    n = len(validation_jobs([spec.name]))
    calls = [(family_rows, (spec, k, seed, params)) for k in range(n)]
    out: Figures = {}
    for rows in run_calls(calls, jobs):
        for r in rows:  # type: ignore[attr-defined]
            out[_key(r)] = r
    if cache is not None:
        keep(spec, params, seed, out, cache)
    return out


def keep(spec: RobotSpec, params: RobotParams, seed: int, figs: Figures, cache: Path) -> None:
    """Keep every row of ``params`` at ``seed`` in ``cache`` (:func:`cache_file`)."""
    path = cache_file(spec, params, seed, cache)
    path.parent.mkdir(parents=True, exist_ok=True)
    write_text_atomic(path, json.dumps([dataclasses.asdict(r) for r in figs.values()]))


@dataclasses.dataclass(frozen=True)
class Verdict:
    """A setting's figures against the defaults' at one seed.

    Attributes:
        lost: ``scenario / metric`` of the rows the defaults meet and the setting does not
            (:func:`meets`).
        worst_rise: the largest ``(|v_setting| − |v_default|) / target`` over the judged
            rows (an open target's figure is shown, not judged).
        worst_row: ``scenario / metric`` of that row.
        missing: rows of the defaults the setting did not produce (a failed run).
    """

    lost: tuple[str, ...]
    worst_rise: float
    worst_row: str
    missing: tuple[str, ...] = ()

    @property
    def acceptable(self) -> bool:
        """No target lost and no row missing."""
        return not self.lost and not self.missing


def meets(r: Row) -> bool:
    """Whether a row's figure is within its target: judged and passed, or open and met."""
    if r.passed is not None:
        return bool(r.passed)
    return bool(r.open and r.target is not None and math.isfinite(r.value)
                and abs(r.value) <= r.target)


def compare(default: Figures, setting: Figures) -> Verdict:
    """The setting's rows against the defaults' (see the module docstring)."""
    lost, missing = [], []
    worst, where = float("-inf"), ""
    def label(key: tuple[str, str, str]) -> str:
        return f"{key[0]} / {key[1]} ({key[2]})" if key[2] else f"{key[0]} / {key[1]}"

    for key, s in setting.items():  # a failed row of its own, e.g. a member that diverged
        if key not in default and s.passed is False:
            lost.append(label(key))
    for key, d in default.items():
        name = label(key)
        s = setting.get(key)
        if s is None:
            missing.append(name)
            continue
        if meets(d) and not meets(s):
            lost.append(name)
        if d.target and d.passed is not None:  # a judged row
            rise = (abs(s.value) - abs(d.value)) / abs(d.target)
            if not rise <= worst:  # NaN (a failed figure) counts as the worst
                worst, where = rise, name
    return Verdict(tuple(lost), worst, where, tuple(missing))


def verdict_text(by_seed: Mapping[int, Verdict]) -> str:
    """One table cell: accepted or the lost targets, and the worst rise, per seed."""
    parts = []
    for seed, v in by_seed.items():
        head = "passes all" if v.acceptable else (
            f"loses {len(v.lost) + len(v.missing)}: {', '.join((*v.lost, *v.missing))[:80]}")
        parts.append(f"seed {seed}: {head}; worst rise {v.worst_rise:+.1%} of target "
                     f"({v.worst_row})")
    return "; ".join(parts)


def judge_settings(spec: RobotSpec, settings: Sequence[Setting], seeds: Sequence[int],
                   jobs: int = 1, progress: bool = True,
                   cache: Path | None = CACHE, run: bool = True) -> dict[str, str]:
    """Validate each of the candidate ``settings`` the robot's parameters express.

    At each seed in turn; a setting that loses a target at one seed is rejected there
    (its later seeds are not run). ``run=False`` runs nothing: the verdicts of the seeds
    whose figures ``cache`` keeps (a setting with none is left out).

    Returns:
        setting label -> table cell (:func:`verdict_text`); settings not validated are
        left out.
    """
    chosen = [(s, s.robot_params(spec)) for s in settings]
    chosen = [(s, p) for s, p in chosen if p is not None]
    if not chosen or spec.params_type is None:
        return {}
    out: dict[str, dict[int, Verdict]] = {s.label: {} for s, _ in chosen}
    for seed in seeds:
        # a setting rejected at an earlier seed needs no later one
        left = [(s, p) for s, p in chosen if all(v.acceptable for v in out[s.label].values())]
        if not left:
            break
        base = (figures(spec, spec.params_type(), seed, jobs, cache) if run
                else kept(spec, spec.params_type(), seed, cache))
        for s, p in left:
            assert p is not None
            mine = figures(spec, p, seed, jobs, cache) if run else kept(spec, p, seed, cache)
            if base is None or mine is None:
                continue
            out[s.label][seed] = compare(base, mine)
            if progress:
                print(f"  {spec.name} {s.label} seed {seed}: "
                      f"{verdict_text({seed: out[s.label][seed]})}", flush=True)
    return {label: verdict_text(v) for label, v in out.items() if v}


def publish(text: str, path: Path = DOC) -> None:
    """Paste the study's text between its markers in ``docs/benchmarks.md``."""
    replace_between(path, MARKER, text)
    print(f"wrote {path}")
