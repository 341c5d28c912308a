"""What a situation truly stemmed from, read off the world's record: the score of the executive's diagnosis.

The executive diagnoses each situation from what it observed (:mod:`vap_bt.bt.diagnosis`); the
runner scores that against the world's own record of what it did — its injection log
(:meth:`~vap_bt.sim.oracle.Oracle.injected`: Table II's situations and the disturbances a person
caused, each with the things it changed in ``affected``) and, for each situation, how many of
those events had happened when the executive took the situation up (:class:`Raised`; the runner
counts them at that moment, so the order is the world's own, whatever the world's clock). The
executive never sees any of it.

The rule, per situation in the order they were raised, over the events before it that no earlier
situation noticed and that touched its objects (an event touches a situation when a thing the event
changed is one of the situation's atom's or action's arguments):

* a Table II situation among them (the robot's own action failed: a grasp or place that did not
  take, a thing dropped, including a held thing dropped while carrying it), or an action the world
  saw fail by physics alone, with nothing drawn (:mod:`vap_bt.sim.natural_failures`: a held thing
  lost, or an action the world allowed that did not do what it should) → ``execution_failure``;
* else a disturbance among them (a person moved a thing, pushed a leaf shut or half shut) →
  ``world_change``;
* else → ``perception_error``: nothing happened to those things that the executive had not already
  taken up, so belief, or the view that raised the situation, was wrong — a wrong prior, a
  relation mis-read in a survey, a wrong answer of the VLM about an unchanged world.

A situation notices every event that touched it: a later situation about the same things is
scored by what happened since (the executive re-located them when it handled the first). An event
that changed nothing is not in the log (:mod:`vap_bt.sim.symbolic`), so it never counts.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from vap_bt.sim.disturbances import KINDS as DISTURBANCES
from vap_bt.world import InjectedSituation


@dataclass(frozen=True)
class Raised:
    """A situation as the world's record places it: the ``objects`` it is about (its atom's and its
    action's arguments) and how many logged events had happened when it was taken up."""

    objects: frozenset[str]
    events_before: int


@dataclass(frozen=True)
class Truth:
    """What a situation truly stemmed from, and the world's events that say so (their indices in
    the injection log; none for a perception error)."""

    diagnosis: str
    events: tuple[int, ...] = ()


def situation_truths(raised: Sequence[Raised], events: Sequence[InjectedSituation]) -> list[Truth]:
    """The truth of each situation in ``raised`` (in the order raised), by the module's rule."""
    noticed: set[int] = set()
    out = []
    for r in raised:
        touching = [i for i, e in enumerate(events[:r.events_before])
                    if i not in noticed and not r.objects.isdisjoint(e.affected)]
        noticed.update(touching)
        failures = tuple(i for i in touching if events[i].kind not in DISTURBANCES)
        changes = tuple(i for i in touching if events[i].kind in DISTURBANCES)
        if failures:
            out.append(Truth("execution_failure", failures))
        elif changes:
            out.append(Truth("world_change", changes))
        else:
            out.append(Truth("perception_error"))
    return out
