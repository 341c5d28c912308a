"""The scene graph as the live view draws it (vap_bt/viz/scene_graph.py): readable by construction.

A belief with rooms, furniture, items on and in things, a held item, a door in two rooms and
facts about nothing is drawn, and the drawing is checked the way a person would look at it: no
two labels overlap, every fact is shown once (a location as a labelled edge, a room by grouping,
a property in its object's label), and what rests on a thing hangs from it.
"""

from __future__ import annotations

import itertools
import re

import pytest

pytest.importorskip("rerun")

from vap_bt.domain.atoms import Atom  # noqa: E402
from vap_bt.scene.graph import SceneGraph  # noqa: E402
from vap_bt.viz.scene_graph import ROBOT, draw, labelled  # noqa: E402
from vap_bt.viz.tree_graph import size_of  # noqa: E402

FACTS = """in_room(counter, kitchen) in_room(cabinet, kitchen) in_room(cup, kitchen) inside(cup, cabinet)
on(kettle, counter) in_room(kettle, kitchen) on(lid, kettle) in_room(sofa, living_room)
in_room(door_lk, kitchen) in_room(door_lk, living_room) closed(cabinet) openable(cabinet) clear(counter)
holding(knife) robot_in(kitchen) hand_empty in_room(stray, hallway) connected(kitchen, living_room)"""


def belief() -> SceneGraph:
    return SceneGraph.of_facts({Atom.parse(a) for a in re.findall(r"\w+\([^)]*\)|\w+", FACTS)})


def boxes(d):
    return {i: (x - size_of(l)[0] / 2, y - size_of(l)[1] / 2, x + size_of(l)[0] / 2, y + size_of(l)[1] / 2)
            for i, l, (x, y) in zip(d.ids, d.labels, d.positions)}


def test_no_two_labels_overlap():
    d = draw(belief())
    assert len(set(d.ids)) == len(d.ids)
    for (a, p), (b, q) in itertools.combinations(boxes(d).items(), 2):
        apart = p[2] <= q[0] or q[2] <= p[0] or p[3] <= q[1] or q[3] <= p[1]
        assert apart, f"{a} and {b} overlap: {p} {q}"
    x0, y0, x1, y1 = d.bounds(margin=0)
    assert all(x0 <= b[0] and b[2] <= x1 + 1e-9 and y0 <= b[1] and b[3] <= y1 + 1e-9 for b in boxes(d).values())


def test_what_rests_on_a_thing_hangs_from_it_by_a_labelled_edge():
    d = draw(belief())
    edges = set(d.edges)
    label = dict(zip(d.ids, d.labels))
    for atom, thing, support in [("inside(cup, cabinet)", "cup", "cabinet"), ("on(kettle, counter)", "kettle", "counter"),
                                 ("on(lid, kettle)", "lid", "kettle")]:
        assert {(support, atom), (atom, thing)} <= edges and label[atom] == atom.split("(")[0]
    # a thing hangs to the right of its support, on a row of its own
    pos = dict(zip(d.ids, d.positions))
    assert pos["cup"][0] > pos["cabinet"][0] and pos["lid"][0] > pos["kettle"][0] > pos["counter"][0]
    # the room groups what it holds: an unlabelled edge (in_room needs no label), rooms leftmost
    assert ("kitchen", "counter") in edges and pos["kitchen"][0] < pos["counter"][0]
    assert {pos[r][0] for r in ("kitchen", "living_room", "hallway")} == {min(x for x, _ in d.positions)}
    # the robot is in its room, holding the knife; the fact about nothing is in its label
    assert {("kitchen", "robot_in(kitchen)"), ("robot_in(kitchen)", ROBOT), (ROBOT, "holding(knife)"),
            ("holding(knife)", "knife")} <= edges
    assert label[ROBOT] == "robot\n[hand_empty]"
    # properties are in their object's label
    assert label["cabinet"] == "cabinet\n[closed, openable]" and label["counter"] == "counter\n[clear]"
    # long lists wrap under the name, no line wider than the name or 18 characters
    wrapped = labelled("cup", ["fillable", "filled", "heated", "reachable"])
    assert wrapped == "cup\n[fillable, filled,\nheated, reachable]" and max(map(len, wrapped.split("\n"))) <= 18


def test_every_fact_is_shown_once():
    g = belief()
    d = draw(g)
    edges, ids = set(d.edges), set(d.ids)
    up = {b: a for a, b in edges}  # each node's parent in the drawing

    def above(node: str) -> list[str]:
        out = []
        while node in up and up[node] not in out:
            node = up[node]
            out.append(node)
        return out

    shown = 0
    for a in g.facts:
        if len(a.args) == 2 and a.predicate == "in_room":  # by grouping (here or higher up), or a node
            shown += (a.args[1] in above(a.args[0])) != (str(a) in ids)
        elif len(a.args) == 2 or a.predicate in ("holding", "robot_in"):
            shown += str(a) in ids
        else:
            label = dict(zip(d.ids, d.labels))[a.args[0] if a.args else ROBOT]
            shown += a.predicate in label
    assert shown == len(g.facts)
    # the cup in a cabinet in the kitchen: its in_room is said by the grouping, not again
    assert "in_room(cup, kitchen)" not in ids and "kitchen" in above("cup")
    # the door in two rooms: grouped under one, linked to the other by a labelled node
    assert ("kitchen", "door_lk") in edges and ("in_room(door_lk, living_room)" in ids)
    assert {("kitchen", "connected(kitchen, living_room)"), ("connected(kitchen, living_room)", "living_room")} <= edges


def test_a_cycle_in_belief_is_drawn_not_followed():
    g = SceneGraph.of_facts({Atom.parse("on(a, b)"), Atom.parse("on(b, a)"), Atom.parse("in_room(a, kitchen)")})
    d = draw(g)
    assert {"a", "b", "kitchen"} <= set(d.ids) and len(set(d.ids)) == len(d.ids)
