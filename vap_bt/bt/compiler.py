"""The plan → behaviour-tree compiler.

A plan ``[a0 … an-1]`` becomes the tree drawn in DESIGN.md — memory sequences throughout, so a
node that succeeded is not ticked again while a later one runs::

    Sequence "plan"
     ├─ Sequence "a0: grasp(cup, table, kitchen)"
     │   ├─ Sequence "pre"   ActivePerception(K) ─ VerifyPredicate(inview cup) …
     │   ├─ ExecuteSkill(grasp, cup, table, kitchen)
     │   ├─ ApplyEffects
     │   └─ Sequence "eff"   ActivePerception(K) ─ VerifyPredicate(holding cup) … ─ FeelHand
     ├─ …
     ├─ Sequence "goal"   ActivePerception(K) ─ VerifyPredicate(on cup counter) …
     └─ GoalCheck

Which atoms are checked is decided from the states the plan expects
(:mod:`vap_bt.domain.expectation`: the belief the tree is compiled from, then each action applied
in turn): before an action, the precondition literals that hold it in the expected state (all of
a conjunction; of a disjunction, the disjunct believed true); after it, the state difference it
makes there — every atom it adds (the paper's Eff+, conditional effects included where their
conditions are expected to hold) and the deleted atoms the rest of the plan needs false. Of
those, the camera is asked about the atoms whose predicate the domain's perception profile
(:mod:`vap_bt.perception.profile`) sources from the VLM; every other atom — proprioception's,
the map's (rigid facts, by default), or never checked — is recorded on the board as unchecked,
with the profile's reason, for the report. After an action that leaves belief holding something,
the gripper is asked whether it still does (:class:`~vap_bt.bt.feel_hand.FeelHand`, the effect
phase's last node: proprioception, no question to the camera). Before claiming success, the goal's
atoms are looked at once more (``goal``, with the effect checks) under every protocol — the lean
protocol's reuse of an unchanged value never settles a goal check: an effect confirmed minutes
ago may have been undone since (a bottle rolled off the counter), and success is claimed on what
the goal check saw (``GoalCheck`` records what each goal atom rests on).

The verification strategy (:mod:`vap_bt.strategy`) says which of those a tree has: ``both``,
``pre``, ``eff`` (which includes ``goal``) or ``none`` remove whole phases; ``ok_robot`` has the
phases of ``both``, made by checks that ask once (the context sets their settings so: one
paraphrase, no budget, no sufficiency question). The action-level baselines put one
:class:`~vap_bt.bt.action_check.VerifyAction` in the ``pre`` phase (AffordanceVQA) or the
``eff`` phase (SuccessVQA), implying the atoms that phase's predicate checks would ask about;
they check no goal atom, and their tree claims the goal once the plan is through. A phase
with nothing to check (``find`` has no precondition the camera judges) is left out rather than
compiled to an empty sequence: an empty sequence does nothing in py_trees, clutters every view of
the tree, and is a load error in BehaviorTree.CPP ("must have 1 or more children").
"""

from __future__ import annotations

import py_trees

from vap_bt.bt.action_check import VerifyAction
from vap_bt.bt.active_perception import ActivePerception
from vap_bt.bt.apply_effects import ApplyEffects
from vap_bt.bt.context import ExecutionContext, Phase, Unchecked
from vap_bt.bt.execute_skill import ExecuteSkill
from vap_bt.bt.feel_hand import FeelHand
from vap_bt.bt.goal_check import GoalCheck
from vap_bt.bt.verify_predicate import VerifyPredicate
from vap_bt.domain.atoms import Literal
from vap_bt.domain.expectation import StepExpectation, expect
from vap_bt.domain.knowledge import DomainKnowledge, GroundAction
from vap_bt.perception.profile import PerceptionProfile, resolve


def profile_of(ctx: ExecutionContext, knowledge: DomainKnowledge) -> PerceptionProfile:
    """The context's perception profile; the domain's own (read once) when it has none."""
    if ctx.profile is None:
        ctx.profile = resolve(knowledge)
    return ctx.profile


def _asked(ctx: ExecutionContext, phase: Phase, literals, action: GroundAction | None,
           knowledge: DomainKnowledge) -> list[Literal]:
    """The literals of ``literals`` the camera is asked about; the rest go on the board as
    unchecked, with the profile's reason."""
    profile = profile_of(ctx, knowledge)
    asked = []
    for l in literals:
        reason = profile.unchecked_reason(l.atom)
        if reason is None:
            asked.append(l)
        else:
            name = str(action) if action else "goal"
            ctx.board.unchecked.setdefault((phase, name, l), Unchecked(phase, name, l.atom, l.positive, reason))
    return asked


def _checks(ctx: ExecutionContext, phase: Phase, literals, action: GroundAction | None, step: int,
            knowledge: DomainKnowledge) -> list[py_trees.composites.Sequence]:
    """The phase's check sequence, as a list of one — or none when there is nothing to check."""
    asked = _asked(ctx, phase, literals, action, knowledge)
    if not asked:
        return []
    return [py_trees.composites.Sequence(phase, memory=True, children=[
        ActivePerception(ctx, VerifyPredicate(ctx, l.atom, l.positive), phase, action, step) for l in asked])]


def _action_check(ctx: ExecutionContext, phase: Phase, literals, action: GroundAction, step: int,
                  knowledge: DomainKnowledge) -> list[py_trees.composites.Sequence]:
    """The phase's action-level question, implying the atoms its predicate checks would ask
    about (the positive ones: :mod:`vap_bt.bt.action_check`), as a list of one — or none when it
    would imply nothing the camera sees."""
    implied = tuple(l.atom for l in _asked(ctx, phase, literals, action, knowledge) if l.positive)
    if not implied:
        return []
    question = VerifyAction(ctx, phase, action, step, implied)
    return [py_trees.composites.Sequence(phase, memory=True, children=[question])]


def compile_action(ctx: ExecutionContext, action: GroundAction, step: int, knowledge: DomainKnowledge,
                   expected: StepExpectation | None = None) -> py_trees.composites.Sequence:
    """One plan step; ``expected`` is what the plan expects of it (default: the action applied to
    the current belief)."""
    expected = expected or expect(ctx.graph.state(), [action])[0]
    children: list[py_trees.behaviour.Behaviour] = []
    strategy = ctx.strategy
    if strategy.pre:
        children += _checks(ctx, "pre", expected.support, action, step, knowledge)
    if strategy.affordance:
        children += _action_check(ctx, "pre", expected.support, action, step, knowledge)
    children += [ExecuteSkill(ctx, action, step), ApplyEffects(ctx, action, expected.diff)]
    if strategy.success:
        children += _action_check(ctx, "eff", expected.effects, action, step, knowledge)
    if strategy.eff:
        eff = _checks(ctx, "eff", expected.effects, action, step, knowledge)
        after = (expected.before - expected.diff.deleted) | expected.diff.added
        if any(profile_of(ctx, knowledge).roles.is_held(a) for a in after):
            if not eff:
                eff = [py_trees.composites.Sequence("eff", memory=True)]
            eff[0].add_child(FeelHand(ctx, action, step))
        children += eff
    return py_trees.composites.Sequence(f"a{step}: {action}", memory=True, children=children)


def compile_plan(ctx: ExecutionContext, plan: list[GroundAction], goal: tuple[Literal, ...],
                 knowledge: DomainKnowledge) -> py_trees.composites.Sequence:
    """The tree of ``plan`` drawn above: each action's checks, skill and effects, then (when effects are
    checked) the goal's checks, and :class:`GoalCheck` last. Which atoms are checked follows from the
    states the plan expects, starting from the belief in ``ctx.graph``."""
    steps = expect(ctx.graph.state(), plan, goal)
    nodes = [compile_action(ctx, a, i, knowledge, e) for i, (a, e) in enumerate(zip(plan, steps))]
    if ctx.strategy.eff:
        nodes += _checks(ctx, "goal", goal, None, len(plan), knowledge)
    nodes.append(GoalCheck(ctx, goal, len(plan), profile_of(ctx, knowledge)))
    return py_trees.composites.Sequence("plan", memory=True, children=nodes)
