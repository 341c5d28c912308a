"""Predicate verification: prompts verbatim from the paper, voting, and the simulated VLM."""

from __future__ import annotations

import re

import pytest

from vap_bt.domain.atoms import Atom
from vap_bt.perception import prompts
from vap_bt.perception.verification import VoteSettings, vote_round
from vap_bt.perception.vlm import Answer, Query, parse_choice, parse_yes_no
from vap_bt.sim.symbolic_vlm import SymbolicVLM
from vap_bt.world import Observation

from conftest import PAPER


def _paper_texttt() -> str:
    text = PAPER.read_text()
    appendix = text[text.index("\\begin{appendices}"):]
    return re.sub(r"\s+", " ", appendix)


def _tex(s: str) -> str:
    return s.replace("_", "\\_").replace("{", "\\{").replace("}", "\\}")


@pytest.mark.skipif(not PAPER.exists(), reason=f"the paper is not beside the checkout ({PAPER})")
def test_paper_paraphrases_are_verbatim():
    appendix = _paper_texttt()
    book = prompts.book()
    paper_preds = [p for p, src in book.sources.items() if src == "paper"]
    assert len(paper_preds) == 9
    for pred in paper_preds:
        for q in book.paraphrases[pred]:
            assert f"\\texttt{{{_tex(q)}}}" in appendix, (pred, q)


@pytest.mark.skipif(not PAPER.exists(), reason=f"the paper is not beside the checkout ({PAPER})")
def test_paper_prompt_templates_are_verbatim():
    appendix = _paper_texttt()
    book = prompts.book()
    for line in ("You are a robot task planner. Convert the natural language instruction into a goal state.",
                 "Analyze this image carefully.",
                 "Choose the single best direction:",
                 "Options: left, right, front, behind, above, closer"):
        assert line in book.goal_parsing + book.predicate_query + book.viewpoint_selection
        assert line in appendix


def test_strict_answer_parsing():
    assert parse_yes_no("Yes.") is True and parse_yes_no("no, it is not") is False
    assert parse_yes_no("I think so") is None and parse_yes_no("") is None
    opts = ("left", "right", "closer")
    assert parse_choice("Move closer.", opts) == "closer"
    assert parse_choice("left or right", opts) is None


class Scripted:
    """A VLM that replays given answers: for testing the vote arithmetic, nothing else."""

    name = "scripted"

    def __init__(self, answers):
        self.answers = list(answers)

    def ask(self, query: Query, obs: Observation) -> Answer:
        a = self.answers.pop(0)
        return Answer(str(a), a)

    def describe(self):
        return {"backend": self.name}


OBS = Observation(view_index=0, targets=("cup",), visibility={"cup": 1.0})
CUP = Atom("on", ("cup", "table"))


@pytest.mark.parametrize("answers,vote,consistent", [
    ([True] * 5, True, True),
    ([True, True, True, True, False], True, True),  # 4 of 5: the paper's own example
    ([True, True, True, False, False], True, False),
    ([False, None, False, False, False], False, True),
    ([None] * 5, None, False),
])
def test_majority_vote_and_consistency(answers, vote, consistent):
    r = vote_round(Scripted(answers), OBS, CUP, VoteSettings())
    assert (r.vote, r.consistent) == (vote, consistent)
    assert len(r.questions) == 5 and r.questions[0] == "Is the cup on the table?"


def test_early_stop_asks_fewer_questions_with_the_same_outcome():
    full = vote_round(Scripted([True] * 5), OBS, CUP, VoteSettings())
    early = vote_round(Scripted([True] * 5), OBS, CUP, VoteSettings(early_stop=True))
    assert (early.vote, early.consistent) == (full.vote, full.consistent)
    assert len(early.answers) == 4  # after four agreeing answers nothing can change


def test_symbolic_vlm_error_rate_matches_its_parameter():
    truth = {CUP: True}
    vlm = SymbolicVLM(lambda a: truth[a], error_rate=0.2, seed=7)
    n, wrong = 4000, 0
    for _ in range(n):
        a = vlm.ask(Query("q", about=(CUP,), objects=("cup", "table")),
                    Observation(0, (), {"cup": 1.0, "table": 1.0}))
        wrong += a.value is not True
    assert abs(wrong / n - 0.2) < 0.025  # ~4 standard errors


def test_symbolic_vlm_guesses_about_what_it_cannot_see_and_knows_it():
    vlm = SymbolicVLM(lambda a: True, error_rate=0.0, seed=1)
    hidden = Observation(0, (), {"cup": 0.0, "table": 1.0})
    answers = [vlm.ask(Query("q", about=(CUP,), objects=("cup", "table")), hidden).value for _ in range(400)]
    assert 0.35 < sum(answers) / len(answers) < 0.65
    suff = [vlm.ask(Query("q", purpose="sufficiency", about=(CUP,), objects=("cup", "table")), hidden).value
            for _ in range(50)]
    assert not any(suff), "with no noise it must say the view is insufficient every time"
