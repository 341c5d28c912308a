"""Situations that come back unchanged: the executive's loop breaker.

A replan from the same belief after the same failure makes the same plan, and the robot does the
same thing again. Once is worth it — a grasp the world let slip may hold the next time — but a
situation that recurs identically (the same kind at the same action, about the same atom with the
same observation and the same message) from the same belief says that repeating alone will not
help. :class:`RepeatWatch` counts such recurrences. On the first (:data:`LOOK_AFRESH`) the
executive looks afresh; a skill that then fails the same way once more (:data:`STUCK`) stops the
episode with the reason, instead of spending the replanning budget on the same motion: a motion
planned from the same measurements fails the same way. An action an AffordanceVQA question keeps
saying cannot be done is then tried against the answer (:mod:`vap_bt.bt.action_check`). A precondition the camera could not make
out (``unseen``) that comes back the same after looking afresh makes the robot act on belief there
(the action's effects are still checked): the same plan brings the robot to the same views (an
item under furniture that its find pose never shows, a relation a model reads poorly), and more
looks from them will not settle it — nor the action's other preconditions about the same thing
(:func:`seen_together`), which are then acted on belief too where they cannot be made out. A goal
atom that stays unseen stops the episode (once handed back to the planner first when no check ever
confirmed it; claimed on the check that confirmed it where that still stands:
:mod:`vap_bt.bt.executive`): success is never claimed on belief alone. A check that came
back with a value is not cause to stop — an injected slip may well go the other way the next
time. But a precondition a check denies from the same belief a third time (:func:`contested`) is
put on trial: the correction took the atom out, the re-location that followed put it back (a
sighting from elsewhere places the item where the check's views deny it), and the replan brought
the robot to the same views, whose model answers the same pictures the same way (heat_pie seed 1
in pybullet: the pie in the oven, seen there from the counter, "not inside" from the oven's front
eighteen times until the replanning budget was gone). The camera and the re-location cannot both
be right; the action is the test — its skill fails if the denial was right, and its effects are
checked.

Replanning itself is bounded by the run's ``max_replans`` (default
:data:`vap_bt.settings.MAX_REPLANS`; the paper sets no bound; an episode needs one that every
situation Table II injects can use).
"""

from __future__ import annotations

from collections import Counter
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # for annotations only: the command line reads MAX_REPLANS without the executive
    from vap_bt.bt.context import Situation
    from vap_bt.domain.atoms import Atom
    from vap_bt.domain.knowledge import GroundAction

#: the occurrence of an identical situation from an identical belief that re-surveys first
LOOK_AFRESH = 2
#: the occurrence of an identical failed execution (or unseen precondition) at which the episode
#: stops: looking afresh did not change what the skill does (or what the camera is shown)
STUCK = 3


def contested(s: Situation, times: int) -> bool:
    """Whether a precondition denied ``times`` from the same belief is to be tried against."""
    return s.kind == "precondition" and times >= STUCK


def seen_together(atom: Atom, action: GroundAction) -> set[Atom]:
    """``atom`` and ``action``'s other positive preconditions about the same thing (its first
    argument): the views from the action's stand show them no better than ``atom``."""
    subject = atom.args[:1]
    return {atom} | {a for a in action.pre_pos if subject and a.args[:1] == subject}


def stuck(s: Situation, times: int) -> bool:
    """Whether a situation seen ``times`` from the same belief ends the episode."""
    return s.kind in ("execution", "action_infeasible", "unseen") and times >= STUCK


class RepeatWatch:
    """How often each situation has happened from the same belief, within one episode."""

    def __init__(self) -> None:
        self._seen: Counter = Counter()

    @staticmethod
    def key(s: Situation, belief: frozenset[Atom]) -> tuple:
        """What makes two situations the same recurrence: kind, action, atom, observation and message, and
        the belief they arose from."""
        return (s.kind, str(s.action) if s.action else None, s.atom, s.observed, s.detail, belief)

    def count(self, s: Situation, belief: frozenset[Atom]) -> int:
        """Record ``s`` raised from ``belief``; returns how many times that has happened (1: new)."""
        k = self.key(s, belief)
        self._seen[k] += 1
        return self._seen[k]

    def forget(self, atom: Atom) -> None:
        """Start counting the situations about ``atom`` afresh: the action that makes it ran
        again, so its checks look at a new outcome, not at the one they could not make out."""
        self._seen = Counter({k: n for k, n in self._seen.items() if k[2] != atom})  # k[2]: the atom (:meth:`key`)


def describe(s: Situation) -> str:
    """A situation in a few words, for the reason an episode stopped."""
    if s.kind == "execution":
        return f"execution of {s.action} failed ({s.detail})"
    if s.kind in ("action_failed", "action_infeasible"):
        return f"{s.kind.replace('_', ' ')} at {s.action}: {s.detail} no"
    if s.kind == "unseen":
        return f"could not see whether {s.atom} holds " + (f"before {s.action}" if s.action else "at the goal")
    return f"{s.kind} {s.atom} observed {s.observed}" + (f" at {s.action}" if s.action else "")
