"""The simulated VLM: answers a question about a frame from the world's record of that frame.

It is a model, not a canned answer, and it lives on the world's side: it is handed the frame id
and looks up the :class:`~vap_bt.sim.captures.CaptureRecord` the simulated camera wrote when it
took the frame — how much of each object the frame shows, where in the image each object's mask
lies, and the truth at capture time. It treats every question alike: a question is judged on the
atoms it concerns (for the action-level baselines, every atom the action implies), whichever
strategy asked. Its parameters are fixed here with their reasons and printed in every report.

**How well a frame shows a thing.** Its *visibility* is the fraction of it the frame shows (from
the camera's record: occlusion and the parts the frame cuts off both count against it), except
that a thing covering at least ``PLAIN_SHARE`` (a tenth) of the image is plainly in the picture,
as well seen as a wholly visible one, whatever fraction of it the frame shows. A model
judges pixels, not what lies beyond the frame: the floor under a stick, a table top filling the
view, a fridge a step away or the stick in the gripper are no harder to make out for being cut
by the image's edges. (Without this rule a floor filling 94 % of a frame counted as 3 % visible,
and every question about a large thing seen from close by was judged unanswerable.)

**Yes/no answers.** ``v`` is the least visibility among the objects the question names (rooms
excluded; 1 when it names none). The chance of a wrong answer is ``p(v) = min(0.5,
error_rate * (2 - v))`` for an object in the frame — the base rate when fully visible, up to
twice that when barely — and 0.5 when it is not in the frame (a guess). Each answer comes from a
latent score ``z = ±mu(v) + N(0, 1)`` (+ when the truth is yes), answered yes iff ``z > 0``, with
``mu(v) = Phi^-1(1 - p(v))``: so answers are wrong exactly at the rate ``p(v)``, each query an
independent draw seeded by the run's seed, the frame and the prompt (answers do not depend on the
order in which concurrent questions arrive; one question asked twice about one frame gets one
answer, as from a model at temperature 0).

**Token probabilities.** Every answer carries the probability the model gives it,
``sigmoid(4 |z|)``: a model's probabilities say something about whether it is right — its
errors come from scores near the boundary, so they are mostly less sure — but they are not its
error rate handed back, and the slope 4 makes it overconfident: answering at accuracy 0.95 it
states 0.96 on average, at 0.90 it states 0.94, at 0.70 it states 0.89, and a pure guess about
an object it cannot see is stated at 0.87.

**View sufficiency** is judged from visibility even at ``v = 0`` (a model can tell that it does
not see the thing asked about): true iff ``v >= 0.5``, wrong at ``p(v)``.

**Viewpoints** come from the frame, as a model would read them off the image: the target's mask
cut by the image's left or right edge → that way; cut by both, or by the top or bottom, or
filling much of the image → ``front`` (step back, look squarely); small in the image →
``closer``; in the image but mostly hidden → ``above`` (look over what is in front of it); whole,
unhidden and not filling the image → ``closer`` (a clearer view of a thing the frame shows whole
is a nearer one: stepping back is what a thing the frame cuts needs). A target not in the image
whose place is — the other object the question names: the drawer the knife should be in, the
counter the bottle should stand on — is read as hidden in or behind that place: the place's mask
cut by the image's left or right edge alone → that way (bring the place into the picture), else
``above`` (look over or into it), as a model reads "no knife in sight, but there is the drawer
it should be in". Nothing named in the picture → a uniform guess (nothing in it says where to
look). The reading is wrong (a uniform choice) at the same rate ``p(v)``, ``v`` being how well
the frame shows what it is read off.

**Which instance a name means.** The detector gives the executive class labels only, and the
executive decides which detection is which object. A question comes with that association (the
frame's ``identified``: a set-of-marks prompt, the question's object marked in the picture), and
the model judges the instance so marked (:meth:`CaptureRecord.resolve
<vap_bt.sim.captures.CaptureRecord.resolve>`): asked whether bottle1 is on the bench about the
bottle the robot took for bottle1, it answers about that bottle, whatever the world calls it; a
false positive so marked is nothing the question names (not in the picture; no atom about it
holds). A name not marked in the frame, or a world that marks nothing, means the instance of that
name. (Over HTTP, :mod:`vap_bt.sim.vlm_endpoint`, only the image and the prompt travel, so names
are read as names there.)

A frame the log does not know (too old, or from elsewhere) gets no answer. With
``error_rate = 0`` every answer about a visible object is right: "VLM noise off".
"""

from __future__ import annotations

import math
import random
from dataclasses import replace
from statistics import NormalDist
from typing import Callable

from vap_bt.perception.vlm import Answer, Query
from vap_bt.robot.frame import Frame
from vap_bt.sim.captures import CaptureRecord

SUFFICIENT_VISIBILITY = 0.5
#: a thing covering at least this share of the image is plainly in the picture, however much of it
#: the frame cuts off (see the module docstring)
PLAIN_SHARE = 0.1
#: slope of the stated probability in the latent score (see the module docstring: overconfident)
CONFIDENCE_SLOPE = 4.0
#: a target smaller than this share of the image is "far": come closer
SMALL_IN_IMAGE = 0.01
#: a target larger than this share of the image, or cut by more than one edge, is "too close": step back
LARGE_IN_IMAGE = 0.5
#: a target shown less than this is "hidden": look over what hides it
HIDDEN = 0.5
_NORMAL = NormalDist()


class SimVLM:
    """The world-side VLM model described in the module docstring."""

    name = "sim"

    def __init__(self, records: Callable[[str], CaptureRecord | None], error_rate: float = 0.0, seed: int = 0,
                 rooms: frozenset[str] = frozenset()) -> None:
        if not 0.0 <= error_rate <= 0.5:
            raise ValueError("error_rate must be within [0, 0.5]")
        self.records, self.error_rate, self.rooms = records, error_rate, rooms
        self.reseed(seed)

    def reseed(self, seed: int) -> None:
        self.seed = seed

    def describe(self) -> dict:
        return {"backend": self.name, "error_rate": self.error_rate, "seed": self.seed,
                "model": "answers from the world's record of the frame: wrong w.p. min(0.5, error_rate*(2-v)) "
                         f"for visible objects (v: visible fraction, or 1 for a thing covering >= {PLAIN_SHARE:g} of the image), 0.5 when unseen, via a latent score z = +-Phi^-1(1-p) + N(0,1); "
                         f"stated probability sigmoid({CONFIDENCE_SLOPE:g}|z|); sufficient iff v >= 0.5; "
                         "viewpoint read off the target's mask (edges, size, occlusion), off its place's when the target is unseen "
                         "(its left or right edge, else above), uniform when neither is in the picture"}

    def ask(self, query: Query, frame: Frame) -> Answer:
        record = self.records(frame.frame_id)
        if record is None:
            return Answer("", None)
        return self.answer(query, record, frame.identified())

    def answer(self, query: Query, record: CaptureRecord, identified: dict[str, int] | None = None) -> Answer:
        """The answer to ``query`` about the capture ``record`` describes (as :meth:`ask`, for a
        caller that found the record itself: the HTTP endpoint, from the image it was shown).
        ``identified``: which of the frame's detections the executive took for which of the
        question's objects — the model judges the instances so marked (:meth:`CaptureRecord.resolve`)."""
        rng = random.Random(f"{self.seed}|{record.frame_id}|{query.kind}|{query.prompt}")
        query = _marked(query, record, identified or {})
        v = self._visibility(query, record)
        if query.kind == "choice":
            choice = self._direction(query, record, v, rng)
            return Answer(choice, choice)
        sufficiency = query.purpose == "sufficiency"
        # an atom about a false positive (a marked blob that is no such thing) does not hold
        true = (v >= SUFFICIENT_VISIBILITY) if sufficiency else all(a is not None and record.holds(a) for a in query.about)
        # whether a view shows enough is judgeable even when it shows nothing: no coin flip there
        p = self._p_seen(v) if sufficiency else self._p_wrong(v)
        mu = _NORMAL.inv_cdf(1.0 - max(p, 1e-9)) if p < 0.5 else 0.0  # noise off: always right, and sure
        z = (mu if true else -mu) + rng.gauss(0.0, 1.0)
        value = z > 0
        confidence = 1.0 / (1.0 + math.exp(-CONFIDENCE_SLOPE * abs(z)))
        return Answer("yes" if value else "no", value, confidence=round(confidence, 4))

    def _direction(self, query: Query, record: CaptureRecord, v: float, rng: random.Random) -> str:
        """The viewpoint the frame suggests for the question's target (its first object), or, with
        the target out of the picture, for the place the question puts it (see the module
        docstring); a uniform choice where the frame says nothing, or is misread."""
        named = self._named(query)
        place = self._place_in_view(named, record)
        want = (self._place_way(place, record, rng) if place is not None
                else self._target_way(named[0] if named else None, record, v, rng))
        options = tuple(query.options)
        return want if want in options else rng.choice(options)

    def _place_in_view(self, named: list[str], record: CaptureRecord) -> str | None:
        """The first other object named that the frame shows, when it does not show the target."""
        if not named or self._seen(named[0], record) > 0.0:
            return None
        return next((o for o in named[1:] if self._seen(o, record) > 0.0), None)

    def _place_way(self, place: str, record: CaptureRecord, rng: random.Random) -> str | None:
        """Over the place, or the way its mask leaves the image sideways; None when misread."""
        if rng.random() < self._p_seen(self._seen(place, record)):
            return None
        edges, _ = record.masks.get(place, ((), 0.0))
        return edges[0] if len(edges) == 1 and edges[0] in ("left", "right") else "above"

    def _target_way(self, target: str | None, record: CaptureRecord, v: float, rng: random.Random) -> str | None:
        """The way the target's mask asks for; None when it is not in the picture, or misread."""
        shown = record.masks.get(target) if target is not None else None
        v = self._seen(target, record) if target is not None else v  # the target's own
        if shown is None or v <= 0.0 or rng.random() < self._p_seen(v):
            return None
        edges, share = shown
        v = record.visibility.get(target, 0.0)  # how much of it the frame shows: is it hidden?
        return ("front" if len(edges) > 1 or "top" in edges or "bottom" in edges or share > LARGE_IN_IMAGE
                else edges[0] if edges else "above" if v < HIDDEN and share >= SMALL_IN_IMAGE else "closer")

    def _named(self, query: Query) -> list[str]:
        """The objects the question names, rooms left out (a room is where, not what)."""
        return [o for o in query.objects if o not in self.rooms]

    def _visibility(self, query: Query, record: CaptureRecord) -> float:
        return min((self._seen(o, record) for o in self._named(query)), default=1.0)

    @staticmethod
    def _seen(name: str, record: CaptureRecord) -> float:
        """How well the frame shows ``name``: its visible fraction, except that a thing covering
        at least ``PLAIN_SHARE`` of the image is plainly in it (see the module docstring)."""
        shown = record.masks.get(name)
        # the mask, not the fraction: the fraction divides by the projection of the thing's box,
        # which blows up when the box reaches behind the camera (a door seen from its doorway
        # covered half the image at a computed 0.0004, and every question about it was a guess)
        return 1.0 if shown is not None and shown[1] >= PLAIN_SHARE else record.visibility.get(name, 0.0)

    def _p_wrong(self, v: float) -> float:
        return 0.5 if v <= 0.0 else self._p_seen(v)

    def _p_seen(self, v: float) -> float:
        return min(0.5, self.error_rate * (2.0 - v))


def _marked(query: Query, record: CaptureRecord, identified: dict[str, int]) -> Query:
    """``query`` about the instances the executive marked in the frame (a false positive is
    marked as ``""``: nothing the frame shows is what the question names). Its ``about`` may then
    hold None for an atom about a false positive."""
    if not identified or not record.marked:
        return query
    about = tuple(record.resolve_atom(a, identified) for a in query.about)
    objects = tuple(record.resolve(o, identified) or "" for o in query.objects)
    return replace(query, about=about, objects=objects)
