"""Where a sighting moved an item from: taken back when the checks there fail and the search
finds the item nowhere else.

boil_water seed 4 in pybullet (Table II injection, strategy both, at 0109f28): two takeouts of the
cup from the microwave slipped (the cup stayed inside); a look through the door read the cup as on
the counter beside it. Every check at the counter then could not see the cup, every re-survey
found it nowhere (the sweep does not look into the microwave), belief kept it on the counter, and
the same plan met the same check six times before the replanning budget ran out.
"""

from __future__ import annotations

from types import SimpleNamespace

from vap_bt.bt.context import Situation
from vap_bt.bt.executive import Executive
from vap_bt.domain.atoms import Atom
from vap_bt.domain.roles import HOUSEHOLD
from vap_bt.robot.site_map import FurnitureInfo, SiteMap
from vap_bt.scene.graph import SceneGraph, SceneObject
from vap_bt.scene.misses import Misses
from vap_bt.scene.moves import SightingMoves
from vap_bt.taskfile import load

from conftest import TREES

IN_ROOM = Atom("in_room", ("cup", "kitchen"))
IN_MICROWAVE = Atom("inside", ("cup", "microwave"))
ON_COUNTER = Atom("on", ("cup", "counter"))
SPOT = (4.1, 3.2, 0.93)  # where the look through the door measured the cup


def sighted_on_the_counter() -> tuple[SceneGraph, SimpleNamespace]:
    """Belief as boil_water seed 4 had it: the cup moved by a sighting from the microwave to the
    counter, and a check there that could not see it (its spot noted); an executive with just what
    :meth:`Executive._relocated` and :meth:`Executive._taken_back` read."""
    graph = SceneGraph.of_facts({IN_ROOM, IN_MICROWAVE}, roles=HOUSEHOLD)
    node = SceneObject("cup", "cup", "perceived", centroid=SPOT)
    ex = SimpleNamespace(moves=SightingMoves(), misses=Misses(), roles=HOUSEHOLD, sightings=SimpleNamespace(saw=lambda *a: None),
                         _seen_again=set(), builder=SimpleNamespace(node=lambda name: node),
                         _placed_anew=lambda name, held=(): False, progress=lambda line: None)
    Executive._relocated(ex, graph, "cup", {IN_ROOM, ON_COUNTER})
    assert graph.location("cup") == {IN_ROOM, ON_COUNTER}
    ex.misses.note("cup", SPOT)
    return graph, ex


def test_a_lost_item_found_nowhere_goes_back_to_where_it_was_before_the_sighting_moved_it():
    graph, ex = sighted_on_the_counter()
    assert Executive._taken_back(ex, graph, "cup", set())
    assert graph.location("cup") == {IN_ROOM, IN_MICROWAVE}
    # once: a second failed search does not go back again (the record is used up)
    assert not Executive._taken_back(ex, graph, "cup", set())


def test_nothing_is_taken_back_while_the_search_found_it_or_no_check_failed_there():
    graph, ex = sighted_on_the_counter()
    found = SimpleNamespace(**{**vars(ex), "_placed_anew": lambda name, held=(): True})
    assert not Executive._taken_back(found, graph, "cup", set())
    assert not Executive._taken_back(ex, graph, "cup", {"cup"})  # in the hand: the gripper's word
    ex.misses.clear("cup")  # no check found it missing at the sighting's spot
    assert not Executive._taken_back(ex, graph, "cup", set())
    assert graph.location("cup") == {IN_ROOM, ON_COUNTER}


def test_a_place_an_action_gave_it_since_is_not_taken_back():
    moves = SightingMoves()
    moves.note("cup", {IN_ROOM, IN_MICROWAVE}, {IN_ROOM, ON_COUNTER})
    # the robot put the cup in the sink since: the sighting's place is no longer belief's
    assert moves.taken_back("cup", {IN_ROOM, Atom("inside", ("cup", "kitchen_sink"))}) is None
    moves.note("cup", set(), {IN_ROOM, ON_COUNTER})  # first seen: nowhere to go back to
    assert moves.taken_back("cup", {IN_ROOM, ON_COUNTER}) is None


def test_a_place_a_check_could_not_find_it_at_before_the_sighting_is_not_taken_back():
    """boil_water seed 8 in pybullet: the cup, believed in the microwave after a placing that
    dropped it, could not be seen inside; the sighting that then put it on the floor was right, and
    a failed look there must not send belief back into the microwave."""
    graph = SceneGraph.of_facts({IN_ROOM, IN_MICROWAVE}, roles=HOUSEHOLD)
    ex = SimpleNamespace(moves=SightingMoves(), misses=Misses(), _portable=lambda name: True, roles=HOUSEHOLD)
    Executive._note_miss(ex, graph, Situation("unseen", None, 4, IN_MICROWAVE, True, None))
    ex.moves.note("cup", {IN_ROOM, IN_MICROWAVE}, {IN_ROOM, ON_COUNTER})
    assert ex.moves.taken_back("cup", {IN_ROOM, ON_COUNTER}) is None
    # once the hand has held it, the old doubt says nothing of where it is
    graph = SceneGraph.of_facts({Atom("holding", ("cup",))}, roles=HOUSEHOLD)
    Executive._note_miss(ex, graph, Situation("effect", None, 5, Atom("holding", ("cup",)), True, True))
    ex.moves.note("cup", {IN_ROOM, IN_MICROWAVE}, {IN_ROOM, ON_COUNTER})
    assert ex.moves.taken_back("cup", {IN_ROOM, ON_COUNTER}) == {IN_ROOM, IN_MICROWAVE}


def test_a_room_alone_is_no_place_to_go_back_to():
    """retrieve_bottles seed 2 in pybullet (6d85a15): a bottle the hand lost was believed only in
    the garden (no support) when a sighting put it on the floor; the checks there could not see
    it, and going back to "in the garden" left no plan reaching the goal (nothing to find it on)."""
    graph = SceneGraph.of_facts({IN_ROOM}, roles=HOUSEHOLD)
    _, ex = sighted_on_the_counter()
    ex.moves = SightingMoves()
    Executive._relocated(ex, graph, "cup", {IN_ROOM, ON_COUNTER})
    graph.objects["cup"] = SceneObject("cup", "cup", "perceived", centroid=SPOT)
    assert not Executive._taken_back(ex, graph, "cup", set())
    assert graph.location("cup") == {IN_ROOM, ON_COUNTER}


def test_a_place_the_skill_did_not_see_the_item_at_is_doubted_and_its_spot_is_a_miss():
    """heat_pie seed 29 in pybullet (Table II injection, both, at 5d15cea): the pie lost on the way
    out of the fridge lay on the floor where a sighting put it; two checks there could not settle,
    and each search then took it back into the fridge, where three take-outs' own looks did not see
    it: stuck. boil_water seed 23: a phantom cup in the empty cabinet was taken by every search,
    and three take-outs found it not there. A skill that looked where belief put the item and did
    not see it is a check that missed it there."""
    graph = SceneGraph.of_facts({IN_ROOM, IN_MICROWAVE}, roles=HOUSEHOLD)
    graph.objects["cup"] = SceneObject("cup", "cup", "perceived", centroid=SPOT,
                                       located=frozenset({IN_ROOM, IN_MICROWAVE}))
    ex = SimpleNamespace(moves=SightingMoves(), misses=Misses(), _portable=lambda name: True, roles=HOUSEHOLD)
    failed = Situation("execution", None, 3, detail="cup is not where it was believed to be: not seen")
    Executive._note_miss(ex, graph, failed)  # a failure that names nothing missing notes nothing
    assert not ex.moves.doubted and not ex.misses.at("cup", SPOT)
    Executive._note_miss(ex, graph, Situation("execution", None, 3, missing="cup"))
    assert ex.moves.doubted == {IN_MICROWAVE}  # the room is no place: only what it was in
    assert ex.misses.at("cup", SPOT)  # a sighting there again is not taken as finding it
    ex.moves.note("cup", {IN_ROOM, IN_MICROWAVE}, {IN_ROOM, ON_COUNTER})
    assert ex.moves.taken_back("cup", {IN_ROOM, ON_COUNTER}) is None


def let_go_in_the_oven(action: str = "placein", args=("apple_pie", "oven", "kitchen")):
    """heat_pie seed 29 in pybullet (Table II injection, both, at 02d7dce): the pie set into the
    oven, a look that judged it not inside, the gripper empty; an executive with just what
    :meth:`Executive._feel_hand`, :meth:`Executive._let_go` and :meth:`Executive._taken_back` read."""
    knowledge = load(TREES / "heat_pie.yaml").planning.knowledge
    ground = knowledge.ground(action, args)
    graph = SceneGraph.of_facts({Atom("holding", ("apple_pie",))}, roles=HOUSEHOLD)  # the placing undone
    ex = SimpleNamespace(moves=SightingMoves(), misses=Misses(), roles=HOUSEHOLD, progress=lambda line: None,
                         body=SimpleNamespace(state=lambda: SimpleNamespace(gripper_holding=False)),
                         sightings=SimpleNamespace(saw=lambda *a: None), _placed_anew=lambda name, held=(): False)
    ex._let_go = lambda g, s, name: Executive._let_go(ex, g, s, name)
    denied = Situation("effect", ground, 4, Atom("inside", ("apple_pie", "oven")), True, False)
    assert Executive._feel_hand(ex, graph, denied) == ["apple_pie"]
    assert graph.location("apple_pie") == set()  # placed nowhere: the plan had no pie to take
    return graph, ex


def test_an_item_the_hand_let_go_where_a_check_denied_it_is_believed_there_when_found_nowhere_else():
    graph, ex = let_go_in_the_oven()
    assert Executive._taken_back(ex, graph, "apple_pie", set())
    assert graph.location("apple_pie") == {Atom("inside", ("apple_pie", "oven")), Atom("in_room", ("apple_pie", "kitchen"))}
    graph.correct(Atom("inside", ("apple_pie", "oven")), False)  # denied again there: the record is used up
    assert not Executive._taken_back(ex, graph, "apple_pie", set())


def test_an_item_the_search_found_or_a_hand_that_put_nothing_down_takes_nothing_back():
    graph, ex = let_go_in_the_oven()
    ex._placed_anew = lambda name, held=(): True  # the search saw it somewhere: taken where it was seen
    assert not Executive._taken_back(ex, graph, "apple_pie", set()) and graph.location("apple_pie") == set()
    graph, ex = let_go_in_the_oven("grasp", ("apple_pie", "floor_kitchen", "kitchen"))
    assert not ex.moves.moves  # a grasp puts the pie nowhere: nothing to go back to
    assert not Executive._taken_back(ex, graph, "apple_pie", set())


def test_a_place_only_unsure_is_taken_back_once_a_skill_missed_the_item_where_the_sighting_put_it():
    """heat_pie seed 20 in pybullet (Table II injection, both, at 95df172): the pie stood in the
    fridge, which three checks could not see into; a sighting put it on the counter, and three
    grasps there did not see it. The checks' "could not make it out" in the fridge is a weaker
    doubt than the grasps' "not here" on the counter."""
    graph = SceneGraph.of_facts({IN_ROOM, IN_MICROWAVE}, roles=HOUSEHOLD)
    ex = SimpleNamespace(moves=SightingMoves(), misses=Misses(), _portable=lambda name: True, roles=HOUSEHOLD)
    Executive._note_miss(ex, graph, Situation("unseen", None, 4, IN_MICROWAVE, True, None))
    assert ex.moves.unsure == {IN_MICROWAVE} and not ex.moves.doubted
    graph = SceneGraph.of_facts({IN_ROOM, ON_COUNTER}, roles=HOUSEHOLD)  # the sighting's place
    ex.moves.note("cup", {IN_ROOM, IN_MICROWAVE}, {IN_ROOM, ON_COUNTER})
    # the checks on the counter could not make it out either: not yet, and the record is kept
    Executive._note_miss(ex, graph, Situation("unseen", None, 5, ON_COUNTER, True, None))
    assert ex.moves.taken_back("cup", {IN_ROOM, ON_COUNTER}) is None and "cup" in ex.moves.moves
    Executive._note_miss(ex, graph, Situation("execution", None, 6, missing="cup"))
    assert ex.moves.doubted == {ON_COUNTER}
    assert ex.moves.taken_back("cup", {IN_ROOM, ON_COUNTER}) == {IN_ROOM, IN_MICROWAVE}
    # a place a look said it is not at stays doubted, whatever the sighting's place had
    ex.moves.doubt(IN_MICROWAVE)
    ex.moves.note("cup", {IN_ROOM, IN_MICROWAVE}, {IN_ROOM, ON_COUNTER})
    assert ex.moves.taken_back("cup", {IN_ROOM, ON_COUNTER}) is None


def test_the_task_files_place_is_the_place_to_go_back_to_from_where_the_survey_put_an_item():
    """boil_water seed 20 in pybullet (Table II injection, both, at 0702075): the task file puts
    the cup inside the cabinet, the survey put it on the counter, and three grasps there did not
    see it; belief kept it there until stuck. The prior names no room: the cabinet's is taken."""
    site = SiteMap(rooms=(), furniture=(FurnitureInfo("cabinet", "cabinet", "container", "kitchen"),))
    ex = SimpleNamespace(prior=frozenset({Atom("inside", ("cup", "cabinet")), Atom("closed", ("cabinet",))}),
                         roles=HOUSEHOLD, builder=SimpleNamespace(site_map=site))
    assert Executive._told_place(ex, "cup") == {Atom("inside", ("cup", "cabinet")), IN_ROOM}
    assert Executive._told_place(ex, "mug") == set()  # the prior says nothing of it
