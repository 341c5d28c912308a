"""tools/progress.py: how far a campaign or benchmark is, on stderr, never in its stdout table."""

from __future__ import annotations

import io
import sys

import pytest

from conftest import ROOT

sys.path.insert(0, str(ROOT))
from tools.progress import Progress, duration  # noqa: E402


class Clock:
    """A clock the test moves by hand."""

    def __init__(self) -> None:
        self.t = 100.0

    def __call__(self) -> float:
        return self.t


def test_a_line_every_few_seconds_and_always_the_last():
    clock, out = Clock(), io.StringIO()
    p = Progress(total=10, unit="episodes", every_s=5.0, stream=out, clock=clock)
    for _ in range(9):  # 9 episodes, 2 s apart: lines after the 3rd (6 s), 6th (12 s) and 9th (18 s)
        clock.t += 2.0
        p.step()
    clock.t += 2.0
    p.step()  # the last one is always said
    lines = out.getvalue().splitlines()
    assert lines == ["  [3/10 episodes  30%  30.0/min  about 14 s left]",
                     "  [6/10 episodes  60%  30.0/min  about 8 s left]",
                     "  [9/10 episodes  90%  30.0/min  about 2 s left]",
                     "  [10/10 episodes  100%  30.0/min  done in 20 s]"]


def test_rate_per_second_when_fast_and_a_label_for_a_second_loop():
    clock, out = Clock(), io.StringIO()
    p = Progress(total=4000, unit="calls", label="baseline", stream=out, clock=clock)
    clock.t += 10.0
    p.step(2000)
    assert out.getvalue() == "  [baseline: 2000/4000 calls  50%  200.0/s  about 10 s left]\n"


@pytest.mark.parametrize("seconds,text", [(0.4, "0 s"), (59.6, "1 min 00 s"), (200, "3 min 20 s"),
                                          (3900, "1 h 05 min")])
def test_durations_read_as_a_person_says_them(seconds, text):
    assert duration(seconds) == text
