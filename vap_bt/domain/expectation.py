"""What a plan expects at each step: the state it meets, what holds the action's precondition
there, and the difference the action makes.

With conditional effects an action's effects depend on the state it runs in (moving a briefcase
moves what is inside it), and with disjunctive preconditions so does what needs to hold
(``(or (holding ?x) (on ?x ?table))``: whichever is true). The compiler therefore decides a tree's
checks from the states the plan expects: the belief the tree is compiled from, then each action's
:meth:`~vap_bt.domain.knowledge.GroundAction.apply` in turn — the same simulation the planner
validated the plan with.

Why at compile time and not when the action runs: the tree is then fixed before it is ticked —
exported to BehaviorTree.CPP, drawn in rerun with every check it will make, shaped as DESIGN.md
draws it — and it stays right. Between two compilations belief changes only through the tree's
own action-driven updates, which apply this same difference (:meth:`SceneGraph.apply
<vap_bt.scene.graph.SceneGraph.apply>`); any other change (a contradicted check corrected into
the graph) fails the tree, and the executive replans and compiles a new tree from the corrected
belief.

Per step:

* ``support`` — the precondition literals to verify before acting: all of a conjunctive
  precondition; for a disjunction, the disjunct the expected state makes true;
* ``diff`` — the atoms the action adds and the true atoms it deletes in the expected state;
* ``effects`` — what to verify after acting: every added atom, and the deleted atoms that matter,
  that is, those the rest of the plan needs false (a later precondition ``(not p)`` or a goal
  ``(not p)``, with nothing re-adding ``p`` before). Deleted atoms nothing relies on are left
  alone, as the paper verifies its Eff+ only.
"""

from __future__ import annotations

from dataclasses import dataclass

from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.knowledge import GroundAction, StateDiff


@dataclass(frozen=True)
class StepExpectation:
    """One plan step as the plan expects it."""

    action: GroundAction
    before: frozenset[Atom]
    support: tuple[Literal, ...]
    diff: StateDiff
    relied: frozenset[Atom]  # deleted atoms the rest of the plan needs false

    @property
    def effects(self) -> tuple[Literal, ...]:
        """What to verify after acting: each added atom, then each deleted atom that matters."""
        return (*(Literal(a) for a in sorted(self.diff.added)),
                *(Literal(a, False) for a in sorted(self.relied)))


def expect(start: frozenset[Atom], plan: list[GroundAction],
           goal: tuple[Literal, ...] = ()) -> list[StepExpectation]:
    """The expectation of every step of ``plan`` run from ``start`` towards ``goal``."""
    states = [frozenset(start)]
    for a in plan:
        states.append(a.apply(states[-1]))
    supports = [a.support(s) for a, s in zip(plan, states)]
    diffs = [a.diff(s) for a, s in zip(plan, states)]
    out = []
    for i, a in enumerate(plan):
        relied = frozenset(d for d in diffs[i].deleted if _needed_false(d, i, states, supports, goal))
        out.append(StepExpectation(a, states[i], supports[i], diffs[i], relied))
    return out


def _needed_false(atom: Atom, step: int, states, supports, goal) -> bool:
    """Does a later step (or the goal) need ``atom`` false before something makes it true again?"""
    want = Literal(atom, False)
    for j in range(step + 1, len(states)):
        if atom in states[j]:
            return False  # re-added first: this deletion is not what a later step relies on
        if j < len(supports) and want in supports[j]:
            return True
    return want in goal


__all__ = ["StepExpectation", "expect"]
