"""The initial belief: what the robot takes to be true before its first action, and why.

Each fact of the first scene graph has one of four sources, in this order of authority:

1. **perception** — where the sweep saw each object (the builder's observed location), which
   room localization puts the robot in, what it stands at and sees in its last frame, and whether
   the gripper holds something;
2. **the VLM** — the state of what opens and closes, asked of the frames that showed it
   (:mod:`vap_bt.perception.state_survey`);
3. **the map** — rooms, doors and furniture and the rigid facts (``connects``, ``openable``, ...);
4. **the task file's prior** — what the user said and nobody has seen (the cup is in the closed
   cabinet; the door to the garden is shut). A prior may be wrong; perception overrides it, and
   verification catches what neither saw.

Anything none of them says is false (the closed-world assumption), except that a thing the map
knows cannot be closed is open. Nothing here reads the world: only frames, the robot's state,
the map, VLM answers and the task file.
"""

from __future__ import annotations

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import DomainKnowledge
from vap_bt.robot.site_map import SiteMap
from vap_bt.robot.state import RobotState
from vap_bt.scene.builder import GEOMETRIC_PREDICATES, SceneGraphBuilder, SweepRecord

#: what localization and the last frame establish about the robot itself
ROBOT_PREDICATES = frozenset({"robot_in", "robot_at", "inview"})
HAND_PREDICATES = frozenset({"holding", "hand_empty"})


def typed(atoms, knowledge: DomainKnowledge, objects: dict[str, str]) -> set[Atom]:
    """The atoms that fit the domain: a known predicate over objects of the right types."""
    out = set()
    for a in atoms:
        sig = knowledge.predicates.get(a.predicate)
        if sig is None or len(sig) != len(a.args):
            continue
        if all(x in objects and knowledge.is_subtype(objects[x], t) for x, t in zip(a.args, sig)):
            out.add(a)
    return out


def map_facts(site_map: SiteMap) -> set[Atom]:
    """Rigid facts and where the map's fixed things are."""
    facts = set(site_map.facts)
    for r in site_map.rooms:
        facts.add(Atom("in_room", (r.floor, r.name)))
    for f in site_map.furniture:
        facts.add(Atom("in_room", (f.name, f.room)))
    for d in site_map.doors:
        facts |= {Atom("in_room", (d.name, r)) for r in d.rooms}
    return facts


def robot_facts(state: RobotState, sweep: SweepRecord | None, site_map: SiteMap) -> set[Atom]:
    """Localization's room; what the robot stands at (what its last view looked at), and whether it
    sees that."""
    facts = {Atom("robot_in", (state.room,))} if state.room else set()
    if sweep is not None and sweep.last_view is not None and sweep.last_view.aim.names:
        target = sweep.last_view.aim.names[0]
        facts.add(Atom("robot_at", (target,)))
        # in the domain's sense (find's effect): the robot is placed to act on what it went to look
        # at, and sees it — the floor it looked round, or a thing its last frame shows. Other
        # things in that frame are not: the domain's moves would never take such an inview back.
        shown = sweep.last_frame.detected() if sweep.last_frame is not None else frozenset()
        if target in shown or target in site_map.floors():
            facts.add(Atom("inview", (target,)))
    elif sweep is not None and state.room and (room := site_map.room(state.room)) is not None and room.floor:
        # a look round that reached no view (every way there blocked): the robot stands on its
        # room's floor, somewhere; believing it stands nowhere would leave the planner no move
        facts.add(Atom("robot_at", (room.floor,)))
    return facts


def hand_facts(state: RobotState, builder: SceneGraphBuilder) -> set[Atom]:
    """The gripper says whether it holds something; what it holds is the item seen held."""
    if state.gripper_holding is None:
        return set()
    if not state.gripper_holding:
        return {Atom("hand_empty")}
    held = [n for n in builder.evidence if Atom("holding", (n,)) in builder.observed(n)]
    return {Atom("holding", (held[0],))} if held else set()


def item_facts(builder: SceneGraphBuilder, items: list[str], prior: set[Atom]) -> tuple[set[Atom], set[str]]:
    """Where each item is: as observed when the frames put it somewhere, else as the prior says
    (with what the frames did see of it, its room say). Returns the facts and the items placed
    only by the prior."""
    facts, from_prior = set(), set()
    for o in items:
        seen = builder.observed(o)
        if builder.placed(o):
            facts |= seen
            continue
        said = {a for a in prior if a.predicate in GEOMETRIC_PREDICATES and a.args and a.args[0] == o}
        if not said:
            facts |= seen
            continue
        said |= {a for a in seen if a.predicate != "in_room"}  # what blocks it, or is blocked by it
        for a in list(said):  # "the cup is in the cabinet" puts the cup in the cabinet's room
            piece = builder.site_map.piece(a.args[1]) if a.predicate in ("on", "inside") else None
            room = piece.room if piece else builder.site_map.floors().get(a.args[1]) if len(a.args) > 1 else None
            if room is not None and not any(x.predicate == "in_room" for x in said):
                said.add(Atom("in_room", (o, room)))
        facts |= said
        if said:
            from_prior.add(o)
    return facts, from_prior


def closed_world_defaults(facts: set[Atom], site_map: SiteMap, objects: dict[str, str],
                          knowledge: DomainKnowledge) -> set[Atom]:
    """What follows when nobody said otherwise: an openable thing not believed open is closed; a
    container that cannot be closed (a basket) is open; an item nothing is believed to block is
    reachable."""
    out = set()
    if {"reachable", "blocking"} <= set(knowledge.predicates):
        blocked = {a.args[1] for a in facts if a.predicate == "blocking"}
        sig = knowledge.predicates["reachable"][0]
        out |= {Atom("reachable", (x,)) for x, t in objects.items() if knowledge.is_subtype(t, sig)
                and x not in blocked and site_map.piece(x) is None}
    if not {"open", "closed"} <= set(knowledge.predicates):
        return out
    for x in objects:
        opened, closed = Atom("open", (x,)), Atom("closed", (x,))
        if opened in facts or closed in facts:
            continue
        if Atom("openable", (x,)) in site_map.facts:
            out.add(closed)
        elif any(knowledge.is_subtype(objects[x], t) for t in ("container",)) and site_map.piece(x) is not None:
            out.add(opened)
    return out
