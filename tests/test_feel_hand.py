"""FeelHand: the gripper's word after an action, what it takes back, and what the hand
holds when the fingers feel something belief does not."""

from __future__ import annotations

import time

from py_trees.common import Status

from vap_bt.bt.context import ExecutionContext, Situation
from vap_bt.bt.executive import Executive, last_taken_from_hand
from vap_bt.bt.feel_hand import FeelHand
from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import GroundAction
from vap_bt.perception.verification import Round
from vap_bt.scene.graph import SceneGraph
from vap_bt.taskfile import load

from conftest import TREES

SLICED = Atom("sliced", ("lemon",))


def after(action: tuple[str, tuple[str, ...]], held: str) -> tuple[ExecutionContext, GroundAction]:
    """The context right after ``action`` ran, belief holding ``held``, the gripper empty, and one
    earlier view that judged the lemon sliced."""
    knowledge = load(TREES / "cut_lemon.yaml").planning.knowledge
    ctx = ExecutionContext(graph=SceneGraph.of_facts({Atom("holding", (held,)), SLICED}), vlm=None, camera=None,
                           skills=None, felt=lambda graph, atom: False)
    ctx.board.verified.saw(SLICED, [Round(view="f1", vote=True, consistent=True, sufficient=True)])
    ground = knowledge.ground(*action)
    node = FeelHand(ctx, ground, 3)
    for _ in range(500):  # the gripper is asked on a worker: tick until it has answered
        node.tick_once()
        if node.status != Status.RUNNING:
            break
        time.sleep(0.001)
    ctx.close()
    assert node.status == Status.FAILURE and ctx.board.situation.atom == Atom("holding", (held,))
    assert ctx.board.situation.kind == "effect" and ctx.board.situation.observed is False
    return ctx, ground


def test_a_tool_lost_by_the_action_that_used_it_names_the_action_to_be_done_again():
    """cut_lemon seed 0 with injection: the knife fell before the stroke, the views after the cut
    said "not sliced", two more at the goal from nearly one spot said "sliced", and success was
    claimed on a whole lemon. The situation names the cut: belief takes it back (the executive
    undoes an effect situation's action) and the replan cuts again, from the cut on."""
    ctx, cut = after(("cut", ("lemon", "knife")), "knife")
    assert ctx.board.situation.action == cut and ctx.board.situation.step == 3
    assert ctx.board.verified.views(SLICED) == [] and not ctx.board.doubted


def test_an_item_lost_on_the_way_leaves_what_the_action_did_to_other_things():
    ctx, _ = after(("find", ("counter", "lemon", "kitchen")), "knife")
    assert ctx.board.situation.action is None and ctx.board.situation.step == 4 and len(ctx.board.verified.views(SLICED)) == 1


def test_an_item_lost_while_carried_somewhere_leaves_the_robot_where_it_got():
    """The knife, held and named as what the robot stood at, fell while the base drove: the
    robot is in the kitchen all the same (a navigation is not taken back)."""
    ctx, _ = after(("navigate", ("living_room", "kitchen", "door_lk", "knife")), "knife")
    assert ctx.board.situation.action is None and ctx.board.situation.step == 4 and len(ctx.board.verified.views(SLICED)) == 1


# -- the gripper holds something belief does not (Executive._held_after_all) ------------------

LOG = Atom("holding", ("wood1",))
ON_HEARTH = Atom("on", ("wood1", "hearth"))


def grasped_then_denied() -> tuple[SceneGraph, GroundAction, Situation]:
    """store_firewood seed 4: the grasp took the log, a view judged it not held; belief, as
    :meth:`Executive._correct` leaves it, has the grasp undone and the log not held."""
    knowledge = load(TREES / "store_firewood.yaml").planning.knowledge
    grasp = knowledge.ground("grasp", ("wood1", "hearth", "living_room"))
    graph = SceneGraph.of_facts({ON_HEARTH, Atom("hand_empty"), Atom("robot_in", ("living_room",)),
                                 Atom("in_room", ("wood1", "living_room")), Atom("robot_at", ("wood1",)),
                                 Atom("reachable", ("wood1",)), Atom("inview", ("wood1",))}, tracks_hand=True)
    graph.apply(grasp)
    s = Situation("effect", grasp, 8, LOG, True, False)
    graph.undo(grasp)
    graph.correct(LOG, False)
    return graph, grasp, s


def test_a_grasp_a_view_judged_empty_handed_holds_what_the_fingers_closed_on():
    graph, _, s = grasped_then_denied()
    Executive._held_after_all(graph, s)
    assert LOG in graph.facts and ON_HEARTH not in graph.facts and Atom("hand_empty") not in graph.facts


def test_a_hand_judged_not_empty_holds_the_item_a_check_last_took_out_of_it():
    graph, _, _ = grasped_then_denied()  # the grasp undone: a view said it did not take
    assert last_taken_from_hand(graph) == "wood1"
    Executive._held_after_all(graph, Situation("precondition", None, 0, Atom("hand_empty"), True, False))
    assert LOG in graph.facts


def test_an_item_the_robot_put_down_is_not_taken_back_into_the_hand():
    graph, grasp, _ = grasped_then_denied()
    graph.apply(grasp)
    graph.correct(LOG, False, cause="gripper")  # the fingers felt it gone: not a view's say-so
    assert last_taken_from_hand(graph) is None
    Executive._held_after_all(graph, Situation("precondition", None, 0, Atom("hand_empty"), True, False))
    assert LOG not in graph.facts
