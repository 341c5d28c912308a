"""Predicate verification (paper Sec. IV-B): paraphrases, majority vote, view sufficiency.

One *round* looks at one observation: it asks the N paraphrased questions about an atom, takes
the majority of the usable answers, and — when the answers agree — asks whether the view was
good enough. A round is *settled* when the answers agree and the view is sufficient; otherwise
active perception (the BT decorator in :mod:`vap_bt.bt.active_perception`) asks the viewpoint
prompt, moves, and runs another round, up to its budget K.

How much is asked, and when, is the verification protocol's business
(:mod:`vap_bt.perception.protocol`: the paper's, or a lean one); :class:`RoundAsker` carries a
round out under either without ever waiting for an answer.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from vap_bt.domain.atoms import Atom
from vap_bt.domain.roles import HOUSEHOLD, Roles
from vap_bt.perception import prompts
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.perception.protocol import Protocol
from vap_bt.perception.vlm import VLM, Answer, Query
from vap_bt.robot.camera import VIEW_DIRECTIONS
from vap_bt.robot.frame import Frame, at_edge
from vap_bt.scene.identity import named_relations


@dataclass(frozen=True)
class VoteSettings:
    """How a round votes: N paraphrases, the share of answers that must agree, and whether to stop asking
    once nothing left could change the vote."""

    paraphrases: int = 5  # N
    agreement: float = 0.8  # share of answers that must agree for "responses consistent" (4 of 5)
    early_stop: bool = False


@dataclass
class Round:
    """One round of a check: the questions asked of one frame and their answers, the vote, the view's
    sufficiency and who judged it, and where the camera went next."""

    view: str  # the frame's id
    questions: list[str] = field(default_factory=list)
    answers: list[bool | None] = field(default_factory=list)
    vote: bool | None = None
    consistent: bool = False
    sufficient: bool | None = None
    direction: str | None = None  # the viewpoint moved to (or last tried) after this round, if any
    moved: bool | None = None  # whether the camera could go there
    #: directions tried after this round that the robot could not move to (before ``direction``)
    refused: tuple[str, ...] = ()
    unshown: tuple[str, ...] = ()  # objects of the atom the frame's detector did not find
    #: who judged the view: "model" (the sufficiency question was asked), "detector" (it found an
    #: object missing, or — where the protocol lets it — everything whole) or "assumed" (a protocol
    #: that never asks: :attr:`Protocol.sufficiency`); None when not judged
    sufficient_by: str | None = None
    #: which of the frame's detections the robot took for each of the atom's objects (its own
    #: re-identification: name -> the detection's index), so a report can say what it looked at
    identified: dict[str, int] = field(default_factory=dict)
    #: where the camera stood for the picture (its believed pose, rounded: :func:`stand_of`); two
    #: rounds from one stand are one picture — the model answers it the same way every time
    stand: tuple | None = None
    #: where the frame's relation detector put the atom's item, for a location atom: True where
    #: the atom says, False elsewhere, None when it reported no place (:func:`located`)
    located: bool | None = None

    @property
    def settled(self) -> bool:
        """Whether the round decides its atom: the answers agree on a value and the view was judged
        sufficient."""
        return self.consistent and self.sufficient is True and self.vote is not None

    def to_json(self) -> dict:
        return {"view": self.view, "answers": ["?" if a is None else ("yes" if a else "no") for a in self.answers],
                "vote": self.vote, "consistent": self.consistent, "sufficient": self.sufficient,
                "direction": self.direction, "moved": self.moved, **({"refused": list(self.refused)} if self.refused else {}),
                **({"unshown": list(self.unshown)} if self.unshown else {}),
                **({"sufficient_by": self.sufficient_by} if self.sufficient_by == "detector" else {}),
                "identified": dict(self.identified),
                **({"located": self.located} if self.located is not None else {})}


def objects_of(atom: Atom) -> tuple[str, ...]:
    """The objects a question about ``atom`` concerns (its arguments): what the simulated model looks for
    in the frame."""
    return atom.args


def unshown(frame: Frame, atom: Atom, undetectable: frozenset[str] = frozenset()) -> tuple[str, ...]:
    """The objects ``atom`` names that the frame's detector did not find (rooms and floors, the
    map's, are never detected and never missing). A view that shows none of a thing cannot
    settle a question about it, whatever a model says: the detector vetoes sufficiency. The
    frame is an identified one (:mod:`vap_bt.scene.identity`): a detection of the thing's class
    the robot did not take for it does not show it."""
    found = frame.detected()
    return tuple(o for o in objects_of(atom) if o not in found and o not in undetectable)


def located(frame: Frame, atom: Atom, undetectable: frozenset[str] = frozenset(),
            roles: Roles = HOUSEHOLD) -> bool | None:
    """Where the frame's relation detector (a world that reports relations with its detections:
    :attr:`~vap_bt.robot.frame.Detection.relations`) put the item of a location atom: True if at
    the atom's place, False if at another, None when it reported none — or when the frame does
    not show the place itself, since a detector can only choose among the places in view (an
    item beside a basket out of the picture would always read "not inside")."""
    if not roles.supports(atom) or unshown(frame, atom, undetectable):
        return None
    item = atom.args[0]
    k = frame.identified().get(item)  # None: a thing of the map, never detected
    if k is None:
        return None
    places = [a for a in named_relations(frame, k) if (roles.supports(a) or roles.is_held(a)) and a.args[0] == item]
    return (atom in places) if places else None


def shown_plainly(frame: Frame, atom: Atom, undetectable: frozenset[str], least_share: float,
                  large_share: float = 1.0) -> bool:
    """Whether the frame's detector finds every object ``atom`` names (rooms and floors aside)
    plainly in view: whole and not tiny (its mask clear of the image's edges and at least
    ``least_share`` of the image), or large (at least ``large_share`` of the image, however much
    of it the edges cut off: a table top filling the view). False where it cannot tell (no masks
    in the frame)."""
    if frame.masks is None:
        return False
    h, w = frame.masks.shape
    for name in objects_of(atom):
        if name in undetectable:
            continue
        mask = frame.mask(name)
        share = 0.0 if mask is None else mask.sum() / (h * w)
        if share >= large_share:
            continue
        if share < least_share:
            return False
        if at_edge(mask):
            return False
    return True


class RoundAsker:
    """One round of questions about one frame, asked as a protocol says, fed answers as they come.

    It never waits: :meth:`to_ask` says which questions to send now (their indices), the caller
    sends them however it likes (in flight at once, or one after another) and hands each answer
    to :meth:`give`; :attr:`done` says when the round is decided, and :meth:`finish` votes it.
    Which questions go when:

    * paper (sequential, no early stop): one after another, every one of the N;
    * early stop: sequential, stopping once nothing left could change the vote or its consistency;
    * concurrent: in waves — the fewest answers that could decide the round, all at once, then
      as many more as could still decide it;
    * logprobs: the first question alone; an answer whose confidence reaches the protocol's
      ``confident`` stands for the whole vote, otherwise the others are asked as above;
    * unanimous: a round settles once ``protocol.unanimous`` answers all agree (three
      paraphrases, none abstaining), without the rest.

    The last two take fewer answers than the paper only for a value the plan ``expected``: a
    surprise (a situation: belief is corrected and the robot replans on it) is always put to the
    paper's full vote, 4 of 5 agreeing, so that the cheaper protocol costs nothing in wrong
    corrections. Without an expectation (a survey's question) they apply to either value.
    """

    def __init__(self, atom: Atom, frame: Frame, s: VoteSettings, profile: PerceptionProfile,
                 protocol: Protocol | None = None, expected: bool | None = None) -> None:
        self.atom, self.frame, self.s, self.expected = atom, frame, s, expected
        self.protocol = protocol or Protocol("paper", early_stop=s.early_stop)
        self.questions = profile.questions(atom, s.paraphrases)
        self.queries = [Query(prompts.predicate_query(q), about=(atom,), objects=objects_of(atom)) for q in self.questions]
        self.need = s.agreement * len(self.questions)
        self.answers: dict[int, bool | None] = {}
        self.asked: list[int] = []
        self.confident: bool | None = None  # the one logprob answer that stood for the vote

    def _counts(self) -> tuple[int, int]:
        vals = list(self.answers.values())
        return sum(a is True for a in vals), sum(a is False for a in vals)

    @property
    def outstanding(self) -> int:
        """How many questions have been sent and not yet answered."""
        return len(self.asked) - len(self.answers)

    def _may_shorten(self, value: bool) -> bool:
        """Whether fewer answers than the paper's may settle ``value``: only an expected one."""
        return self.expected is None or value == self.expected

    def _agreeing(self) -> bool | None:
        """The value every answer so far gives (none abstaining), when fewer answers may settle
        it; None otherwise (no answers yet, disagreement, an abstention, or a surprise)."""
        vals = set(self.answers.values())
        if len(vals) != 1 or None in vals:
            return None
        value = vals.pop()
        return value if self._may_shorten(value) else None

    @property
    def unanimous(self) -> bool:
        """``protocol.unanimous`` answers or more, all agreeing on a value they may settle."""
        k = self.protocol.unanimous
        return bool(k) and len(self.answers) >= k and self._agreeing() is not None

    @property
    def done(self) -> bool:
        """Whether the round needs no more answers: all are in, a confident answer stood for the vote, or
        (as the protocol allows) nothing still to ask could change the vote. Never while answers are
        outstanding, short of a confident one."""
        if self.confident is not None:
            return True
        if len(self.answers) == len(self.questions):
            return True
        if self.outstanding:
            return False
        if self.unanimous:
            return True
        early = self.protocol.early_stop or self.protocol.concurrent
        return early and _decided(self._ordered(), len(self.questions), self.need)

    def _ordered(self) -> list[bool | None]:
        return [self.answers[i] for i in sorted(self.answers)]

    def to_ask(self) -> list[int]:
        """Indices of the questions to send now (empty: wait, or the round is done)."""
        if self.done or self.outstanding:
            return []
        left = [i for i in range(len(self.questions)) if i not in self.asked]
        if self.protocol.logprobs and not self.asked:
            wave = left[:1]
        elif not self.protocol.concurrent:
            wave = left[:1]
        elif not self.protocol.early_stop:
            wave = left
        else:
            yes, no = self._counts()
            want = math.ceil(self.need - 1e-9) - max(yes, no)
            if self.protocol.unanimous and (not self.answers or self._agreeing() is not None):
                want = min(want, self.protocol.unanimous - len(self.answers))
            wave = left[:max(1, want)]
        self.asked += wave
        return wave

    def give(self, index: int, answer: Answer) -> None:
        """Record the answer to question ``index``; anything but a yes or no is an abstention. Under
        ``logprobs`` a confident first answer may stand for the whole vote."""
        value = answer.value if isinstance(answer.value, bool) else None
        self.answers[index] = value
        if (self.protocol.logprobs and len(self.asked) == 1 and value is not None and answer.confidence is not None
                and answer.confidence >= self.protocol.confident and self._may_shorten(value)):
            self.confident = value

    def finish(self) -> Round:
        """The round as asked: its questions, answers, vote v_p = 1[mean(y) > 0.5] over the usable
        answers (none usable: no vote) and whether they agree enough to be consistent."""
        r = Round(view=self.frame.frame_id, stand=stand_of(self.frame),
                  identified={n: k for n, k in self.frame.identified().items() if n in objects_of(self.atom)})
        for i in sorted(self.answers):
            r.questions.append(self.questions[i])
            r.answers.append(self.answers[i])
        yes, no = self._counts()
        if self.confident is not None:
            r.vote, r.consistent = self.confident, True
            return r
        r.vote = (yes * 2 > yes + no) if yes + no else None
        r.consistent = max(yes, no) >= self.need or self.unanimous
        return r


def vote_round(vlm: VLM, obs: Frame, atom: Atom, s: VoteSettings, profile: PerceptionProfile,
               protocol: Protocol | None = None, expected: bool | None = None) -> Round:
    """Ask the paraphrases of ``atom`` (its domain's ``profile`` has them) about ``obs`` and vote (paper Alg. 2, lines 2–4), waiting
    for each answer (the survey, and tests; behaviours use :class:`RoundAsker` without waiting)."""
    asker = RoundAsker(atom, obs, s, profile, protocol, expected)
    while not asker.done:
        for i in asker.to_ask():
            asker.give(i, vlm.ask(asker.queries[i], obs))
    return asker.finish()


def _decided(answers: list[bool | None], total: int, need: float) -> bool:
    """True once no remaining answer can change the round's outcome (vote and consistency)."""
    yes = sum(a is True for a in answers)
    no = sum(a is False for a in answers)
    left = total - len(answers)
    vote_fixed = yes > no + left or no >= yes + left  # ties go to False, as mean(y) > 0.5 does
    consistency_fixed = max(yes, no) >= need or max(yes, no) + left < need
    return vote_fixed and consistency_fixed


def sufficiency_query(atom: Atom, question: str) -> Query:
    """The view-sufficiency prompt (appendix) for a round's first question."""
    return Query(prompts.view_sufficiency(question), purpose="sufficiency", about=(atom,), objects=objects_of(atom))


def viewpoint_query(atom: Atom, question: str, target: str) -> Query:
    """The viewpoint-selection prompt (appendix): one of left/right/front/behind/above/closer."""
    return Query(prompts.viewpoint_selection(question, target), kind="choice", purpose="viewpoint",
                 about=(atom,), objects=objects_of(atom), options=VIEW_DIRECTIONS)


def yes_no(answer: Answer) -> bool | None:
    """The answer's yes or no; None for no usable answer (or a choice)."""
    return answer.value if isinstance(answer.value, bool) else None


def choice(answer: Answer) -> str | None:
    """The option the answer named; None for no usable answer (or a yes or no)."""
    return answer.value if isinstance(answer.value, str) else None


def check_sufficiency(vlm: VLM, obs: Frame, atom: Atom, question: str) -> bool | None:
    """Ask the view-sufficiency question and wait for the answer."""
    return yes_no(vlm.ask(sufficiency_query(atom, question), obs))


def suggest_viewpoint(vlm: VLM, obs: Frame, atom: Atom, question: str, target: str) -> str | None:
    """Ask the viewpoint-selection question and wait for the answer."""
    return choice(vlm.ask(viewpoint_query(atom, question, target), obs))


def target_of(atom: Atom) -> str:
    """The object to look at for an atom: its first argument (the robot for hand_empty)."""
    return atom.args[0] if atom.args else "gripper"


#: views that showed the atom's objects, with consistent answers, that must agree (and none say
#: otherwise) for a check with its budget spent to stand without a settled view (see :func:`verdict`)
AGREEING_VIEWS = 2


@dataclass(frozen=True)
class Verdict:
    """What a check's views say together: a value and how it was reached, or nothing yet."""

    value: bool
    outcome: str  # "settled" (views agree), "agreed" (budget spent, every view agreed), "unsettled"


#: a stand's position to this (metres) and its viewing direction to this (unit-vector components)
STAND_STEP = 0.02


def stand_of(frame: Frame) -> tuple | None:
    """Where the camera stood for ``frame``, rounded to :data:`STAND_STEP`; in a world without
    camera poses, the frame's named stand (:attr:`Frame.stand`); None without either."""
    T = frame.camera_pose
    if T is None:
        return (frame.stand,) if frame.stand else None
    return tuple(int(round(float(v) / STAND_STEP)) for v in (*T[:3, 3], *T[:3, 2]))


def distinct(rounds: list[Round]) -> list[Round]:
    """The rounds of different pictures: of rounds from one stand (:attr:`Round.stand`) only the
    last counts — the same picture asked again is the same draw of the model's errors, not a
    second opinion (a robot sent back to one stand again and again would otherwise pile up
    agreeing "views" of one wrong answer)."""
    last = {r.stand: k for k, r in enumerate(rounds) if r.stand is not None}
    return [r for k, r in enumerate(rounds) if r.stand is None or last[r.stand] == k]


def votes(rounds: list[Round]) -> list[bool]:
    """What the views voted: one value for each round whose detector showed the atom's objects
    and whose answers were consistent (see :func:`verdict`)."""
    return [r.vote for r in rounds if not r.unshown and r.consistent and r.vote is not None]


def verdict(rounds: list[Round], exhausted: bool) -> Verdict | None:
    """Weigh every view of one check (the paper's Alg. 2 takes the first settled round; one lucky
    round after views that said otherwise is too close to a guess to rewrite belief):

    * a settled round decides at once when no other view voted otherwise;
    * when views disagree, a value needs more settled rounds for it than views voting against it
      (a coin-flip view that happened to look sure is outvoted by the views that did not); a view
      votes when its answers were consistent (the paper's gate for a round to mean anything,
      sufficient or not): one whose paraphrases disagreed among themselves says nothing either way;
    * with the budget spent (``exhausted``) and nothing decided, a value stands only if at least
      ``AGREEING_VIEWS`` views that showed the atom's objects voted for it and none voted against
      (independent views agreeing is evidence; one view the model found insufficient is not);
      otherwise the check is ``unsettled``: it does not overturn belief.

    A view whose detector did not find the atom's objects (``unshown``) votes nothing: its
    answers are guesses about a thing it does not show.

    Rounds from one stand count once (:func:`distinct`). Returns None while the check should
    keep looking."""
    rounds = distinct(rounds)
    voted = votes(rounds)
    for value in (True, False):
        settled = sum(r.settled and r.vote == value for r in rounds)
        against = sum(v != value for v in voted)
        if settled and (against == 0 or settled > against):
            return Verdict(value, "settled")
    if not exhausted:
        return None
    if len(voted) >= AGREEING_VIEWS and len(set(voted)) == 1:
        return Verdict(voted[0], "agreed")
    return Verdict(False, "unsettled")
