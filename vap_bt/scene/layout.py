"""Scene layouts: a compact, human-written description of a household and the facts it means.

Writing every ground atom of a house by hand is error-prone, so task files describe a scene the
way a person would — rooms, doors between them, furniture in rooms, items on or inside furniture
— and :func:`layout_facts` expands that into the domain's atoms, in the predicates its perception
profile names for each role (:mod:`vap_bt.domain.roles`; the household's by default): where each
thing is, the doors' ``connects`` both ways, ``openable``/``open``/``closed``, ``reachable``,
``blocking``, a floor per room for things that fall. The words of the layout itself (``place: on
table``, a door's ``state: open``) are the file's own, whatever the domain calls those relations.
The same layout names the objects a physical world must build.
"""

from __future__ import annotations

import re
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from vap_bt.domain.atoms import Atom
from vap_bt.domain.roles import Roles


def floor_of(room: str) -> str:
    """Every room has a floor surface; dropped things land there."""
    return f"floor_{room}"


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid")


class Door(_Strict):
    """A door between two rooms, and whether it starts open."""

    between: tuple[str, str]
    state: Literal["open", "closed"] = "open"


class Furniture(_Strict):
    """A piece of furniture in a room: a surface (things go on it), a container or appliance (things go
    inside), or a sink; whether it is open, for what opens, and whether its top starts clear."""

    type: Literal["surface", "container", "appliance", "sink"]
    room: str
    state: Literal["open", "closed"] | None = None  # only for things that open
    clear: bool = True


class Item(_Strict):
    """``place`` is ``"on <surface>"``, ``"inside <container>"`` or ``"held"``.

    (A ``place`` string rather than ``on:``/``inside:`` keys, because YAML 1.1 reads a bare
    ``on`` key as the boolean true.)"""

    type: Literal["item", "knife"] = "item"
    place: str
    fillable: bool = False
    blocked_by: list[str] = Field(default_factory=list)

    @model_validator(mode="after")
    def _place(self) -> "Item":
        words = self.place.split()
        if not (words == ["held"] or (len(words) == 2 and words[0] in ("on", "inside"))):
            raise ValueError(f"place must be 'on <surface>', 'inside <container>' or 'held', not {self.place!r}")
        return self

    @property
    def held(self) -> bool:
        """Whether the robot starts holding the item (``place: held``)."""
        return self.place == "held"

    @property
    def on(self) -> str | None:
        """What the item starts on (``place: on X``), else None."""
        w = self.place.split()
        return w[1] if w[0] == "on" else None

    @property
    def inside(self) -> str | None:
        """What the item starts inside (``place: inside X``), else None."""
        w = self.place.split()
        return w[1] if w[0] == "inside" else None


class Robot(_Strict):
    """Where the robot starts: its room, and what it stands at (default: the room's floor)."""

    room: str
    at: str | None = None  # what the robot stands at and looks at; default: its room's floor


class Layout(_Strict):
    """A household as a person describes it: rooms, doors, the robot, furniture and items. Reading one
    checks that every name it uses is one of its own and every place fits what goes there."""

    rooms: list[str]
    doors: dict[str, Door] = Field(default_factory=dict)
    robot: Robot
    furniture: dict[str, Furniture] = Field(default_factory=dict)
    items: dict[str, Item] = Field(default_factory=dict)

    @model_validator(mode="after")
    def _names(self) -> "Layout":
        _unique_pddl_names(self)
        rooms = set(self.rooms)
        for name, d in self.doors.items():
            for r in d.between:
                if r not in rooms:
                    raise ValueError(f"door {name!r}: unknown room {r!r}")
        for name, f in self.furniture.items():
            if f.room not in rooms:
                raise ValueError(f"furniture {name!r}: unknown room {f.room!r}")
        places = {**{floor_of(r): "surface" for r in rooms}, **{n: f.type for n, f in self.furniture.items()}}
        for name, it in self.items.items():
            if it.on is not None and places.get(it.on) != "surface":
                raise ValueError(f"item {name!r}: on: {it.on!r} is not a surface of this scene")
            if it.inside is not None and places.get(it.inside) not in ("container", "appliance"):
                raise ValueError(f"item {name!r}: inside: {it.inside!r} is not a container of this scene")
            for b in it.blocked_by:
                if b not in self.items:
                    raise ValueError(f"item {name!r}: blocked_by: unknown item {b!r}")
        if self.robot.room not in rooms:
            raise ValueError(f"robot: unknown room {self.robot.room!r}")
        return self

    def objects(self) -> dict[str, str]:
        """Object name -> PDDL type."""
        out = {r: "room" for r in self.rooms}
        out.update({floor_of(r): "surface" for r in self.rooms})
        out.update({d: "door" for d in self.doors})
        out.update({n: f.type for n, f in self.furniture.items()})
        out.update({n: i.type for n, i in self.items.items()})
        return out

    def room_of(self, name: str) -> str | None:
        """The room ``name`` starts in (a piece of furniture's, a floor's, an item's support's); None for a
        held item or a name that is none of these."""
        if name in self.furniture:
            return self.furniture[name].room
        for r in self.rooms:
            if name == floor_of(r):
                return r
        it = self.items.get(name)
        if it is None or it.held:
            return None
        return self.room_of(it.on or it.inside)


#: a name both PDDL and a goal's atoms read as written: PDDL ignores case, atoms are lower-cased
_NAME = re.compile(r"[a-z][a-z0-9_-]*")


def _unique_pddl_names(layout: Layout) -> None:
    """Every object of the scene has a name of its own that PDDL reads (else the generated problem
    fails to parse, and the parser's message points into text the user never wrote)."""
    kinds: dict[str, str] = {}
    for kind, names in (("room", set(layout.rooms)), ("floor", {floor_of(r) for r in layout.rooms}),
                        ("door", layout.doors), ("furniture", layout.furniture), ("item", layout.items)):
        for name in names:
            if not _NAME.fullmatch(name):
                raise ValueError(f"{kind} {name!r}: a name is lower-case letters, digits, _ and -, "
                                 "starting with a letter")
            if name in kinds:
                raise ValueError(f"{name!r} is the name of a {kinds[name]} already; the {kind} needs one of its own")
            kinds[name] = kind


def layout_facts(layout: Layout, roles: Roles | None = None) -> set[Atom]:
    """The ground atoms a layout means, in the predicates ``roles`` names (default: the
    household's); a role no predicate plays says nothing."""
    r = roles or Roles()
    f: set[Atom] = {Atom(r.robot_in, (layout.robot.room,))}
    at = layout.robot.at or floor_of(layout.robot.room)
    f |= {Atom(r.robot_at, (at,)), Atom(r.in_view, (at,))}
    for room in layout.rooms:
        f |= {Atom(r.in_room, (floor_of(room), room)), Atom(r.clear, (floor_of(room),))}
    for name, d in layout.doors.items():
        a, b = d.between
        f |= {Atom(r.connects, (name, a, b)), Atom(r.connects, (name, b, a)),
              Atom(r.in_room, (name, a)), Atom(r.in_room, (name, b)), Atom(r.openable, (name,)),
              Atom(_state(d.state, r), (name,))}
    for name, fu in layout.furniture.items():
        f.add(Atom(r.in_room, (name, fu.room)))
        if fu.state is not None:
            f |= {Atom(r.openable, (name,)), Atom(_state(fu.state, r), (name,))}
        elif fu.type in ("container", "appliance"):
            f.add(Atom(r.open, (name,)))  # an open-topped container (a basket) is always open
        if fu.type == "surface" and fu.clear:
            f.add(Atom(r.clear, (name,)))
    held = False
    for name, it in layout.items.items():
        if it.held:
            f.add(Atom(r.held, (name,)))
            held = True
        else:
            f.add(Atom(r.on, (name, it.on)) if it.on else Atom(r.inside, (name, it.inside)))
            f.add(Atom(r.in_room, (name, layout.room_of(name))))
        if it.fillable:
            f.add(Atom(r.fillable, (name,)))
        for b in it.blocked_by:
            f.add(Atom(r.blocking, (b, name)))
        if not it.blocked_by:
            f.add(Atom(r.reachable, (name,)))
    if not held:
        f.add(Atom(r.hand_empty))
    return {a for a in f if a.predicate is not None}


def _state(word: str, roles: Roles) -> str | None:
    """The predicate of a layout's ``state:`` word (the file's ``open``/``closed``)."""
    return roles.open if word == "open" else roles.closed
