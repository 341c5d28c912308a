"""Progress of a long campaign or benchmark: items done, rate, time left — on stderr.

Every script under ``tools/experiments`` and ``tools/bench`` that loops over episodes or scenes
reports through this one helper, so they all say it the same way and none of it reaches stdout,
where their tables and JSON go. A line is printed at most every ``every_s`` seconds, and always
for the last item, so a fast symbolic campaign prints a handful of lines and a slow pybullet one
prints after each scene::

    progress = Progress(total=450, unit="episodes")
    for ...:
        ...                      # one episode
        progress.step()
    #   [120/450 episodes  27%  41.3/min  about 8 min left]

Scripts import it as ``from tools.progress import Progress`` with the checkout's root on
``sys.path`` (each script puts it there).
"""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass, field
from typing import Callable, TextIO


def duration(seconds: float) -> str:
    """``45 s``, ``3 min 20 s``, ``1 h 05 min``: as precise as a person needs."""
    s = max(0, round(seconds))
    if s < 60:
        return f"{s} s"
    if s < 3600:
        return f"{s // 60} min {s % 60:02d} s"
    return f"{s // 3600} h {s % 3600 // 60:02d} min"


def rate(per_second: float) -> str:
    """Items per second when there are several a second, else per minute."""
    return f"{per_second:.1f}/s" if per_second >= 1 else f"{per_second * 60:.1f}/min"


@dataclass
class Progress:
    """Counts finished items of a known total and prints where the loop is, now and then."""

    total: int
    unit: str = "episodes"
    label: str = ""  # what is being counted, when a script has several loops (``"baseline"``)
    every_s: float = 5.0
    stream: TextIO | None = None  # default: sys.stderr at the moment of printing
    clock: Callable[[], float] = time.perf_counter
    done: int = 0
    _start: float = field(init=False)
    _last: float = field(init=False)

    def __post_init__(self) -> None:
        self._start = self._last = self.clock()

    def step(self, n: int = 1, note: str = "") -> None:
        """``n`` more items are done; print a line if it is time (or if this was the last)."""
        self.done += n
        now = self.clock()
        if self.done >= self.total or now - self._last >= self.every_s:
            self._last = now
            print(self.line(now, note), file=self.stream or sys.stderr, flush=True)

    def line(self, now: float | None = None, note: str = "") -> str:
        """``  [label: 120/450 episodes  27%  41.3/min  about 8 min left]``."""
        elapsed = (self.clock() if now is None else now) - self._start
        per_s = self.done / elapsed if elapsed > 0 else 0.0
        parts = [f"{self.done}/{self.total} {self.unit}"]
        if self.total:
            parts.append(f"{100 * self.done / self.total:.0f}%")
        if per_s > 0:
            parts.append(rate(per_s))
        if self.done >= self.total:
            parts.append(f"done in {duration(elapsed)}")
        elif per_s > 0:
            parts.append(f"about {duration((self.total - self.done) / per_s)} left")
        head = f"{self.label}: " if self.label else ""
        return f"  [{head}{'  '.join(parts)}]" + (f" {note}" if note else "")
