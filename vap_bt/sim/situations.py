"""Situation injection: the paper's Table II as data, and one seeded draw per action.

Each row is a situation the world may cause when an action runs: its kind, its probability, and
what it does, expressed so that every world can carry it out in its own terms:

* ``effect``  — whether the action's intended effects still happen (a navigation during which the
  held object falls still arrives; a grasp that fails does not hold anything);
* ``drops``   — which argument (by index), if any, ends up on the floor near the robot; ``"held"``
  means whatever the robot was holding.

The symbolic world applies this to ground facts; the pybullet world makes it physically so
(opens the gripper, lets the object fall). Table II's "N/A" rows (object not in view after
navigation, no free space) are not injected: they arise from the world itself.
"""

from __future__ import annotations

import random
from dataclasses import dataclass


@dataclass(frozen=True)
class SituationSpec:
    """One row of Table II: the ``kind`` of situation ``action`` may cause, with what ``probability``,
    whether its intended effects still happen, and what it ``drops``."""

    action: str
    kind: str
    probability: float
    effect: bool  # do the intended effects still happen?
    drops: int | str | None = None  # argument index, "held", or None


#: Table II of the paper (simulation experiments), row by row. ``takeout`` is grasping from an
#: open container and shares grasp's row; ``navigate`` between rooms shares find's.
TABLE_II: tuple[SituationSpec, ...] = (
    SituationSpec("find", "held_object_drops_during_navigation", 0.10, effect=True, drops="held"),
    SituationSpec("navigate", "held_object_drops_during_navigation", 0.10, effect=True, drops="held"),
    SituationSpec("grasp", "grasp_fails_object_unchanged", 0.25, effect=False),
    SituationSpec("grasp", "grasp_fails_object_drops_nearby", 0.25, effect=False, drops=0),
    SituationSpec("takeout", "grasp_fails_object_unchanged", 0.25, effect=False),
    SituationSpec("takeout", "grasp_fails_object_drops_nearby", 0.25, effect=False, drops=0),
    SituationSpec("placein", "place_fails_object_in_hand", 0.10, effect=False),
    SituationSpec("placein", "place_fails_object_drops_nearby", 0.10, effect=False, drops=0),
    SituationSpec("placeon", "place_fails_object_in_hand", 0.10, effect=False),
    SituationSpec("placeon", "place_fails_object_drops_nearby", 0.10, effect=False, drops=0),
    SituationSpec("fill", "container_not_fully_filled", 0.05, effect=False),
    SituationSpec("fill", "container_drops_nearby", 0.05, effect=False, drops=0),
    SituationSpec("open", "open_fails_object_closed", 0.10, effect=False),
    SituationSpec("close", "close_fails_object_open", 0.10, effect=False),
    SituationSpec("turnon", "turnon_fails_object_off", 0.10, effect=False),
    SituationSpec("cut", "cut_fails_knife_in_hand", 0.25, effect=False),
    SituationSpec("cut", "cut_fails_knife_drops_nearby", 0.25, effect=False, drops=1),
)


class SituationModel:
    """Draws at most one situation per executed action, from a seeded generator."""

    def __init__(self, table: tuple[SituationSpec, ...] = TABLE_II, enabled: bool = True, seed: int = 0) -> None:
        self.table, self.enabled = table, enabled
        self.rng = random.Random(seed)

    @classmethod
    def forced(cls, action: str, kind: str, seed: int = 0) -> SituationModel:
        """A model that always draws Table II's row ``kind`` for ``action`` (tests, fault drills)."""
        spec = next((s for s in TABLE_II if s.action == action and s.kind == kind), None)
        if spec is None:
            raise ValueError(f"Table II has no row {kind!r} for {action!r}")
        return cls(table=(SituationSpec(spec.action, spec.kind, 1.0, spec.effect, spec.drops),), seed=seed)

    def reseed(self, seed: int) -> None:
        """Restart the draws from ``seed`` (an episode's reset)."""
        self.rng = random.Random(seed)

    def draw(self, action: str) -> SituationSpec | None:
        """The situation ``action`` causes this time, or None. Takes one uniform draw per call, enabled
        or not, so that each action's draws stay the same whatever rows are on."""
        # one uniform draw per action, always taken, so that enabling or disabling rows of one
        # action does not shift the random stream of the others
        u = self.rng.random()
        if not self.enabled:
            return None
        acc = 0.0
        for spec in self.table:
            if spec.action == action:
                acc += spec.probability
                if u < acc:
                    return spec
        return None

    def describe(self) -> list[dict]:
        """The enabled rows (action, kind, probability), for the report; empty when injection is off."""
        return [{"action": s.action, "kind": s.kind, "p": s.probability} for s in self.table] if self.enabled else []
