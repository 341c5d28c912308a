"""The simulated VLM: answers a question about a frame from the world's record of that frame.

It is a model, not a canned answer, and it lives on the world's side: it is handed the frame id
and looks up the :class:`~vap_bt.sim.captures.CaptureRecord` the simulated camera wrote when it
took the frame — how much of each object the frame shows and the truth at capture time. Each
query is one independent draw from a seeded generator. The chance of a wrong answer depends only
on how much of the named objects that frame shows, never on which strategy asked:

* ``v`` = the least visibility among the objects the question names (rooms excluded; 1 when it
  names none);
* ``v = 0`` — the object is not in the picture: the model guesses (wrong with probability 0.5);
* ``v > 0`` — wrong with probability ``min(0.5, error_rate * (2 - v))``: the base rate for a
  fully visible object, up to twice that for a barely visible one.

Truth for a predicate question is that every atom it concerns holds (for the action-level
baselines, every atom the action implies). The draw for a query is seeded by the run's seed, the
frame and the prompt, so answers do not depend on the order in which concurrent questions
arrive (and a question asked twice about one frame gets one answer, as from a model at
temperature 0). View sufficiency is judged with the visible-object
rate even at ``v = 0`` (a model can tell that it does not see the thing asked about), its truth
being ``v >= 0.5``. The viewpoint choice is uniform over the options (a frame-based choice is
future work). A frame the log does not know (too old, or from elsewhere) gets no answer.
With ``error_rate = 0`` every answer about a visible object is right: "VLM noise off".
"""

from __future__ import annotations

import random
from typing import Callable

from vap_bt.perception.vlm import Answer, Query
from vap_bt.robot.frame import Frame
from vap_bt.sim.captures import CaptureRecord

SUFFICIENT_VISIBILITY = 0.5


class SimVLM:
    """The world-side VLM model described in the module docstring."""

    name = "sim"

    def __init__(self, records: Callable[[str], CaptureRecord | None], error_rate: float = 0.0, seed: int = 0,
                 rooms: frozenset[str] = frozenset()) -> None:
        if not 0.0 <= error_rate <= 0.5:
            raise ValueError("error_rate must be within [0, 0.5]")
        self.records, self.error_rate, self.rooms = records, error_rate, rooms
        self.reseed(seed)

    def reseed(self, seed: int) -> None:
        self.seed = seed

    def describe(self) -> dict:
        return {"backend": self.name, "error_rate": self.error_rate, "seed": self.seed,
                "model": "answers from the world's record of the frame: wrong w.p. min(0.5, error_rate*(2-v)) "
                         "for visible objects, 0.5 when unseen; sufficient iff v >= 0.5; viewpoint uniform"}

    def ask(self, query: Query, frame: Frame) -> Answer:
        record = self.records(frame.frame_id)
        if record is None:
            return Answer("", None)
        v = self._visibility(query, record)
        rng = random.Random(f"{self.seed}|{frame.frame_id}|{query.kind}|{query.prompt}")
        if query.kind == "choice":
            choice = rng.choice(query.options)
            return Answer(choice, choice)
        sufficiency = query.purpose == "sufficiency"
        true = (v >= SUFFICIENT_VISIBILITY) if sufficiency else all(map(record.holds, query.about))
        # whether a view shows enough is judgeable even when it shows nothing: no coin flip there
        p = self._p_seen(v) if sufficiency else self._p_wrong(v)
        value = true != (rng.random() < p)
        return Answer("yes" if value else "no", value)

    def _visibility(self, query: Query, record: CaptureRecord) -> float:
        named = [o for o in query.objects if o not in self.rooms]
        return min((record.visibility.get(o, 0.0) for o in named), default=1.0)

    def _p_wrong(self, v: float) -> float:
        return 0.5 if v <= 0.0 else self._p_seen(v)

    def _p_seen(self, v: float) -> float:
        return min(0.5, self.error_rate * (2.0 - v))
