"""A simulated VLM for worlds without pixels: answers from the truth, wrong at a known rate.

This is a model, not a canned answer. Each query is one independent draw from a seeded
generator. Truth comes from the world (:meth:`World.holds` of the atoms the question is about;
for the action-level baselines, of every atom the question implies). The chance of a wrong
answer depends only on how much of the named objects the observation shows, never on which
strategy asked:

* ``v`` = the least visibility among the named objects (1 when the question names none);
* ``v = 0`` — the object is not in the picture: the model guesses (wrong with probability 0.5);
* ``v > 0`` — wrong with probability ``min(0.5, error_rate * (2 - v))``: the base rate for a
  fully visible object, up to twice that for a barely visible one.

View sufficiency is judged with the visible-object rate even at ``v = 0`` (a model can tell that
it does not see the thing asked about), its truth being ``v >= 0.5``. The viewpoint choice is
uniform over the options: without pixels there is nothing to prefer one direction by, and the
symbolic camera redraws visibility whatever the direction.
With ``error_rate = 0`` every answer about a visible object is right: "VLM noise off".
"""

from __future__ import annotations

import random
from typing import Callable

from vap_bt.domain.atoms import Atom
from vap_bt.perception.vlm import Answer, Query
from vap_bt.world import Observation

SUFFICIENT_VISIBILITY = 0.5


class SymbolicVLM:
    name = "symbolic"

    def __init__(self, truth: Callable[[Atom], bool], error_rate: float = 0.0, seed: int = 0,
                 rooms: frozenset[str] = frozenset()) -> None:
        if not 0.0 <= error_rate <= 0.5:
            raise ValueError("error_rate must be within [0, 0.5]")
        self.truth, self.error_rate, self.rooms = truth, error_rate, rooms
        self.seed = seed
        self.rng = random.Random(seed ^ 0xB1A5)
        self.queries = 0

    def reseed(self, seed: int) -> None:
        self.seed = seed
        self.rng = random.Random(seed ^ 0xB1A5)

    def describe(self) -> dict:
        return {"backend": self.name, "error_rate": self.error_rate, "seed": self.seed,
                "model": "wrong w.p. min(0.5, error_rate*(2-v)) for visible objects, 0.5 when unseen; "
                         "sufficient iff v >= 0.5; viewpoint uniform"}

    def ask(self, query: Query, observation: Observation) -> Answer:
        self.queries += 1
        v = self._visibility(query, observation)
        if query.kind == "choice":
            choice = self.rng.choice(query.options)
            return Answer(choice, choice)
        true = (v >= SUFFICIENT_VISIBILITY) if query.purpose == "sufficiency" else all(map(self.truth, query.about))
        # whether a view shows enough is judgeable even when it shows nothing: no coin flip there
        p = self._p_seen(v) if query.purpose == "sufficiency" else self._p_wrong(v)
        wrong = self.rng.random() < p
        value = true != wrong
        return Answer("yes" if value else "no", value)

    def _visibility(self, query: Query, obs: Observation) -> float:
        named = [o for o in query.objects if o not in self.rooms]
        return min((obs.visibility.get(o, 0.0) for o in named), default=1.0)

    def _p_wrong(self, v: float) -> float:
        return 0.5 if v <= 0.0 else self._p_seen(v)

    def _p_seen(self, v: float) -> float:
        return min(0.5, self.error_rate * (2.0 - v))
