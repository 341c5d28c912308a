"""Capture records: what a simulated camera knew about each frame it took.

A real VLM judges a frame from its pixels. The simulated VLM (:mod:`vap_bt.sim.sim_vlm`) lives on
the world's side and judges a frame from the world's record of that capture: how much of each
object the frame shows (its *visibility*, from the frame's own masks or the symbolic camera's
model) and the truth at capture time. The camera writes one :class:`CaptureRecord` per frame;
the log keeps the last few hundred, keyed by frame id, which is all the simulated VLM is given
besides the question.

Truth is read through the oracle lazily and remembered: questions about a frame arrive right
after it is taken, before the world moves again, so a value read then is the value at capture.
A record also stores the world's step counter at capture; a question about a frame after the
world has stepped is answered from what was read before, or — if nothing was — from the truth
now, and counted as ``late`` (reported, so that it could never go unnoticed).
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass, field
from typing import Callable

from vap_bt.domain.atoms import Atom
from vap_bt.sim.oracle import Oracle


@dataclass
class CaptureRecord:
    """The world's side of one frame."""

    frame_id: str
    step: int  # the world's step counter at capture
    visibility: dict[str, float]  # object -> visible fraction in this frame (0: not in it)
    oracle: Oracle
    now: Callable[[], int]  # the world's step counter now
    #: object -> (image edges its mask touches: "left", "right", "top", "bottom"; share of the image
    #: it covers) — pixel worlds only
    masks: dict[str, tuple[tuple[str, ...], float]] = field(default_factory=dict)
    _truth: dict[Atom, bool] = field(default_factory=dict)
    late: int = 0

    def holds(self, atom: Atom) -> bool:
        if atom not in self._truth:
            if self.now() != self.step:
                self.late += 1
            self._truth[atom] = self.oracle.holds(atom)
        return self._truth[atom]


class CaptureLog:
    """The last ``size`` capture records, by frame id."""

    def __init__(self, size: int = 512) -> None:
        self.size = size
        self._records: OrderedDict[str, CaptureRecord] = OrderedDict()

    def add(self, record: CaptureRecord) -> None:
        self._records[record.frame_id] = record
        while len(self._records) > self.size:
            self._records.popitem(last=False)

    def get(self, frame_id: str) -> CaptureRecord | None:
        return self._records.get(frame_id)

    def clear(self) -> None:
        self._records.clear()

    @property
    def late(self) -> int:
        return sum(r.late for r in self._records.values())
