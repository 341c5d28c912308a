"""FeelHand: the gripper's word after an action, and what it casts doubt on."""

from __future__ import annotations

from py_trees.common import Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.feel_hand import FeelHand
from vap_bt.domain.atoms import Atom
from vap_bt.perception.verification import Round
from vap_bt.scene.graph import SceneGraph
from vap_bt.taskfile import load

from conftest import TREES

SLICED = Atom("sliced", ("lemon",))


def after(action: tuple[str, tuple[str, ...]], held: str) -> ExecutionContext:
    """The context right after ``action`` ran, belief holding ``held``, the gripper empty, and one
    earlier view that judged the lemon sliced."""
    knowledge = load(TREES / "cut_lemon.yaml").planning.knowledge
    ctx = ExecutionContext(graph=SceneGraph.of_facts({Atom("holding", (held,)), SLICED}), vlm=None, camera=None,
                           skills=None, felt=lambda graph, atom: False)
    ctx.verified.saw(SLICED, [Round(view="f1", vote=True, consistent=True, sufficient=True)])
    node = FeelHand(ctx, knowledge.ground(*action), 3)
    node.tick_once()
    assert node.status == Status.FAILURE and ctx.situation.atom == Atom("holding", (held,))
    return ctx


def test_a_tool_lost_by_the_action_that_used_it_casts_doubt_on_the_actions_effects():
    """cut_lemon seed 1 with injection: the knife dropped mid-cut, one view said "sliced", one more
    at the goal agreed, and success was claimed on a whole lemon."""
    ctx = after(("cut", ("lemon", "knife")), "knife")
    assert SLICED in ctx.doubted and ctx.verified.views(SLICED) == []


def test_an_item_lost_on_the_way_casts_no_doubt_on_what_the_action_did_to_other_things():
    ctx = after(("find", ("counter", "lemon", "kitchen")), "knife")
    assert SLICED not in ctx.doubted and len(ctx.verified.views(SLICED)) == 1
