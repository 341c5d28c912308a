"""The plan → behaviour-tree compiler.

A plan ``[a0 … an-1]`` becomes the tree drawn in DESIGN.md — memory sequences throughout, so a
node that succeeded is not ticked again while a later one runs::

    Sequence "plan"
     ├─ Sequence "a0: grasp(cup, table, kitchen)"
     │   ├─ Sequence "pre"   ActivePerception(K) ─ VerifyPredicate(inview cup) …
     │   ├─ ExecuteSkill(grasp, cup, table, kitchen)
     │   ├─ ApplyEffects
     │   └─ Sequence "eff"   ActivePerception(K) ─ VerifyPredicate(holding cup) …
     ├─ …
     ├─ Sequence "goal"   ActivePerception(K) ─ VerifyPredicate(on cup counter) …
     └─ GoalCheck

Which atoms are checked: the preconditions (``pre``) and the add effects (``eff``, the paper's
Eff+) whose predicate the camera can judge (there are paraphrases for it) and that some action
can change (rigid facts are map knowledge). Before claiming success, the goal's atoms are looked
at once more (``goal``, with the effect checks): an effect confirmed minutes ago may have been
undone since (a bottle rolled off the counter). The verification mode removes whole phases:
``both``, ``pre``, ``eff`` (which includes ``goal``) or ``none``. A phase with nothing to check
(``find`` has no precondition the camera judges) is left out rather than compiled to an empty
sequence: an empty sequence does nothing in py_trees, clutters every view of the tree, and is a
load error in BehaviorTree.CPP ("must have 1 or more children").
"""

from __future__ import annotations

import py_trees

from vap_bt.bt.active_perception import ActivePerception
from vap_bt.bt.apply_effects import ApplyEffects
from vap_bt.bt.context import ExecutionContext, Phase
from vap_bt.bt.execute_skill import ExecuteSkill
from vap_bt.bt.goal_check import GoalCheck
from vap_bt.bt.verify_predicate import VerifyPredicate
from vap_bt.domain.atoms import Literal
from vap_bt.domain.knowledge import DomainKnowledge, GroundAction
from vap_bt.perception.prompts import verifiable


def checked(literals, knowledge: DomainKnowledge) -> list[Literal]:
    return [l for l in literals if verifiable(l.atom.predicate) and not knowledge.is_rigid(l.atom.predicate)]


def _checks(ctx: ExecutionContext, phase: Phase, literals: list[Literal], action: GroundAction | None,
            step: int) -> list[py_trees.composites.Sequence]:
    """The phase's check sequence, as a list of one — or none when there is nothing to check."""
    if not literals:
        return []
    return [py_trees.composites.Sequence(phase, memory=True, children=[
        ActivePerception(ctx, VerifyPredicate(ctx, l.atom, l.positive), phase, action, step) for l in literals])]


def compile_action(ctx: ExecutionContext, action: GroundAction, step: int,
                   knowledge: DomainKnowledge) -> py_trees.composites.Sequence:
    children: list[py_trees.behaviour.Behaviour] = []
    if ctx.mode.pre:
        children += _checks(ctx, "pre", checked(action.preconditions, knowledge), action, step)
    children += [ExecuteSkill(ctx, action, step), ApplyEffects(ctx, action)]
    if ctx.mode.eff:
        adds = [Literal(a) for a in sorted(action.add - action.pre_pos)]  # Eff+ that the action changes
        children += _checks(ctx, "eff", checked(adds, knowledge), action, step)
    return py_trees.composites.Sequence(f"a{step}: {action}", memory=True, children=children)


def compile_plan(ctx: ExecutionContext, plan: list[GroundAction], goal: tuple[Literal, ...],
                 knowledge: DomainKnowledge) -> py_trees.composites.Sequence:
    nodes = [compile_action(ctx, a, i, knowledge) for i, a in enumerate(plan)]
    if ctx.mode.eff:
        nodes += _checks(ctx, "goal", checked(goal, knowledge), None, len(plan))
    nodes.append(GoalCheck(ctx, goal, len(plan)))
    return py_trees.composites.Sequence("plan", memory=True, children=nodes)
