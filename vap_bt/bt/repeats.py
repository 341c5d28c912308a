"""Situations that come back unchanged: the executive's loop breaker.

A replan from the same belief after the same failure makes the same plan, and the robot does the
same thing again. Once is worth it — a grasp the world let slip may hold the next time — but a
situation that recurs identically (the same kind at the same action, about the same atom with the
same observation and the same message) from the same belief says that repeating alone will not
help. :class:`RepeatWatch` counts such recurrences. On the first (:data:`LOOK_AFRESH`) the
executive looks afresh; a skill that then fails the same way once more (:data:`STUCK`) stops the
episode with the reason, instead of spending the replanning budget on the same motion: a motion
planned from the same measurements fails the same way. A check that comes back the same is not
cause to stop — an injected slip or a view the VLM could not make out may well go the other way
the next time.
"""

from __future__ import annotations

from collections import Counter

from vap_bt.bt.context import Situation
from vap_bt.domain.atoms import Atom

#: the occurrence of an identical situation from an identical belief that re-surveys first
LOOK_AFRESH = 2
#: the occurrence of an identical failed execution at which the episode stops: looking afresh
#: did not change what the skill does
STUCK = 3


def stuck(s: Situation, times: int) -> bool:
    """Whether a situation seen ``times`` from the same belief ends the episode."""
    return s.kind == "execution" and times >= STUCK


class RepeatWatch:
    """How often each situation has happened from the same belief, within one episode."""

    def __init__(self) -> None:
        self._seen: Counter = Counter()

    @staticmethod
    def key(s: Situation, belief: frozenset[Atom]) -> tuple:
        return (s.kind, str(s.action) if s.action else None, s.atom, s.observed, s.detail, belief)

    def count(self, s: Situation, belief: frozenset[Atom]) -> int:
        """Record ``s`` raised from ``belief``; returns how many times that has happened (1: new)."""
        k = self.key(s, belief)
        self._seen[k] += 1
        return self._seen[k]


def describe(s: Situation) -> str:
    """A situation in a few words, for the reason an episode stopped."""
    if s.kind == "execution":
        return f"execution of {s.action} failed ({s.detail})"
    if s.kind == "unseen":
        return f"could not see whether {s.atom} holds before {s.action}"
    return f"{s.kind} {s.atom} observed {s.observed}" + (f" at {s.action}" if s.action else "")
