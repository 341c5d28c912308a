"""What the symbolic world's relation detector reports about an item in a frame, and how it errs.

A world without pixels gives the executive no geometry to measure, so each detection of an item
carries *relation reports* instead (:attr:`~vap_bt.robot.frame.Detection.relations`): where it
rests, the room it is in and, in domains that have them, what blocks it and whether it can be
reached. A real RGB-D pipeline gets these wrong where the picture shows them poorly — a contact
hidden behind the front of a shelf, a container's inside seen at a grazing angle, two things
overlapping — so the reports err by model vlm-2's rule (:mod:`vap_bt.sim.latent`) over the
evidence the simulated VLM reads from the same frame (:mod:`vap_bt.sim.observability`, from the
view's :class:`~vap_bt.sim.captures.ObjectView` shares: contact, interior, fingers, visibility).
They are not coin flips at a fixed rate: a report is wrong the more often the worse its view
shows its relation, errors about one relation class in one view go together, and the same view
always gives the same reports. A report is right iff

    z = ± o · Φ⁻¹(A) + noise · ( √ρ e_class + √(1 − ρ) e_atom )

is positive (``A``, ``ρ``, ``noise``: :class:`~vap_bt.sim.detector.DetectorModel`'s ``accuracy``,
``view_correlation`` and ``relation_noise``; no bias towards yes, as a geometric test has none;
the draws are keyed by the run's seed, the view and what they are shared by, and are this
detector's own: the simulated VLM reads the same view with draws of its own):

* **where it rests** — one report, a choice among the places the frame shows it could rest at:
  its true place (support, container or hand), read right iff ``z`` > 0 with ``o`` the true
  relation's observability (``on``: the item's contact with its support; ``inside``: the
  container's inside, or half of the item; ``holding``: the fingers and the item); otherwise one
  of the other places in the frame, drawn uniformly per view (none when the frame shows no
  other). The places are the surfaces in the frame and the floor of the room, the containers in
  the frame that are open (nothing is seen inside a shut one), and the hand for what it holds
  only (a cup on a table is never read as held). With a support comes the room the camera is in
  (the map's, not the detector's: exact).
* **what blocks it, whether it can be reached** — a yes or a no for every candidate:
  ``reachable(x)``, and ``blocking(b, x)`` and ``blocking(x, b)`` for every other item ``b`` in
  the frame resting on the same thing (the pairs a geometric test compares); ``o`` is the smaller
  share of the two items the view shows. The draw is keyed by the atom, so the detections of both
  items of a pair report it alike.
* An item in a shut container is never in a frame (:mod:`vap_bt.sim.symbolic`), so nothing is
  ever reported of it; an item the hand holds gets no blocking or reachable reports.
"""

from __future__ import annotations

import math

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import DomainKnowledge
from vap_bt.scene.layout import floor_of
from vap_bt.sim.captures import CaptureRecord
from vap_bt.sim.detector import DetectorModel
from vap_bt.sim.latent import draw_normal, draw_uniform, score, signal
from vap_bt.sim.observability import Observability

#: what says where an item rests, one of them at a time
PLACES = ("holding", "on", "inside")


class RelationDetector:
    """The symbolic relation detector described in the module docstring."""

    def __init__(self, model: DetectorModel, knowledge: DomainKnowledge, objects: dict[str, str], seed: int = 0) -> None:
        self.model, self.knowledge, self.objects, self.seed = model, knowledge, objects, seed
        self.rooms = frozenset(o for o, t in objects.items() if t == "room")
        self._index: _TruthIndex | None = None

    def _indexed(self, truth: frozenset[Atom]) -> "_TruthIndex":
        """``truth`` indexed by object, built once per state: a frame reports on every item it
        shows against the same truth, and scanning it per item and per pair cost 97 % of an
        IPC episode with a thousand facts (caldera: 180 of 204 s)."""
        if self._index is None or self._index.truth is not truth:
            self._index = _TruthIndex(truth)
        return self._index

    def report(self, record: CaptureRecord, item: str, truth: frozenset[Atom], room: str | None) -> tuple[Atom, ...]:
        """The relations reported with ``item``'s detection in the frame ``record`` describes;
        ``truth`` holds at capture, ``room`` is where the camera is."""
        seen = Observability(record, self.rooms)
        out = []
        where = self._where(record, seen, item, truth, room)
        if where is not None:
            out.append(where)
            if where.predicate != "holding" and room is not None and self._fits(Atom("in_room", (item, room))):
                out.append(Atom("in_room", (item, room)))
        out += [a for a in self._candidates(record, item, truth) if self._reads_yes(record, seen, a)]
        return tuple(out)

    # -- where it rests ----------------------------------------------------------------------

    def _where(self, record: CaptureRecord, seen: Observability, item: str, truth: frozenset[Atom],
               room: str | None) -> Atom | None:
        true = next((a for a in self._indexed(truth).places.get(item, ()) if self._fits(a)), None)
        if true is None:
            return None
        if self._reads_yes(record, seen, true):
            return true
        others = [p for p in self._places(record, item, truth, room) if p != true]
        if not others:
            return None
        pick = draw_uniform(self.seed, record.picture_key, "detector", "misplaced", item)
        return others[min(len(others) - 1, int(pick * len(others)))]

    def _places(self, record: CaptureRecord, item: str, truth: frozenset[Atom], room: str | None) -> list[Atom]:
        """Where the frame shows ``item`` could rest (see the module docstring)."""
        out = [Atom("holding", (item,))] if Atom("holding", (item,)) in truth else []
        shown = sorted(o for o, v in record.visibility.items() if v > 0.0 and o != item)
        floor = floor_of(room) if room is not None else None
        for pred in ("on", "inside"):
            for y in [*shown, *([floor] if pred == "on" and floor in self.objects and floor not in shown else [])]:
                a = Atom(pred, (item, y))
                if self._fits(a) and not (pred == "inside" and Atom("closed", (y,)) in truth):
                    out.append(a)
        return out

    # -- yes or no ---------------------------------------------------------------------------

    def _candidates(self, record: CaptureRecord, item: str, truth: frozenset[Atom]) -> list[Atom]:
        """The blocking and reachable atoms a geometric test would decide about ``item``."""
        index = self._indexed(truth)
        if item in index.held:
            return []
        out = [a for a in (Atom("reachable", (item,)),) if self._fits(a)]
        if "blocking" not in self.knowledge.predicates:
            return out
        rests = index.supports.get(item, set())
        for b in sorted(o for o, v in record.visibility.items() if v > 0.0 and o != item and o not in index.held):
            if rests & index.supports.get(b, set()):
                out += [a for a in (Atom("blocking", (b, item)), Atom("blocking", (item, b))) if self._fits(a)]
        return out

    def _reads_yes(self, record: CaptureRecord, seen: Observability, atom: Atom) -> bool:
        """Whether the detector reads ``atom`` as holding in this view (the module's rule)."""
        m = self.model
        e = seen.evidence(atom)
        picture = record.picture_key
        rho = m.view_correlation
        shared = (math.sqrt(rho) * draw_normal(self.seed, picture, "detector", e.relation)
                  + math.sqrt(1.0 - rho) * draw_normal(self.seed, picture, "detector", str(atom)))
        return score(e.apparent, signal(e.observability, m.accuracy), e.observability, m.relation_noise, 0.0,
                     shared) > 0

    def _fits(self, atom: Atom) -> bool:
        """``atom`` is a predicate of the domain over objects of the right types."""
        sig = self.knowledge.predicates.get(atom.predicate)
        return sig is not None and len(sig) == len(atom.args) and all(
            x in self.objects and self.knowledge.is_subtype(self.objects[x], t) for x, t in zip(atom.args, sig))


class _TruthIndex:
    """One state's facts by object: where each thing rests (``places``, sorted as the state's
    atoms sort), what it stands on or is in (``supports``), and what the hand holds."""

    def __init__(self, truth: frozenset[Atom]) -> None:
        self.truth = truth
        self.places: dict[str, list[Atom]] = {}
        self.supports: dict[str, set[str]] = {}
        self.held: set[str] = set()
        for a in sorted(truth):
            if a.predicate in PLACES and a.args:
                self.places.setdefault(a.args[0], []).append(a)
            if a.predicate in ("on", "inside") and len(a.args) == 2:
                self.supports.setdefault(a.args[0], set()).add(a.args[1])
            if a.predicate == "holding" and a.args:
                self.held.add(a.args[0])
