"""Capture records: what a simulated camera knew about each frame it took.

A real VLM judges a frame from its pixels. The simulated VLM (:mod:`vap_bt.sim.sim_vlm`) lives on
the world's side and judges a frame from the world's record of that capture: how much of each
object the frame shows (its *visibility*, from the frame's own masks or the symbolic camera's
model) and the truth at capture time. The camera writes one :class:`CaptureRecord` per frame;
the log keeps the last few hundred, keyed by frame id, which is all the simulated VLM is given
besides the question.

Truth is read through the oracle lazily and remembered: questions about a frame arrive right
after it is taken, before the world moves again, so a value read then is the value at capture.
A record also stores the world's step counter at capture; a question about a frame after the
world has stepped is answered from what was read before, or — if nothing was — from the truth
now, and counted as ``late`` — reported in the episode's ``world.late_truth_readings``, so that
it never goes unnoticed. One source is known: the survey's best frames, asked about the doors'
and appliances' states again after the robot has acted (stop 56: 2 in heat_pie seed 55, each
about 2000 steps after its frame); a late reading answers from the leaf's state now.

Beyond how much of each object a frame shows, a record says how well it shows what a *relation*
needs (:class:`ObjectView`: the contact between an item and its support, a container's inside, a
leaf, the fingers), each object's class (a model reads "bottle1" as "the bottle"), and the
*picture* the frame is: the key under which the simulated VLM's persistent errors are drawn
(the same picture gets the same answers; a genuinely new view draws anew).

A record keeps, too, which world instance produced each of the frame's detections (by the
detection's index; ``""`` for a false positive) — what the detector never tells the robot. With
the executive's own association (which detection it took for which object: the names it filled
in), :meth:`CaptureRecord.resolve` says which instance the robot really meant by a name: the
simulated VLM answers about that instance (a set-of-marks prompt: the question's object is the
one marked in the picture), and the runner scores a verification against it. A world that acts
by name (the symbolic one: its actions take the executive's names) marks nothing
(``marked=False``): there a name means the instance of that name.

A record also names the pixels its frame carries (``image_sha1``, the hash the VLM backends'
request records use, :func:`~vap_bt.perception.backends.image.rgb_sha1`), so that a model shown
only the image — the simulated VLM behind its HTTP endpoint, :mod:`vap_bt.sim.vlm_endpoint` —
can find the record again (:meth:`CaptureLog.by_image`). A world without pixels can give its
frames a :func:`frame_card`: a small picture of nothing but the frame's id, for a model that can
only be shown images.
"""

from __future__ import annotations

import hashlib
from collections import OrderedDict
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from vap_bt.domain.atoms import Atom
from vap_bt.sim.oracle import Oracle


@dataclass(frozen=True)
class ObjectView:
    """How one frame shows what a relation about one object needs (each a fraction in [0, 1],
    None where it does not apply to the object); see :mod:`vap_bt.sim.observability`."""

    pixels: int = 0  # visible pixels of the object (0 in worlds without pixels)
    #: items: the share of their bottom band (where they meet their support) the frame shows
    contact: float | None = None
    #: containers: the share of their cavity's opening through which the frame sees inside
    #: (0 when shut: a closed door hides the inside whatever the view)
    interior: float | None = None
    #: articulated furniture and doors: the share of the leaf (door, drawer front) shown
    leaf: float | None = None
    #: surfaces and floors: how much of the top (where things would stand) the frame covers
    top: float | None = None


@dataclass
class CaptureRecord:
    """The world's side of one frame."""

    frame_id: str
    step: int  # the world's step counter at capture
    visibility: dict[str, float]  # object -> visible fraction in this frame (0: not in it)
    oracle: Oracle
    now: Callable[[], int]  # the world's step counter now
    #: object -> (image edges its mask touches: "left", "right", "top", "bottom"; share of the image
    #: it covers) — pixel worlds only
    masks: dict[str, tuple[tuple[str, ...], float]] = field(default_factory=dict)
    #: SHA-1 of the frame's rgb array (None: the frame carries no pixels)
    image_sha1: str | None = None
    #: object -> what the relations about it need from this frame (see :class:`ObjectView`)
    views: dict[str, ObjectView] = field(default_factory=dict)
    #: object -> its class as a detector or a model names it ("bottle" for bottle1)
    labels: dict[str, str] = field(default_factory=dict)
    #: the share of the gripper's fingers the frame shows (None: the world has no hand in view)
    fingers: float | None = None
    #: the picture this frame is, for persistent model errors: the pixels' hash where the frame
    #: has pixels, else the world's view (pose) identity; "" means the frame id
    picture: str = ""
    #: the world instance behind each detection of the frame, by index ("" for a false positive)
    instances: tuple[str, ...] = ()
    #: whether a name the executive gave a detection means that detection's instance (see the
    #: module docstring); False where a name means the instance of that name
    marked: bool = False
    _truth: dict[Atom, bool] = field(default_factory=dict)
    late: int = 0

    @property
    def picture_key(self) -> str:
        """The key the simulated VLM draws this picture's persistent errors under: the picture's
        identity, else the pixels' hash, else the frame id."""
        return self.picture or self.image_sha1 or self.frame_id

    def resolve(self, name: str, identified: dict[str, int]) -> str | None:
        """The world instance the executive meant by ``name`` in this frame: the one behind the
        detection it identified as ``name`` (None for a false positive: nothing), else — not
        identified here, or a world that marks nothing — the instance of that name."""
        k = identified.get(name)
        if not self.marked or k is None or not 0 <= k < len(self.instances):
            return name
        return self.instances[k] or None

    def resolve_atom(self, atom: Atom, identified: dict[str, int]) -> Atom | None:
        """``atom`` with its objects resolved (:meth:`resolve`); None when one is a false positive."""
        args = tuple(self.resolve(a, identified) for a in atom.args)
        return None if None in args else Atom(atom.predicate, args)

    def holds(self, atom: Atom) -> bool:
        """Whether ``atom`` held when the frame was taken: read from the oracle on first asking and
        remembered; a first reading after the world stepped is the truth now, counted as ``late``."""
        if atom not in self._truth:
            if self.now() != self.step:
                self.late += 1
            self._truth[atom] = self.oracle.holds(atom)
        return self._truth[atom]


class CaptureLog:
    """The last ``size`` capture records, by frame id and by the hash of their pixels."""

    def __init__(self, size: int = 512) -> None:
        self.size = size
        self._records: OrderedDict[str, CaptureRecord] = OrderedDict()
        self._by_image: dict[str, str] = {}  # image hash -> the latest frame id with those pixels
        self._late_forgotten = 0  # late readings of records no longer kept

    def add(self, record: CaptureRecord) -> None:
        """Keep ``record`` under its frame id (and its pixels' hash), forgetting the oldest beyond
        ``size``."""
        self._records[record.frame_id] = record
        if record.image_sha1 is not None:
            self._by_image[record.image_sha1] = record.frame_id
        while len(self._records) > self.size:
            _, old = self._records.popitem(last=False)
            self._late_forgotten += old.late
            if old.image_sha1 is not None and self._by_image.get(old.image_sha1) == old.frame_id:
                del self._by_image[old.image_sha1]

    def get(self, frame_id: str) -> CaptureRecord | None:
        """The record of frame ``frame_id``, or None (too old, or never taken here)."""
        return self._records.get(frame_id)

    def by_image(self, sha1: str) -> CaptureRecord | None:
        """The latest record whose frame carried exactly these pixels. Several captures show the
        same pixels when the robot looked again without anything moving; the executive asks about
        a frame before it captures the next, so the latest is the one it asks about."""
        frame_id = self._by_image.get(sha1)
        return self._records.get(frame_id) if frame_id is not None else None

    def clear(self) -> None:
        """Forget every record (the world was reset)."""
        self._records.clear()
        self._by_image.clear()
        self._late_forgotten = 0

    @property
    def late(self) -> int:
        """How many truth readings the records made after the world had stepped, since the last
        :meth:`clear` (kept records and forgotten ones alike; should be 0)."""
        return self._late_forgotten + sum(r.late for r in self._records.values())


#: side of a :func:`frame_card` in pixels
CARD_SIZE = 8


def frame_card(frame_id: str) -> np.ndarray:
    """A ``CARD_SIZE`` square RGB picture of nothing but ``frame_id`` (its SHAKE-256 bytes as
    pixels): distinct frames get distinct cards. It shows nothing of the scene."""
    pixels = hashlib.shake_256(frame_id.encode()).digest(CARD_SIZE * CARD_SIZE * 3)
    return np.frombuffer(pixels, np.uint8).reshape(CARD_SIZE, CARD_SIZE, 3).copy()
