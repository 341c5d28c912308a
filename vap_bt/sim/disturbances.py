"""Scripted disturbances: what a person does to the world mid-episode, drawn per episode from a seed.

Table II's situations (:mod:`vap_bt.sim.situations`) are the robot's own failures; a disturbance
is someone else's doing, between two of the robot's actions: a person takes a thing and puts it
down somewhere else, or pushes a door (or a cupboard's leaf) half shut, or shut. The world
carries it out — never the executive, which has to notice it by looking — and records it in its
injection log beside Table II's situations (:class:`~vap_bt.world.InjectedSituation`, with the
thing it changed in ``affected``), so that a report can score it. A disturbance that would change
nothing (shutting a leaf that is already shut, moving a thing the robot holds) does not happen and
is not recorded.

A :class:`Disturbance` is one event: *after* the world's action of index ``after`` ends (0: the
first action of the episode, whatever its outcome), do ``kind`` to ``target``. A
:class:`DisturbanceModel` draws at most one per episode: with its probability, a kind (uniformly,
or the one asked for — a campaign balances kinds over tasks), a step uniformly in
``[0, max_after)``, a target — a thing the goal names if there is one (moving it is what can undo
the robot's work), else any portable thing; a leaf of a room door or an openable piece of
furniture — and, for a move, another surface (or floor) that can hold things. Its generator is
its own, seeded from the episode's seed, so disturbances never shift Table II's random stream.

Both worlds take the same events: the symbolic one applies them to its facts
(:meth:`~vap_bt.sim.symbolic.SymbolicWorld`), the pybullet one as its scripted dicts
(:meth:`Disturbance.script`: the thing set down on its new support, the leaf's joint set to a
fraction of its travel).
"""

from __future__ import annotations

import random
from dataclasses import asdict, dataclass

from vap_bt.domain.task import PlanningTask

MOVED = "object_moved_by_person"
HALF_SHUT = "door_left_half_open"  # pybullet's name for a leaf swung part way (tests use it)
SHUT = "door_shut_by_person"
KINDS: tuple[str, ...] = (MOVED, HALF_SHUT, SHUT)
#: how far a half-shut leaf is left open, as a fraction of its travel (pybullet; symbolic: ajar)
HALF_OPEN = 0.4


@dataclass(frozen=True)
class Disturbance:
    """One scripted event: after action ``after`` ends, ``kind`` happens to ``target``."""

    kind: str
    after: int
    target: str
    to: str | None = None  # a move: the surface or floor the thing is put on

    def script(self) -> dict:
        """The pybullet world's scripted dict (:mod:`vap_bt.sim.pybullet_world`)."""
        if self.kind == MOVED:
            return {"after": self.after, "move": self.target, "to": self.to}
        return {"after": self.after, "door": self.target, "open": HALF_OPEN if self.kind == HALF_SHUT else 0.0}

    def to_json(self) -> dict:
        return asdict(self)


@dataclass(frozen=True)
class DisturbanceModel:
    """At most one disturbance per episode, with ``probability``, after one of the first
    ``max_after`` actions; ``kind`` fixes its kind (None: drawn)."""

    probability: float = 0.0
    max_after: int = 6
    kind: str | None = None

    def draw(self, task: PlanningTask, seed: int, kind: str | None = None) -> list[Disturbance]:
        """The episode's disturbances for ``seed`` (empty, or one); ``kind`` overrides the model's."""
        rng = random.Random(seed ^ 0xD157)
        if not rng.random() < self.probability:
            return []
        kind = kind or self.kind or rng.choice([k for k in KINDS if _targets(task, k)] or [MOVED])
        if kind not in KINDS:
            raise ValueError(f"unknown disturbance {kind!r} ({', '.join(KINDS)})")
        after = rng.randrange(self.max_after)
        targets = _targets(task, kind)
        if not targets:
            return []
        target = rng.choice(targets)
        if kind != MOVED:
            return [Disturbance(kind, after, target)]
        places = _places(task, target)
        return [Disturbance(MOVED, after, target, rng.choice(places))] if places else []

    def describe(self) -> dict:
        """The model's parameters, for the report."""
        return asdict(self)


def _targets(task: PlanningTask, kind: str) -> list[str]:
    """What ``kind`` can happen to: a thing the goal names (else any item), or any leaf (a room's
    door, an openable piece of furniture)."""
    if kind != MOVED:
        return sorted(o for o, t in task.objects.items() if _is(task, t, "door") or _openable(task, o))
    items = sorted(o for o, t in task.objects.items() if _is(task, t, "item"))
    return sorted({x for lit in task.goal for x in lit.atom.args} & set(items)) or items


def _places(task: PlanningTask, thing: str) -> list[str]:
    """Surfaces (floors too) that can hold things, other than where ``thing`` starts."""
    start = {a.args[1] for a in task.init if a.predicate in ("on", "inside") and a.args[0] == thing}
    return sorted(o for o, t in task.objects.items() if _is(task, t, "surface") and o not in start
                  and any(a.predicate == "clear" and a.args == (o,) for a in task.init))


def _is(task: PlanningTask, typ: str, base: str) -> bool:
    k = task.knowledge
    return base in k.parents and k.is_subtype(typ, base)


def _openable(task: PlanningTask, obj: str) -> bool:
    return any(a.predicate == "openable" and a.args == (obj,) for a in task.init)
