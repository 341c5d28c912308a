"""The simulated VLM: a model of how a real vision-language model answers about one picture.

It lives on the world's side and is handed the frame id; it looks up the world's
:class:`~vap_bt.sim.captures.CaptureRecord` of that frame and reads from it what a model would
read from the pixels (:mod:`vap_bt.sim.observability`): for each atom a question is about, the
*apparent* answer (what the picture shows, which occlusion can make wrong) and how observable the
*relation* is in this picture (the contact for ``on``, the inside for ``inside``, the fingers for
``holding``, the leaf for ``open``; all harder as things shrink in the image). Every question is
treated alike whichever strategy asked it: an action-level question ("did the robot successfully
pick up the cup?") is judged on the conjunction of the facts it implies, about every object it
involves. Model version :data:`MODEL_VERSION`; its parameters (:class:`VlmModel`) are fixed with
their sources in docs/perception.md, printed in every report, and never tuned to an experiment's
outcome: a change is a new version, and every figure is measured again.

**Errors are structural, not coin flips.** A yes/no answer is ``yes`` iff its latent score
(:mod:`vap_bt.sim.latent`, shared with the symbolic world's relation detector)

    z = s * d  +  noise * [ b_yes * (1 - o)  +  sqrt(r_rel) e_rel  +  sqrt(r_atom) e_atom  +  sqrt(1 - r_rel - r_atom) e_q ]

is positive: ``s`` = +1 when the picture apparently says yes, ``o`` the relation's observability,
``d = o * Phi^-1(A)`` the signal, ``A`` the accuracy of a single answer at full observability for
the relation's class (:attr:`VlmModel.accuracy`), ``b_yes`` a bias towards "yes" that grows as the
evidence fades (real models say yes when unsure). The standard normal parts are drawn from the
run's seed and the *picture* (the pixels' hash: the same picture gives the same answers; a
genuinely new view draws anew): ``e_rel`` is shared by every question about one relation class in
that picture (a view-and-relation effect), ``e_atom`` by every question about one atom (its five
paraphrases), ``e_q`` belongs to the question's wording. Paraphrases of one atom about one picture
are therefore correlated with correlation ``r_rel + r_atom`` (:attr:`VlmModel.paraphrase_correlation`),
so five of them can agree and be wrong, and only another view helps. At observability 0 the
answer is the bias and the shared noise: near chance, leaning to yes.

**Abstentions.** Where the relation cannot be observed at all (``o`` below
:attr:`VlmModel.abstain_below`: a shut container's inside, a thing not in the picture) a model
often says it cannot tell: it abstains with probability :attr:`VlmModel.abstain_rate`, drawn per
picture and atom (an abstention is no answer, which the vote ignores).

**Token probabilities.** The probability a model states for its answer is ``sigmoid(c |z|)``
shrunk towards one half where the evidence is all but absent,
``0.5 + (sigmoid(c |z|) - 0.5) * (l + (1 - l) min(1, o / o_aware))``: overconfident wherever it
sees something (``c`` = :attr:`VlmModel.confidence_slope`; a poor view is stated as surely as a
good one), and never confident about what it cannot see at all (at ``o`` = 0 it states at most
``0.5 + l/2``). The calibration curve and the expected calibration error this gives are
measured (tools/bench/perception.py) and reported.

**View sufficiency** ("is this view sufficient to answer ...?") is a yes/no judgement of the same
observability: true iff ``o >= theta``; the model answers yes iff
``kappa (o - theta) + noise * (beta + e)`` is positive, ``beta`` > 0 its overconfidence (it calls
views sufficient too often), ``e`` drawn per picture and prompt.

**Viewpoints** are read off the picture, relation first: an item whose contact, a container
whose inside or a leaf that the frame shows poorly while the thing itself is plain → ``above``
for ``on``/``inside`` (look over what hides it, or into the cavity), ``front`` for a leaf; else off
the target's mask: cut by the image's left or right edge → that way; cut by both, or by the top or
bottom, or filling much of the image → ``front`` (step back); small → ``closer``; mostly hidden →
``above``; whole → ``closer``. A target not in the picture whose place is (the drawer the knife
should be in) is read as hidden in or behind that place: the place's left or right edge → that
way, else ``above``. Nothing named in the picture → a uniform guess. A reading is wrong (a uniform
choice) with probability ``noise * (1 - Phi(o' Phi^-1(A_view)))``, ``o'`` how well the picture
shows what it is read off.

**Which instance a name means.** The detector gives the executive class labels only, and the
executive decides which detection is which object. A question comes with that association (the
frame's ``identified``: a set-of-marks prompt, the question's object marked in the picture), and
the model judges the instance so marked (:meth:`CaptureRecord.resolve
<vap_bt.sim.captures.CaptureRecord.resolve>`): asked whether bottle1 is on the bench about the
bottle the robot took for bottle1, it answers about that bottle, whatever the world calls it; a
false positive so marked is nothing the question names (no atom about it holds: the picture shows
no such thing). A name not marked in the frame — over HTTP (:mod:`vap_bt.sim.vlm_endpoint`) only
the image and the prompt travel — is read as its class: the named instance if the picture shows
it, else the most visible instance of its class (:func:`vap_bt.sim.observability.referent`).

With ``noise`` = 0 the model is an ideal reader of the picture: it answers the apparent truth
wherever the relation is observable at all (and "no" where it is not), judges sufficiency exactly
by ``theta``, never misreads a viewpoint and never abstains ("VLM noise off"). A frame the log
does not know (too old, or from elsewhere) gets no answer.
"""

from __future__ import annotations

import math
import random
from dataclasses import asdict, dataclass, field, replace
from typing import Callable

from vap_bt.perception.vlm import Answer, Query
from vap_bt.robot.frame import Frame
from vap_bt.sim.captures import CaptureRecord
from vap_bt.sim.latent import cdf, draw_normal, draw_uniform, probit, score, signal
from vap_bt.sim.observability import Evidence, Observability

#: the model's version: a change of any parameter or rule is a new version (docs/perception.md)
MODEL_VERSION = "vlm-2 (2026-12-03)"
#: a target smaller than this share of the image is "far": come closer
SMALL_IN_IMAGE = 0.01
#: a target larger than this share of the image, or cut by more than one edge, is "too close": step back
LARGE_IN_IMAGE = 0.5
#: a target shown less than this is "hidden": look over what hides it
HIDDEN = 0.5
#: a relation's own evidence (contact, inside, leaf) below this while the thing is plain: look at it
POOR_EVIDENCE = 0.4


@dataclass(frozen=True)
class VlmModel:
    """The simulated model's parameters (sources and reasons: docs/perception.md)."""

    #: single-answer accuracy at full observability, per calibration class of relation
    accuracy: dict[str, float] = field(default_factory=lambda: {
        "inview": 0.93, "on": 0.88, "inside": 0.82, "holding": 0.88, "open": 0.83,
        "state": 0.75, "spatial": 0.72, "other": 0.80})
    #: correlation of the latent noise of two paraphrases of one atom about one picture (0.5), split
    #: into the part shared by the relation class in the picture and the part shared by the atom
    relation_correlation: float = 0.15
    atom_correlation: float = 0.35
    #: latent bias towards "yes" at observability 0 (linearly less as the evidence firms):
    #: Phi(0.25) = 0.6 of answers about what cannot be seen are "yes"
    yes_bias: float = 0.25
    #: below this observability a model may say it cannot tell, with this probability
    abstain_below: float = 0.05
    abstain_rate: float = 0.2
    #: stated probability: slope in |z|; the share of its excess over one half kept at o = 0, and
    #: the observability from which a model no longer notices that it cannot see (it keeps all)
    confidence_slope: float = 4.0
    confidence_floor: float = 0.5
    confidence_aware: float = 0.25
    #: view sufficiency: threshold on observability, slope, and overconfidence (latent units)
    sufficiency_threshold: float = 0.5
    sufficiency_slope: float = 2.5
    overconfidence: float = 0.5
    #: accuracy of reading a viewpoint off a plainly seen target
    viewpoint_accuracy: float = 0.75
    #: scale of every imperfection (1: the calibrated model; 0: an ideal reader of the picture)
    noise: float = 1.0

    @property
    def paraphrase_correlation(self) -> float:
        """The correlation of two paraphrases' latent noise about one atom in one picture: ``r_rel +
        r_atom``."""
        return self.relation_correlation + self.atom_correlation

    def describe(self) -> dict:
        """The model's version and every parameter, for the report."""
        return {"version": MODEL_VERSION, **asdict(self), "paraphrase_correlation": self.paraphrase_correlation}


@dataclass(frozen=True)
class Judgement:
    """One yes/no judgement the model made, for measuring it against the truth (world side)."""

    purpose: str
    relation: str
    observability: float
    apparent: bool
    truth: bool
    answer: bool | None
    confidence: float | None
    picture: str
    atoms: tuple[str, ...]


class SimVLM:
    """The world-side VLM model described in the module docstring."""

    name = "sim"

    def __init__(self, records: Callable[[str], CaptureRecord | None], noise: float = 1.0, seed: int = 0,
                 rooms: frozenset[str] = frozenset(), model: VlmModel | None = None) -> None:
        if not 0.0 <= noise <= 2.0:
            raise ValueError("noise must be within [0, 2] (1: the calibrated model, 0: no noise)")
        self.model = VlmModel(noise=noise) if model is None else model
        self.records, self.rooms = records, rooms
        #: every yes/no judgement since the last reseed (kept for the benches' calibration figures)
        self.ledger: list[Judgement] = []
        self.reseed(seed)

    @property
    def noise(self) -> float:
        """The noise scale (1: the calibrated model, 0: an ideal reader of the picture)."""
        return self.model.noise

    def reseed(self, seed: int) -> None:
        """Draw every answer from ``seed`` from now on (an episode's reset), and start a new ledger."""
        self.seed = seed
        self.ledger = []

    def describe(self) -> dict:
        return {"backend": self.name, "seed": self.seed, **self.model.describe(),
                "model": "answers from the world's record of the picture: the apparent truth at the relation's "
                         "observability (contact, inside, fingers, leaf; size), a latent score with parts shared by "
                         "relation and atom per picture (correlated paraphrases), a yes-bias and abstentions where "
                         "nothing can be seen, overconfident token probabilities, sufficiency from the same "
                         "observability, viewpoints read off the picture (docs/perception.md)"}

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
        query = _marked(query, record, identified or {})
        seen = Observability(record, self.rooms)
        if query.kind == "choice":
            choice = self._direction(query, seen)
            return Answer(choice, choice)
        evidence = [seen.evidence(a) for a in query.about]
        if query.purpose == "sufficiency":
            return self._sufficiency(query, record, evidence)
        return self._yes_no(query, record, evidence)

    # -- yes/no -----------------------------------------------------------------------------

    def _yes_no(self, query: Query, record: CaptureRecord, evidence: list[Evidence]) -> Answer:
        m = self.model
        picture = record.picture_key
        o = min((e.observability for e in evidence), default=1.0)
        apparent = all(e.apparent for e in evidence)
        # the conjunction is as strong as its weakest fact
        d = min((signal(e.observability, m.accuracy.get(e.relation, m.accuracy["other"])) for e in evidence), default=0.0)
        relation = min(evidence, key=lambda e: e.observability).relation if evidence else "other"
        atoms = tuple(sorted(str(e.atom) for e in evidence))  # "None": about a false positive
        truth = all(a is not None and record.holds(a) for a in query.about)
        if m.noise > 0 and o < m.abstain_below and self._uniform(picture, "abstain", atoms) < m.abstain_rate:
            self._note(query, relation, o, apparent, truth, None, None, picture, atoms)
            return Answer("I can't tell from this image.", None)
        shared = (math.sqrt(m.relation_correlation) * self._normal(picture, "relation", relation)
                  + math.sqrt(m.atom_correlation) * self._normal(picture, "atom", *atoms)
                  + math.sqrt(max(0.0, 1.0 - m.paraphrase_correlation)) * self._normal(picture, "question", query.prompt))
        z = score(apparent, d, o, m.noise, m.yes_bias, shared)
        value = z > 0
        sure = 1.0 / (1.0 + math.exp(-m.confidence_slope * abs(z)))
        keep = m.confidence_floor + (1.0 - m.confidence_floor) * min(1.0, o / m.confidence_aware)
        confidence = round(0.5 + (sure - 0.5) * keep, 4)
        self._note(query, relation, o, apparent, truth, value, confidence, picture, atoms)
        return Answer("yes" if value else "no", value, confidence=confidence)

    def _sufficiency(self, query: Query, record: CaptureRecord, evidence: list[Evidence]) -> Answer:
        m = self.model
        o = min((e.observability for e in evidence), default=1.0)
        z = m.sufficiency_slope * (o - m.sufficiency_threshold) + m.noise * (
            m.overconfidence + self._normal(record.picture_key, "sufficiency", query.prompt))
        value = z > 0 if m.noise > 0 or o != m.sufficiency_threshold else True
        sure = 1.0 / (1.0 + math.exp(-m.confidence_slope * abs(z)))
        atoms = tuple(sorted(str(e.atom) for e in evidence))  # "None": about a false positive
        self._note(query, "sufficiency", o, o >= m.sufficiency_threshold, o >= m.sufficiency_threshold, value,
                   round(sure, 4), record.picture_key, atoms)
        return Answer("yes" if value else "no", value, confidence=round(sure, 4))

    def _note(self, query: Query, relation: str, o: float, apparent: bool, truth: bool, answer, confidence,
              picture: str, atoms) -> None:
        self.ledger.append(Judgement(query.purpose, relation, round(o, 4), apparent, truth, answer, confidence,
                                     picture, atoms))

    # -- viewpoints -------------------------------------------------------------------------

    def _direction(self, query: Query, seen: Observability) -> str:
        """The viewpoint the picture suggests for the question's target (its first object), or,
        with the target out of the picture, for the place the question puts it; a uniform choice
        where the picture says nothing, or is misread (see the module docstring)."""
        rng = random.Random(f"{self.seed}|{seen.record.picture_key}|viewpoint|{query.prompt}")
        named = [o for o in query.objects if o not in self.rooms]
        target = named[0] if named else None
        place = next((o for o in named[1:] if seen.seen(o) > 0.0), None) \
            if target is not None and seen.seen(target) <= 0.0 else None
        if place is not None:
            want, clear = self._place_way(place, seen), seen.seen(place)
        elif target is not None and seen.seen(target) > 0.0:
            atom = query.about[0] if query.about else None  # None: about a false positive
            want = (self._relation_way(atom, seen) if atom is not None else None) or self._target_way(target, seen)
            clear = seen.seen(target)
        else:
            want, clear = None, 0.0
        m = self.model
        misread = m.noise * (1.0 - cdf(signal(clear, m.viewpoint_accuracy)))
        options = tuple(query.options)
        if want not in options or rng.random() < misread:
            return rng.choice(options)
        return want

    def _relation_way(self, atom, seen: Observability) -> str | None:
        """Where to look when the thing is plain but what the relation needs is not."""
        x = atom.args[0] if atom.args else None
        if x is None or seen.seen(x) < HIDDEN:
            return None
        if atom.predicate == "on" and (seen.view(x).contact or 1.0) < POOR_EVIDENCE:
            return "above"
        if atom.predicate == "inside" and len(atom.args) == 2 and (seen.view(atom.args[1]).interior or 0.0) < POOR_EVIDENCE:
            return "above"
        if atom.predicate in ("open", "closed") and (seen.view(x).leaf or 1.0) < POOR_EVIDENCE:
            return "front"
        return None

    @staticmethod
    def _place_way(place: str, seen: Observability) -> str:
        """Over the place, or the way its mask leaves the image sideways."""
        edges, _ = seen.record.masks.get(place, ((), 0.0))
        return edges[0] if len(edges) == 1 and edges[0] in ("left", "right") else "above"

    @staticmethod
    def _target_way(target: str, seen: Observability) -> str:
        """The way the target's mask asks for (see the module docstring)."""
        edges, share = seen.record.masks.get(target, ((), 0.0))
        hidden = seen.record.visibility.get(target, 0.0) < HIDDEN
        if len(edges) > 1 or "top" in edges or "bottom" in edges or share > LARGE_IN_IMAGE:
            return "front"
        if edges:
            return edges[0]
        return "above" if hidden and share >= SMALL_IN_IMAGE else "closer"

    # -- seeded draws -----------------------------------------------------------------------

    def _normal(self, picture: str, *key: str) -> float:
        return draw_normal(self.seed, picture, *key)

    def _uniform(self, picture: str, *key) -> float:
        return draw_uniform(self.seed, picture, *key)


def _marked(query: Query, record: CaptureRecord, identified: dict[str, int]) -> Query:
    """``query`` about the instances the executive marked in the frame. An atom about a false
    positive (a marked blob that is no such thing) becomes None: nothing in the picture is it."""
    if not identified or not record.marked:
        return query
    about = tuple(record.resolve_atom(a, identified) for a in query.about)
    objects = tuple(record.resolve(o, identified) or "" for o in query.objects)
    return replace(query, about=about, objects=objects)
