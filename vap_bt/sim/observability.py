"""What a picture shows about a relation: the evidence a vision-language model answers from.

A model does not know the world; it reads a picture. For every atom a question is about, this
module says, from the world's record of one frame (:class:`~vap_bt.sim.captures.CaptureRecord`),
two things (an :class:`Evidence`):

* **apparent** — what a perfect reader of *this picture* would answer. It is the truth when the
  picture shows what the atom is about, but not always: an item hidden behind another on a table
  looks absent, so "is the cup on the table?" apparently has the answer *no*. These are the
  systematic errors occlusion and poor viewpoints cause (paper Sec. I), which no rewording of the
  question cures and only another view can;
* **observability** in [0, 1] — how clearly the picture shows the *relation* asked about, not
  merely the objects: ``on`` needs the contact between the thing and its support in view (the
  item's bottom band, :attr:`ObjectView.contact`), ``inside`` the container's interior (a shut
  container hides it: observability 0), ``holding`` the fingers and the object, ``open``/``closed``
  the leaf, ``inview`` the object's pixels; every relation gets harder as the things shrink in
  the image (:func:`size_quality`).

The rules per relation (x the first argument, y the second; "shown" means the object covers at
least :data:`SHOWN_PIXELS` of a pixel frame, or is in view in a world without pixels; size(x) is
:func:`size_quality`, seen(x) the share of x the picture shows):

========================  =======================================  ==================================
relation                   x shown                                  x not shown
========================  =======================================  ==================================
``inview(x)``              truth, size(x)                           no, 1 (plainly absent)
``on(x, y)``               truth, size(x) * contact(x)              no, top(y) (the support's top)
``inside(x, y)``           truth, size(x) * max(interior(y),        no, interior(y)
                           seen(x) / 2)
``holding(x)``             truth, fingers * size(x) * seen(x)       no, fingers if the hand is
                                                                    empty, else 0
``hand_empty``             truth, fingers
``open(x)``, ``closed``    truth, size(x) * max(leaf(x),            truth, 0
                           interior(x))
states (filled, heated,    truth, size(x) * seen(x)                 truth, 0
sliced, turned_on)
anything else              truth, min over objects of size * seen   truth, 0
========================  =======================================  ==================================

A model reads an instance name as its class ("bottle1" is "the bottle"): the objects a question
names are resolved to the instances the picture shows (:func:`referent`) — the named instance
when it is in the picture, else the most visible instance of its class, else the named one (out
of the picture). The evidence is about those referents. Every relation falls in one
*calibration class* (:data:`RELATION_CLASS`), whose accuracy at full observability the simulated
VLM takes from published measurements (:mod:`vap_bt.sim.sim_vlm`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from vap_bt.domain.atoms import Atom
from vap_bt.sim.captures import CaptureRecord, ObjectView

#: pixels of an object below which a picture does not show it (a few stray pixels are no sighting)
SHOWN_PIXELS = 12
#: a thing covering at least this share of the image is plainly in the picture however much of it
#: lies beyond the frame (a table top filling the view, the stick in the gripper)
PLAIN_SHARE = 0.1
#: size quality, by the share of the image an object covers: at most SIZE_LOW it is too small to
#: judge anything about (0), from SIZE_HIGH on fully judgeable (1); log-linear between. A model is
#: shown a camera's picture (640 x 480 here): a 12 px square (144 px, 0.047 % of it) is where
#: small-target perception saturates (FineSightBench, arXiv 2606.07861), a 96 px square (9216 px,
#: 3 %) is COCO's "large" object, where detectors and VQA models do as well as they ever do
#: (docs/perception.md). The share, not the renderer's pixel count, so that the figure does not
#: depend on the simulated image's size
SIZE_LOW, SIZE_HIGH = 144 / (640 * 480), 9216 / (640 * 480)
#: how much a marked false positive (a blob, a patch of floor) shows of the thing a question names:
#: nothing — the thing is not in the picture, and the model cannot judge a relation of it
FALSE_POSITIVE_OBSERVABILITY = 0.0
#: which calibration class each predicate's questions fall in
RELATION_CLASS = {"inview": "inview", "on": "on", "inside": "inside", "holding": "holding",
                  "hand_empty": "holding", "open": "open", "closed": "open", "filled": "state",
                  "heated": "state", "sliced": "state", "turned_on": "state", "blocking": "spatial",
                  "reachable": "spatial", "near": "spatial"}


@dataclass(frozen=True)
class Evidence:
    """What one picture shows about one atom (see the module docstring)."""

    atom: Atom | None  # the atom about the referents (the instances the picture shows); None: a false positive
    apparent: bool
    observability: float
    relation: str  # calibration class
    shown: bool  # the atom's first object is in the picture


def size_quality(share: float) -> float:
    """How judgeable a thing covering ``share`` of the image is for its size (see :data:`SIZE_LOW`)."""
    if share <= SIZE_LOW:
        return 0.0
    return min(1.0, math.log(share / SIZE_LOW) / math.log(SIZE_HIGH / SIZE_LOW))


def label_of(name: str, record: CaptureRecord) -> str:
    """The class a detector or a model reads ``name`` as in this frame (``bottle`` for bottle1); the name
    itself when the record has none."""
    return record.labels.get(name, name)


def referent(name: str, record: CaptureRecord, rooms: frozenset[str] = frozenset()) -> str:
    """The instance a model takes ``name`` to mean in this picture (see the module docstring)."""
    if name in rooms or _seen(name, record) > 0.0 or not record.labels:
        return name
    cls = label_of(name, record)
    shown = [(record.visibility.get(o, 0.0) * record.masks.get(o, ((), 1.0))[1], o) for o, c in record.labels.items()
             if c == cls and o != name and _seen(o, record) > 0.0]
    return max(shown)[1] if shown else name


class Observability:
    """The rules of the module docstring over one capture record."""

    def __init__(self, record: CaptureRecord, rooms: frozenset[str] = frozenset()) -> None:
        self.record, self.rooms = record, rooms

    def evidence(self, atom: Atom | None) -> Evidence:
        """What the picture shows about ``atom``; None is an atom about a false positive the
        executive marked (a blob that is no such thing): the thing it names is not in the picture."""
        if atom is None:
            return Evidence(None, False, FALSE_POSITIVE_OBSERVABILITY, "other", True)
        rec = self.record
        args = tuple(referent(a, rec, self.rooms) for a in atom.args)
        atom = Atom(atom.predicate, args)
        relation = RELATION_CLASS.get(atom.predicate, "other")
        x = args[0] if args else None
        shown = x is None or self.shown(x)
        truth = rec.holds(atom)
        rule = getattr(self, "_" + atom.predicate, None)
        apparent, o = rule(truth, shown, *args) if rule is not None and _arity_ok(rule, args) else \
            self._default(truth, args)
        return Evidence(atom, apparent, max(0.0, min(1.0, o)), relation, shown)

    # -- per relation (truth, whether x is shown, the atom's arguments) -> (apparent, observability)

    def _inview(self, truth, shown, x):
        return (truth, self.size(x)) if shown else (False, 1.0)

    def _on(self, truth, shown, x, y):
        if shown:
            return truth, self.size(x) * _or(self.view(x).contact, self.seen(x))
        return False, _or(self.view(y).top, self.seen(y))

    def _inside(self, truth, shown, x, y):
        interior = _or(self.view(y).interior, 0.0)
        if shown:
            return truth, self.size(x) * max(interior, self.seen(x) / 2)
        return False, interior

    def _holding(self, truth, shown, x):
        fingers = _or(self.record.fingers, 1.0)
        if shown:
            return truth, fingers * self.size(x) * self.seen(x)
        # fingers closed on nothing show an empty hand plainly; fingers apart on a thing the
        # camera cannot see (held under its lens, nearer than it renders) show nothing either way
        return False, fingers if self.record.holds(Atom("hand_empty", ())) else 0.0

    def _hand_empty(self, truth, shown):
        return truth, _or(self.record.fingers, 1.0)

    def _open(self, truth, shown, x):
        # a leaf seen shows how it stands; an inside seen shows that the leaf is out of the way
        v = self.view(x)
        shows = max(_or(v.leaf, self.seen(x)), _or(v.interior, 0.0))
        return truth, (self.size(x) * shows) if shown else 0.0

    _closed = _open

    def _state(self, truth, shown, x):
        return truth, (self.size(x) * self.seen(x)) if shown else 0.0

    _filled = _heated = _sliced = _turned_on = _state

    def _default(self, truth, args):
        named = [a for a in args if a not in self.rooms]
        return truth, min((self.size(a) * self.seen(a) if self.shown(a) else 0.0 for a in named), default=1.0)

    # -- how the picture shows one object ----------------------------------------------------

    def view(self, name: str) -> ObjectView:
        """How the frame shows what ``name``'s relations need (contact, interior, leaf); nothing shown
        when the record has no view of it."""
        return self.record.views.get(name, ObjectView())

    def seen(self, name: str) -> float:
        """The share of ``name`` the picture shows, in [0, 1]."""
        return _seen(name, self.record)

    def shown(self, name: str) -> bool:
        """Whether ``name`` counts as in the picture: a room always; else seen, and covering at least
        :data:`SHOWN_PIXELS` in a frame with pixels."""
        if name in self.rooms:
            return True
        if self.seen(name) <= 0.0:
            return False
        pixels = _pixels(name, self.record)
        return pixels is None or pixels >= SHOWN_PIXELS

    def size(self, name: str) -> float:
        """How much ``name``'s size in the image lets a model read it (:func:`size_quality`); 1 in a
        world without pixels."""
        if not self.record.masks:  # no pixels: the world's visibility draw stands for size too
            return 1.0
        return size_quality(self.record.masks.get(name, ((), 0.0))[1])


def _seen(name: str, record: CaptureRecord) -> float:
    """The share of ``name`` the picture shows, except that a thing covering at least
    :data:`PLAIN_SHARE` of the image is plainly in it (the mask decides, not the fraction: the
    fraction divides by the projection of the thing's box, which blows up when the box reaches
    behind the camera)."""
    shown = record.masks.get(name)
    return 1.0 if shown is not None and shown[1] >= PLAIN_SHARE else record.visibility.get(name, 0.0)


def _pixels(name: str, record: CaptureRecord) -> int | None:
    """Visible pixels of ``name``, None in a world without pixels (no masks)."""
    if not record.masks:
        return None
    v = record.views.get(name)
    return v.pixels if v is not None else 0


def _or(value: float | None, default: float) -> float:
    return default if value is None else value


def _arity_ok(rule, args) -> bool:
    """A rule takes (self, truth, shown, *args): another domain's ``on`` of one argument (a car on
    the ferry) is not the household's ``on`` and falls to the default rule."""
    return rule.__code__.co_argcount - 3 == len(args)
