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
from vap_bt.domain.roles import Roles
from vap_bt.robot.site_map import SiteMap
from vap_bt.robot.state import RobotState
from vap_bt.scene.builder import SceneGraphBuilder, SweepRecord


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


def map_facts(site_map: SiteMap, roles: Roles) -> set[Atom]:
    """Rigid facts and where the map's fixed things are."""
    facts = set(site_map.facts)
    in_room = roles.in_room
    if in_room is None:
        return facts
    for r in site_map.rooms:
        facts.add(Atom(in_room, (r.floor, r.name)))
    for f in site_map.furniture:
        facts.add(Atom(in_room, (f.name, f.room)))
    for d in site_map.doors:
        facts |= {Atom(in_room, (d.name, r)) for r in d.rooms}
    return facts


def robot_facts(state: RobotState, sweep: SweepRecord | None, site_map: SiteMap, roles: Roles) -> set[Atom]:
    """Localization's room; what the robot stands at (what its last view looked at), and whether it
    sees that (the domain's predicates of those roles; none for a role it lacks)."""
    facts = {Atom(roles.robot_in, (state.room,))} if state.room else set()
    if sweep is not None and sweep.last_view is not None and sweep.last_view.aim.names:
        target = sweep.last_view.aim.names[0]
        facts.add(Atom(roles.robot_at, (target,)))
        # in the domain's sense (find's effect): the robot is placed to act on what it went to look
        # at, and sees it — the floor it looked round, or a thing its last frame shows. Other
        # things in that frame are not: the domain's moves would never take such an inview back.
        shown = sweep.last_frame.detected() if sweep.last_frame is not None else frozenset()
        if target in shown or target in site_map.floors():
            facts.add(Atom(roles.in_view, (target,)))
    elif sweep is not None and state.room and (room := site_map.room(state.room)) is not None and room.floor:
        # a look round that reached no view (every way there blocked): the robot stands on its
        # room's floor, somewhere; believing it stands nowhere would leave the planner no move
        facts.add(Atom(roles.robot_at, (room.floor,)))
    return {a for a in facts if a.predicate is not None}


def hand_facts(state: RobotState, builder: SceneGraphBuilder) -> set[Atom]:
    """The gripper says whether it holds something; what it holds is the item seen held."""
    roles = builder.roles
    if state.gripper_holding is None:
        return set()
    if not state.gripper_holding:
        return {Atom(roles.hand_empty)} if roles.hand_empty is not None else set()
    held = [n for n in builder.evidence if roles.holding(n) in builder.observed(n)]
    return {roles.holding(held[0])} if held else set()


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
        roles = builder.roles
        said = {a for a in prior if a.predicate in builder.geometric and a.args and a.args[0] == o}
        if not said:
            facts |= seen
            continue
        said |= {a for a in seen if a.predicate != roles.in_room}  # what blocks it, or is blocked by it
        for a in list(said):  # "the cup is in the cabinet" puts the cup in the cabinet's room
            piece = builder.site_map.piece(a.args[1]) if a.predicate in roles.support else None
            room = piece.room if piece else builder.site_map.floors().get(a.args[1]) if len(a.args) > 1 else None
            if room is not None and roles.in_room is not None and not any(x.predicate == roles.in_room for x in said):
                said.add(Atom(roles.in_room, (o, room)))
        facts |= said
        if said:
            from_prior.add(o)
    return facts, from_prior


def closed_world_defaults(facts: set[Atom], site_map: SiteMap, objects: dict[str, str],
                          knowledge: DomainKnowledge, roles: Roles) -> set[Atom]:
    """What follows when nobody said otherwise: an openable thing not believed open is closed; a
    container that cannot be closed (a basket) is open; an item nothing is believed to block is
    reachable."""
    out = set()
    r = roles
    if r.reachable in knowledge.predicates and r.blocking in knowledge.predicates:
        blocked = {a.args[1] for a in facts if a.predicate == r.blocking}
        sig = knowledge.predicates[r.reachable][0]
        out |= {Atom(r.reachable, (x,)) for x, t in objects.items() if knowledge.is_subtype(t, sig)
                and x not in blocked and site_map.piece(x) is None}
    if r.open not in knowledge.predicates or r.closed not in knowledge.predicates:
        return out
    for x in objects:
        opened, closed = Atom(r.open, (x,)), Atom(r.closed, (x,))
        if opened in facts or closed in facts:
            continue
        if Atom(r.openable, (x,)) in site_map.facts:
            out.add(closed)
        elif r.container is not None and knowledge.is_subtype(objects[x], r.container) and site_map.piece(x) is not None:
            out.add(opened)
    return out
