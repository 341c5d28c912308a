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

from dataclasses import dataclass

from vap_bt.domain.atoms import Atom
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.perception.verification import Round, VoteSettings, check_sufficiency, vote_round
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
        last = self.rounds[-1]
        return last.vote if last.settled else None

    def to_json(self) -> dict:
        return {"predicate": str(self.atom), "value": self.value, "rounds": [r.to_json() for r in self.rounds]}


def survey_states(vlm: VLM, frames: dict[str, list[Frame]], candidates: list[str], vote: VoteSettings,
                  profile: PerceptionProfile, predicates: tuple[str, ...] = SURVEYED) -> list[StateAnswer]:
    """Ask each of ``predicates`` the profile asks of the VLM about each candidate, of the frames
    that showed it, until settled."""
    out = []
    predicates = tuple(p for p in predicates if profile.asks(p, 1))
    for name in candidates:
        shown = frames.get(name, [])
        for p in predicates:
            atom, rounds = Atom(p, (name,)), []
            for frame in shown:
                r = vote_round(vlm, frame, atom, vote, profile)
                if r.consistent and r.vote is not None:
                    r.sufficient, r.sufficient_by = check_sufficiency(vlm, frame, atom, r.questions[0]), "model"
                rounds.append(r)
                if r.settled:
                    break
            if rounds:
                out.append(StateAnswer(atom, rounds))
    return out
