"""The catalogue: what each kind of furniture and item looks like, as data (``catalog.yaml``).

A task file names things the way a person would (``kitchen_sink``, ``wood1``, ``garden_bench``).
The physical world needs shapes, sizes, colours and articulations for them.
:meth:`Catalog.furniture_kind` and :meth:`Catalog.item_kind` resolve a name to a catalogue kind —
the exact name or its alias, then the name's words from the last (digits stripped) or their
aliases, then the generic kind of the thing's PDDL type — so that no scene needs code of its own
and an unknown name still gets a sensible body.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import yaml

CATALOG_PATH = Path(__file__).with_name("catalog.yaml")

Color = tuple[float, float, float, float]


@dataclass(frozen=True)
class Cavity:
    """The hollow of a container or sink, in its frame: ``z`` range, wall thickness, and the side it is
    reached through."""

    z: tuple[float, float]
    wall: float
    open: str  # "front" | "top"


@dataclass(frozen=True)
class DoorSpec:
    """A hinged leaf (``hinge`` left|right|bottom, ``travel`` rad) or a drawer (``slide`` m)."""

    hinge: str | None
    travel: float
    slide: float | None
    friction: float
    color: Color

    @property
    def prismatic(self) -> bool:
        """Whether it slides (a drawer) rather than swings."""
        return self.slide is not None

    @property
    def full(self) -> float:
        """Joint value of the fully open position."""
        return self.slide if self.slide is not None else self.travel


@dataclass(frozen=True)
class FurnitureKind:
    """What a kind of furniture looks like: outer box ``size`` (m), colours, the optional cavity, door,
    lamp, stand, legs and tap, and the ``standoff`` of the base when looking at it."""

    name: str
    type: str
    size: tuple[float, float, float]
    color: Color
    standoff: float
    cavity: Cavity | None = None
    door: DoorSpec | None = None
    light: tuple[Color, Color] | None = None  # (off, on)
    base: tuple[float, Color] | None = None  # a stand below an appliance: (height, colour)
    legs: float | None = None
    top_color: Color | None = None
    tap: Color | None = None


@dataclass(frozen=True)
class ItemKind:
    """What a kind of item looks like: shape and size (m; a cylinder's is (radius, height)), mass (kg),
    colours."""

    name: str
    shape: str  # box | cylinder | sphere
    size: tuple[float, ...]
    mass: float
    color: Color
    lying: bool = False
    filled_color: Color | None = None

    @property
    def extent(self) -> tuple[float, float, float]:
        """Axis-aligned extent (x, y, z) of the item in its resting orientation."""
        if self.shape == "box":
            return tuple(self.size)  # type: ignore[return-value]
        if self.shape == "sphere":
            d = 2 * self.size[0]
            return (d, d, d)
        r, h = self.size
        return (h, 2 * r, 2 * r) if self.lying else (2 * r, 2 * r, h)


@dataclass(frozen=True)
class RoomStyle:
    """How every room is built: default floor size, walls, doorway width, door colour, gap between
    furniture."""

    width: float
    depth: float
    wall_height: float
    wall_thickness: float
    doorway: float
    door_open_angle: float
    floor_colors: tuple[Color, ...]
    wall_color: Color
    door_color: Color
    furniture_gap: float


@dataclass(frozen=True)
class Catalog:
    """Every kind of furniture and item, the room style, and the thresholds at which an articulation
    counts as closed or open."""

    room: RoomStyle
    furniture: dict[str, FurnitureKind]
    items: dict[str, ItemKind]
    aliases: dict[str, str]
    generic: dict[str, str]
    closed_below: float
    open_above: float
    heated_tint: Color
    half_filled_color: Color

    def furniture_kind(self, name: str, pddl_type: str) -> FurnitureKind:
        """The kind of furniture named ``name``: the exact name, an alias, or its last word that names a
        kind, else the generic kind of ``pddl_type``."""
        return self.furniture[_resolve(name, self.furniture, self.aliases, self.generic[pddl_type])]

    def item_kind(self, name: str, pddl_type: str) -> ItemKind:
        """The kind of item named ``name``, resolved as :meth:`furniture_kind` does."""
        return self.items[_resolve(name, self.items, self.aliases, self.generic[pddl_type])]


def _resolve(name: str, kinds: dict[str, Any], aliases: dict[str, str], fallback: str) -> str:
    if name in kinds:
        return name
    if name in aliases and aliases[name] in kinds:
        return aliases[name]
    words = [re.sub(r"\d+$", "", w) for w in name.split("_")]
    for w in reversed(words):  # the last word names the thing: "garden_bench" is a bench
        if w in kinds:
            return w
        if w in aliases and aliases[w] in kinds:
            return aliases[w]
    return fallback


def _color(v) -> Color:
    return tuple(float(x) for x in v)  # type: ignore[return-value]


def _furniture(name: str, d: dict) -> FurnitureKind:
    cav = d.get("cavity")
    door = d.get("door")
    light = d.get("light")
    base = d.get("base")
    return FurnitureKind(
        name=name,
        type=d["type"],
        size=tuple(float(x) for x in d["size"]),  # type: ignore[arg-type]
        color=_color(d["color"]),
        standoff=float(d["standoff"]),
        cavity=Cavity(tuple(cav["z"]), float(cav["wall"]), cav["open"]) if cav else None,
        door=DoorSpec(door.get("hinge"), float(door.get("travel", 0.0)), door.get("slide"),
                      float(door["friction"]), _color(door["color"])) if door else None,
        light=(_color(light["dark"]), _color(light["lit"])) if light else None,
        base=(float(base["height"]), _color(base["color"])) if base else None,
        legs=d.get("legs"),
        top_color=_color(d["top_color"]) if "top_color" in d else None,
        tap=_color(d["tap"]["color"]) if "tap" in d else None,
    )


def _item(name: str, d: dict) -> ItemKind:
    return ItemKind(name=name, shape=d["shape"], size=tuple(float(x) for x in d["size"]), mass=float(d["mass"]),
                    color=_color(d["color"]), lying=bool(d.get("lying", False)),
                    filled_color=_color(d["filled_color"]) if "filled_color" in d else None)


@cache
def load_catalog(path: Path = CATALOG_PATH) -> Catalog:
    """Read the catalogue (``catalog.yaml`` beside this module by default), once per path."""
    raw = yaml.safe_load(Path(path).read_text())
    r = raw["room"]
    room = RoomStyle(
        width=r["width"], depth=r["depth"], wall_height=r["wall_height"], wall_thickness=r["wall_thickness"],
        doorway=r["doorway"], door_open_angle=r["door_open_angle"],
        floor_colors=tuple(_color(c) for c in r["floor_colors"]), wall_color=_color(r["wall_color"]),
        door_color=_color(r["door_color"]), furniture_gap=r["furniture_gap"])
    st = raw["states"]
    return Catalog(
        room=room,
        furniture={k: _furniture(k, v) for k, v in raw["furniture"].items()},
        items={k: _item(k, v) for k, v in raw["items"].items()},
        aliases=dict(raw.get("aliases", {})),
        generic=dict(raw["generic"]),
        closed_below=float(raw["thresholds"]["closed_below"]),
        open_above=float(raw["thresholds"]["open_above"]),
        heated_tint=_color(st["heated_tint"]),
        half_filled_color=_color(st["half_filled_color"]),
    )
