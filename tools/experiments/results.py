"""Episode rows: what a campaign keeps of each episode, appended as it finishes, and resumed from.

A row is flat: the episode's key (:class:`tools.experiments.engine.Key`), whether its
configuration could run at all (``runnable``: a strategy this world or VLM backend cannot run is
a row saying so, never a faked result), the outcome scored against the world (``success`` = the
executive claims the goal AND the world's ``goal_satisfied``; ``claimed_denied`` = it claimed a
goal the world denies), the executive's work (situations, replans, VLM queries, executed
actions, wall time), the perception model's version, and the measures of
:mod:`tools.experiments.measures` (viewpoints per uncertain check, failure mode, diagnoses).

:class:`EpisodeLog` appends each row to ``episodes.jsonl`` as one line, flushed and synced, so a
stopped campaign loses at most the episodes in flight, and ``--resume`` skips every key already
there. ``episodes.csv`` is written from the log at the end (list-valued measures joined by ``;``).
"""

from __future__ import annotations

import csv
import json
import os
from dataclasses import asdict
from pathlib import Path

from tools.experiments import measures
from tools.experiments.engine import Key, key_of

#: the CSV's columns, in order (the key's first)
COLUMNS = ("experiment", "world", "task", "strategy", "viewpoints", "seed", "runnable", "success", "claimed",
           "claimed_denied", "situations", "replans", "vlm_queries", "actions", "wall_s", "vlm_version",
           "world_version", "openblas", "reason", "error", *measures.COLUMNS)


def episode_row(key: Key, report: dict) -> dict:
    """The row of a finished episode, from its report."""
    claimed, holds = bool(report["success"]), bool(report["goal_satisfied"])
    vlm = report.get("vlm") or {}
    return {**asdict(key), "runnable": True, "success": claimed and holds, "claimed": claimed,
            "claimed_denied": claimed and not holds, "situations": len(report["situations"]),
            "replans": report["replans"], "vlm_queries": report["vlm_queries"],
            "actions": len(report["actions_executed"]), "wall_s": report["wall_s"],
            "vlm_version": vlm.get("version") or vlm.get("model") or vlm.get("backend"),
            # the simulated world's mechanics (pybullet_world.WORLD_VERSION; none in the symbolic world)
            "world_version": ((report.get("world") or {}).get("physics") or {}).get("version"),
            # the BLAS kernels the worker ran (vap_bt/numerics.py): a cluster's worker that loaded
            # numpy before vap_bt and was not given OPENBLAS_CORETYPE runs its CPU's, and may differ
            "openblas": (report.get("versions") or {}).get("openblas"),
            "reason": report["reason"], "error": None, **measures.of(report)}


def not_runnable(key: Key, exc: Exception) -> dict:
    """The row of a configuration that cannot run in this world or with this VLM backend (the
    session said so with an InputError before anything ran)."""
    return {**_empty(key), "runnable": False, "reason": f"not runnable: {exc}"}


def crashed(key: Key, exc: Exception, wall_s: float) -> dict:
    """The row of an episode that raised: a failure of the campaign's subject, kept and counted."""
    return {**_empty(key), "runnable": True, "success": False, "claimed": False, "claimed_denied": False,
            "wall_s": round(wall_s, 4), "error": f"{type(exc).__name__}: {exc}",
            "reason": "crashed", "failure_mode": measures.CRASH}


def _empty(key: Key) -> dict:
    return {**dict.fromkeys(COLUMNS), **asdict(key)}


class EpisodeLog:
    """A campaign's ``episodes.jsonl``: rows appended one line each as episodes finish."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def rows(self) -> list[dict]:
        """Every row written so far (a last line cut short by a stop mid-write is dropped)."""
        if not self.path.exists():
            return []
        rows = []
        for line in self.path.read_text().splitlines():
            try:
                rows.append(json.loads(line))
            except json.JSONDecodeError:
                continue
        return rows

    def episodes(self) -> set[tuple]:
        """The episodes (:meth:`Key.episode`) of the rows written so far: what ``--resume`` skips,
        whichever experiment wrote them."""
        return {key_of(r).episode() for r in self.rows()}

    def start(self, resume: bool) -> None:
        """Begin the log: kept as it is to resume, else emptied (a fresh campaign)."""
        self.path.parent.mkdir(parents=True, exist_ok=True)
        if not resume or not self.path.exists():
            self.path.write_text("")
        elif (text := self.path.read_text()) and not text.endswith("\n"):  # a line cut short: end it (dropped on read)
            with self.path.open("a") as f:
                f.write("\n")

    def append(self, row: dict) -> None:
        """Write one row and make sure it is on disk before the next episode is counted."""
        with self.path.open("a") as f:
            f.write(json.dumps(row) + "\n")
            f.flush()
            os.fsync(f.fileno())


def write_csv(rows: list[dict], path: Path) -> None:
    """``episodes.csv``: one line per row, sorted by key, list values joined by ``;``."""
    with path.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        writer.writeheader()
        for row in sorted(rows, key=key_of):
            writer.writerow({k: ";".join(map(str, v)) if isinstance(v, list) else v for k, v in row.items()})
