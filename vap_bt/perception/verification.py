"""Predicate verification (paper Sec. IV-B): paraphrases, majority vote, view sufficiency.

One *round* looks at one observation: it asks the N paraphrased questions about an atom, takes
the majority of the usable answers, and — when the answers agree — asks whether the view was
good enough. A round is *settled* when the answers agree and the view is sufficient; otherwise
active perception (the BT decorator in :mod:`vap_bt.bt.active_perception`) asks the viewpoint
prompt, moves, and runs another round, up to its budget K.

Two switches go beyond the paper and are off unless asked for: ``early_stop`` stops asking once
neither the vote nor its consistency can change, and the caller may run rounds concurrently.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from vap_bt.domain.atoms import Atom
from vap_bt.perception import prompts
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.perception.vlm import VLM, Query
from vap_bt.robot.camera import VIEW_DIRECTIONS
from vap_bt.robot.frame import Frame


@dataclass(frozen=True)
class VoteSettings:
    paraphrases: int = 5  # N
    agreement: float = 0.8  # share of answers that must agree for "responses consistent" (4 of 5)
    early_stop: bool = False


@dataclass
class Round:
    view: str  # the frame's id
    questions: list[str] = field(default_factory=list)
    answers: list[bool | None] = field(default_factory=list)
    vote: bool | None = None
    consistent: bool = False
    sufficient: bool | None = None
    direction: str | None = None  # the viewpoint suggested after this round, if any
    moved: bool | None = None  # whether the camera could go there

    @property
    def settled(self) -> bool:
        return self.consistent and self.sufficient is True and self.vote is not None

    def to_json(self) -> dict:
        return {"view": self.view, "answers": ["?" if a is None else ("yes" if a else "no") for a in self.answers],
                "vote": self.vote, "consistent": self.consistent, "sufficient": self.sufficient,
                "direction": self.direction, "moved": self.moved}


def objects_of(atom: Atom) -> tuple[str, ...]:
    return atom.args


def vote_round(vlm: VLM, obs: Frame, atom: Atom, s: VoteSettings, profile: PerceptionProfile) -> Round:
    """Ask the paraphrases of ``atom`` (its domain's ``profile`` has them) about ``obs`` and vote
    (paper Alg. 2, lines 2–4)."""
    qs = profile.questions(atom, s.paraphrases)
    r = Round(view=obs.frame_id)
    need = s.agreement * len(qs)
    for q in qs:
        ans = vlm.ask(Query(prompts.predicate_query(q), about=(atom,), objects=objects_of(atom)), obs).value
        r.questions.append(q)
        r.answers.append(ans if isinstance(ans, bool) else None)
        if s.early_stop and _decided(r.answers, len(qs), need):
            break
    yes = sum(a is True for a in r.answers)
    no = sum(a is False for a in r.answers)
    # v_p = 1[mean(y) > 0.5] over the usable answers; with none usable there is no vote
    r.vote = (yes * 2 > yes + no) if yes + no else None
    r.consistent = max(yes, no) >= need
    return r


def _decided(answers: list[bool | None], total: int, need: float) -> bool:
    """True once no remaining answer can change the round's outcome (vote and consistency)."""
    yes = sum(a is True for a in answers)
    no = sum(a is False for a in answers)
    left = total - len(answers)
    vote_fixed = yes > no + left or no + 0 >= yes + left  # ties go to False, as mean(y) > 0.5 does
    consistency_fixed = max(yes, no) >= need or max(yes, no) + left < need
    return vote_fixed and consistency_fixed


def check_sufficiency(vlm: VLM, obs: Frame, atom: Atom, question: str) -> bool | None:
    """The view-sufficiency prompt (appendix) for the round's first question."""
    q = Query(prompts.view_sufficiency(question), purpose="sufficiency", about=(atom,), objects=objects_of(atom))
    ans = vlm.ask(q, obs).value
    return ans if isinstance(ans, bool) else None


def suggest_viewpoint(vlm: VLM, obs: Frame, atom: Atom, question: str, target: str) -> str | None:
    """The viewpoint-selection prompt (appendix): one of left/right/front/behind/above/closer."""
    q = Query(prompts.viewpoint_selection(question, target), kind="choice", purpose="viewpoint",
              about=(atom,), objects=objects_of(atom), options=VIEW_DIRECTIONS)
    ans = vlm.ask(q, obs).value
    return ans if isinstance(ans, str) else None


def target_of(atom: Atom) -> str:
    """The object to look at for an atom: its first argument (the robot for hand_empty)."""
    return atom.args[0] if atom.args else "gripper"


@dataclass(frozen=True)
class Verdict:
    """What a check's views say together: a value and how it was reached, or nothing yet."""

    value: bool
    outcome: str  # "settled" (views agree), "agreed" (budget spent, every view agreed), "unsettled"


def verdict(rounds: list[Round], exhausted: bool) -> Verdict | None:
    """Weigh every view of one check (the paper's Alg. 2 takes the first settled round; one lucky
    round after views that said otherwise is too close to a guess to rewrite belief):

    * a settled round decides at once when no other view voted otherwise;
    * when views disagree, a value needs more settled rounds for it than views voting against it
      (a coin-flip view that happened to look sure is outvoted by the views that did not);
    * with the budget spent (``exhausted``) and nothing decided, a value stands only if every
      view's answers agreed on it (independent views agreeing is evidence); otherwise the check
      is ``unsettled``: it does not overturn belief.

    Returns None while the check should keep looking."""
    votes = [r.vote for r in rounds if r.vote is not None]
    for value in (True, False):
        settled = sum(r.settled and r.vote == value for r in rounds)
        against = sum(v != value for v in votes)
        if settled and (against == 0 or settled > against):
            return Verdict(value, "settled")
    if not exhausted:
        return None
    agreed = {r.vote for r in rounds}
    if all(r.consistent for r in rounds) and len(agreed) == 1 and None not in agreed:
        return Verdict(agreed.pop(), "agreed")
    return Verdict(False, "unsettled")
