"""Class labels: what kind of thing a detector says it sees, never which one.

A real detector returns a class label per instance ("bottle", "cabinet"); which bottle it is, is
the robot's to work out (:mod:`vap_bt.scene.identity`). Both sides of the seam need the same
rule from a name to its class — the worlds to label what they render, the executive and the
skills to know which detections could be a given object — so it lives here, on the robot's side,
and nowhere else:

* an item's class is its name without trailing ordinal digits (``bottle1`` -> ``bottle``,
  ``apple_pie`` -> ``apple_pie``): the task's names of interchangeable things number them;
* a piece of furniture's class is its kind in the site map (:attr:`FurnitureInfo.label
  <vap_bt.robot.site_map.FurnitureInfo.label>`: a ``garden_bench`` is a ``bench``);
* a door is a ``door``.

:data:`SIMILAR` lists the classes a detector is known to confuse (a cup and a mug look alike):
the simulated detector draws its confusions from it, and re-identification accepts a label from
it at a cost.
"""

from __future__ import annotations

import re

from vap_bt.robot.site_map import SiteMap

DOOR = "door"

_ORDINAL = re.compile(r"(?<=[A-Za-z_])\d+$")

#: pairs of classes a detector confuses (symmetric): similar shape and size, told apart by
#: colour or proportion only. The household's items; other domains' classes are never confused
SIMILAR: frozenset[frozenset[str]] = frozenset(map(frozenset, (
    ("cup", "mug"), ("plate", "bowl"), ("wood", "stick"), ("bottle", "cup"), ("firewood", "stick"),
    ("wood", "firewood"), ("lemon", "egg"))))


def class_of(name: str) -> str:
    """An item's class: its name without trailing ordinal digits (``bottle1`` -> ``bottle``,
    ``stick_2`` -> ``stick``); a name of digits only keeps them (no class word to strip to)."""
    stripped = _ORDINAL.sub("", name)
    return stripped.rstrip("_") or name


def label_of(name: str, site_map: SiteMap | None = None) -> str:
    """The class a detector reports for ``name``: the map's kind for its furniture, ``door`` for
    its doors, else :func:`class_of`."""
    if site_map is not None:
        piece = site_map.piece(name)
        if piece is not None:
            return piece.label
        if site_map.door(name) is not None:
            return DOOR
    return class_of(name)


def similar(a: str, b: str) -> bool:
    """Whether a detector confuses classes ``a`` and ``b`` (never a class with itself)."""
    return a != b and frozenset((a, b)) in SIMILAR


def partners(label: str) -> tuple[str, ...]:
    """The classes a detector takes ``label`` for now and then, sorted."""
    return tuple(sorted(next(iter(p - {label})) for p in SIMILAR if label in p))
