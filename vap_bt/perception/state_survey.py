"""Asking the VLM about states geometry cannot give, during the initial survey.

Where things are comes from geometry; whether a door, a cabinet or a fridge is open does not (an
open door leaf is just more points). So for every container and door the sweep saw, the survey
asks ``open(x)`` through the normal verification path — the N paraphrases, the vote and the
view-sufficiency question — of the frames that showed it best, best first, until a round
settles (the robot does not move for it: these are the sweep's own views). A settled answer is
believed; otherwise the task file's prior, else the closed-world default, stands
(:mod:`vap_bt.scene.belief`).

Other states (filled, heated, sliced, turned_on) are not asked here: they are rarely judgeable
from across a room, they start from the task file's prior (default false), and every action that
needs one verifies it as a precondition before it acts.
"""

from __future__ import annotations

from concurrent.futures import Executor
from dataclasses import dataclass

from vap_bt.domain.atoms import Atom
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.perception.protocol import Protocol
from vap_bt.perception.verification import Round, VoteSettings, check_sufficiency, shown_plainly, vote_round
from vap_bt.perception.vlm import VLM
from vap_bt.robot.frame import Frame

#: state predicates the survey asks about; their complements follow (closed for open)
SURVEYED = ("open",)


@dataclass
class StateAnswer:
    """One surveyed atom: the round asked, and the value it settled on (None: unsettled)."""

    atom: Atom
    rounds: list[Round]

    @property
    def value(self) -> bool | None:
        """The last round's vote if it settled; None leaves belief to the prior."""
        last = self.rounds[-1]
        return last.vote if last.settled else None

    def to_json(self) -> dict:
        return {"predicate": str(self.atom), "value": self.value, "rounds": [r.to_json() for r in self.rounds]}


def survey_states(vlm: VLM, frames: dict[str, list[Frame]], candidates: list[str], vote: VoteSettings,
                  profile: PerceptionProfile, predicates: tuple[str, ...] = SURVEYED,
                  protocol: Protocol | None = None, undetectable: frozenset[str] = frozenset(),
                  executor: Executor | None = None) -> list[StateAnswer]:
    """Ask each of ``predicates`` the profile asks of the VLM about each candidate, of the frames
    that showed it, until settled — as ``protocol`` asks (default: the paper's). Given an
    ``executor`` and a protocol that asks concurrently, every candidate is asked about at once
    (each candidate's frames still one after another: the next is looked at only if the last
    did not settle)."""
    predicates = tuple(p for p in predicates if profile.asks(p, 1))
    jobs = [(Atom(p, (name,)), frames[name]) for name in candidates if frames.get(name) for p in predicates]

    def ask(atom: Atom, shown: list[Frame]) -> StateAnswer:
        rounds = []
        for frame in shown:
            rounds.append(_round(vlm, frame, atom, vote, profile, protocol, undetectable))
            if rounds[-1].settled:
                break
        return StateAnswer(atom, rounds)

    if executor is not None and protocol is not None and protocol.concurrent:
        return list(executor.map(lambda job: ask(*job), jobs))
    return [ask(*job) for job in jobs]


def _round(vlm: VLM, frame: Frame, atom: Atom, vote: VoteSettings, profile: PerceptionProfile,
           protocol: Protocol | None, undetectable: frozenset[str]) -> Round:
    """One round about one of the sweep's frames; the view-sufficiency question only when the
    answers agree, the protocol asks it at all, and (where the protocol lets it) the detector does
    not already show the thing plainly."""
    r = vote_round(vlm, frame, atom, vote, profile, protocol)
    if not (r.consistent and r.vote is not None):
        return r
    if protocol is not None and not protocol.sufficiency:
        r.sufficient, r.sufficient_by = True, "assumed"
    elif protocol is not None and protocol.detector and shown_plainly(frame, atom, undetectable, protocol.whole_share,
                                                                     protocol.large_share):
        r.sufficient, r.sufficient_by = True, "detector"
    else:
        r.sufficient, r.sufficient_by = check_sufficiency(vlm, frame, atom, r.questions[0]), "model"
    return r
