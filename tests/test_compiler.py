"""The plan → tree compiler builds exactly the tree DESIGN.md draws."""

from __future__ import annotations

import py_trees
import pytest

from vap_bt.bt.active_perception import ActivePerception
from vap_bt.bt.apply_effects import ApplyEffects
from vap_bt.bt.execute_skill import ExecuteSkill
from vap_bt.bt.feel_hand import FeelHand
from vap_bt.bt.goal_check import GoalCheck
from vap_bt.bt.verify_predicate import VerifyPredicate

from conftest import household_profile, tree_for


def checks(seq: py_trees.composites.Sequence) -> list[str]:
    """The atoms a phase asks the camera about (the gripper's word, last of an effect phase, aside)."""
    out = []
    for node in seq.children:
        if isinstance(node, FeelHand):
            assert node is seq.children[-1] and seq.name == "eff"
            continue
        assert isinstance(node, ActivePerception) and isinstance(node.decorated, VerifyPredicate)
        out.append(node.decorated.name)
    return out


def test_the_gripper_is_asked_after_every_action_that_leaves_something_in_the_hand(cup):
    task, actions = cup
    root = tree_for(task, actions, "both")
    felt = [any(isinstance(c, FeelHand) for c in step.children[-1].children) for step in root.children[:-2]]
    grasp = next(i for i, a in enumerate(actions) if a.name == "grasp")
    place = next(i for i, a in enumerate(actions) if a.name.startswith("place"))
    assert felt == [grasp <= i < place for i in range(len(actions))]


def test_tree_shape_for_both(cup):
    task, actions = cup
    root = tree_for(task, actions, "both")
    assert isinstance(root, py_trees.composites.Sequence) and root.memory and root.name == "plan"
    assert [c.name for c in root.children[:-2]] == [f"a{i}: {a}" for i, a in enumerate(actions)]
    assert isinstance(root.children[-1], GoalCheck)
    assert root.children[-2].name == "goal" and checks(root.children[-2]) == ["on(cup, counter)"]
    for step, action in zip(root.children[:-2], actions):
        assert step.memory
        kinds = [type(c) for c in step.children]
        # a phase with nothing to check is left out (find: no precondition the camera judges)
        has_pre = any(household_profile().unchecked_reason(l.atom) is None for l in action.preconditions)
        assert kinds == [py_trees.composites.Sequence] * has_pre + [
            ExecuteSkill, ApplyEffects, py_trees.composites.Sequence]
        assert [c.name for c in step.children if isinstance(c, py_trees.composites.Sequence)] == (
            ["pre"] * has_pre + ["eff"])
    assert any(a.name == "find" for a in actions), "the plan should hold an action without checked preconditions"
    assert not all(isinstance(s.children[0], py_trees.composites.Sequence) for s in root.children[:-2])


def test_grasp_checks_what_the_camera_can_judge(cup):
    task, actions = cup
    root = tree_for(task, actions, "both")
    i = next(i for i, a in enumerate(actions) if a.name == "grasp")
    step = root.children[i]
    # in_room is map knowledge and never asked; the rest of grasp's preconditions are
    assert sorted(checks(step.children[0])) == sorted(
        ["inview(cup)", "hand_empty", "reachable(cup)", "on(cup, coffee_table)"])
    assert checks(step.children[3]) == ["holding(cup)"]


@pytest.mark.parametrize("mode,names", [
    ("pre", ["pre", None, None]),
    ("eff", [None, None, "eff"]),
    ("none", [None, None]),
])
def test_modes_drop_whole_phases(cup, mode, names):
    task, actions = cup
    root = tree_for(task, actions, mode)
    step = root.children[1]
    got = [c.name if isinstance(c, py_trees.composites.Sequence) else None for c in step.children]
    assert got == names
    # the goal is looked at again only where effects are
    assert (root.children[-2].name == "goal") == ("eff" in names)
