"""The episode report: everything needed to judge a run and to run it again.

``success`` is the executive's own claim; ``goal_satisfied`` is the world's truth about the goal,
read after the episode. They are reported side by side so that a claim the world denies shows.
The report also records the seed, versions, world and VLM parameters, every plan, action,
verification, situation (detected, and injected by the world) and replan.

A run stopped by Ctrl-C, at whatever moment, writes the same report with what was known by then
(:class:`vap_bt.runner.EpisodeInterrupted`): the same keys, so that a reader needs no second
schema; ``interrupted`` says it was stopped and ``phase`` what the episode was doing.
"""

from __future__ import annotations

import json
import platform
import sys
from importlib import metadata
from pathlib import Path


def versions() -> dict[str, str]:
    out = {"python": platform.python_version()}
    for dist in ("vap-bt", "py-trees", "unified-planning", "up-fast-downward", "eclipse-zenoh", "pybullet", "pin"):
        try:
            out[dist] = metadata.version(dist)
        except metadata.PackageNotFoundError:
            out[dist] = "not installed"
    return out


def command_line() -> str:
    return " ".join(["vap-bt" if Path(sys.argv[0]).name in ("vap-bt", "cli.py") else sys.argv[0], *sys.argv[1:]])


def write(report: dict, path: str | Path) -> None:
    """Write atomically: a reader never sees half a report, and an old one is replaced whole."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(path.suffix + ".part")
    tmp.write_text(json.dumps(report, indent=2, sort_keys=False, default=str) + "\n")
    tmp.replace(path)
