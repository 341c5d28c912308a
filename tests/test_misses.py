"""Where a check found an item missing: a sighting there is not taken as finding it.

gather_kindling seed 1: a false positive labelled "stick" on the living-room floor, the same in
every re-survey (the same views give the same pictures), was taken for stick2 eight times while
the real one lay in the garden; the replanning budget ran out.
"""

from __future__ import annotations

from types import SimpleNamespace

from vap_bt.bt.context import Situation
from vap_bt.bt.executive import Executive
from vap_bt.domain.atoms import Atom
from vap_bt.domain.roles import HOUSEHOLD
from vap_bt.scene.graph import SceneGraph, SceneObject
from vap_bt.scene.misses import MISS_RADIUS, Misses
from vap_bt.scene.moves import SightingMoves

ON_FLOOR = Atom("on", ("stick2", "floor_living_room"))
SPOT = (2.04, 1.51, 0.02)


def test_a_spot_where_an_item_was_missed_holds_for_that_item_until_it_is_held():
    m = Misses()
    m.note("stick2", SPOT)
    assert m.at("stick2", (2.04 + 0.8 * MISS_RADIUS, 1.51, 0.05))  # the same false positive, seen again
    assert not m.at("stick2", (2.04 + 1.2 * MISS_RADIUS, 1.51, 0.02))  # a thing beside it
    assert not m.at("stick1", SPOT) and not m.at("stick2", None)
    m.clear("stick2")
    assert not m.at("stick2", SPOT)


def executive_with(graph: SceneGraph) -> SimpleNamespace:
    """Just what :meth:`Executive._note_miss` reads of an executive."""
    return SimpleNamespace(misses=Misses(), moves=SightingMoves(), _portable=lambda name: name.startswith("stick"),
                           roles=HOUSEHOLD)


def measured(graph: SceneGraph, name: str, centroid) -> None:
    graph.objects[name] = SceneObject(name, "stick", "perceived", centroid=centroid,
                                      located=frozenset(graph.location(name)))


def test_a_check_that_does_not_find_an_item_where_it_was_measured_notes_the_spot():
    graph = SceneGraph.of_facts({ON_FLOOR})
    measured(graph, "stick2", SPOT)
    ex = executive_with(graph)
    Executive._note_miss(ex, graph, Situation("unseen", None, 0, Atom("inview", ("stick2",))))
    assert ex.misses.at("stick2", SPOT)


def test_a_confirmed_check_a_prior_place_or_a_stale_measurement_notes_nothing():
    graph = SceneGraph.of_facts({ON_FLOOR, Atom("on", ("stick1", "woodpile"))})
    ex = executive_with(graph)
    # the task file's word only: nothing measured, so nothing was missed where a frame put it
    Executive._note_miss(ex, graph, Situation("unseen", None, 0, Atom("on", ("stick1", "woodpile"))))
    measured(graph, "stick2", SPOT)
    Executive._note_miss(ex, graph, Situation("precondition", None, 0, ON_FLOOR, True, True))
    # an action carried it on: the centroid belongs to the place it left
    graph.facts = {Atom("on", ("stick2", "table"))}
    Executive._note_miss(ex, graph, Situation("effect", None, 0, Atom("on", ("stick2", "table")), True, False))
    assert ex.misses.spots == {}


def test_an_item_in_the_hand_is_missing_nowhere():
    graph = SceneGraph.of_facts({ON_FLOOR})
    measured(graph, "stick2", SPOT)
    ex = executive_with(graph)
    Executive._note_miss(ex, graph, Situation("unseen", None, 0, ON_FLOOR))
    graph.facts = {Atom("holding", ("stick2",))}
    Executive._note_miss(ex, graph, Situation("unseen", None, 0, Atom("inview", ("stick1",))))
    assert not ex.misses.at("stick2", SPOT)
