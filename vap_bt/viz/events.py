"""The episode told as text: one line per event, and a page per verification round.

Everything the executive records on its :class:`~vap_bt.bt.context.ExecutionContext` — plans,
actions started and finished, each round of looking (the N paraphrased questions and their
answers, the vote, the view-sufficiency answer, the next viewpoint), each settled verification,
each situation, each change of belief — becomes a line for rerun's text log, with a level that
lets the viewer filter: situations are warnings, failed skills errors. A round also gets a
markdown page with its question/answer table, which the viewer shows next to the image.

Pure formatting: no rerun here, so the wording can be tested and reused (e.g. in reports).
"""

from __future__ import annotations

from vap_bt.bt.context import Situation, Verification
from vap_bt.domain.atoms import Atom
from vap_bt.perception.verification import Round
from vap_bt.scene.graph import Change

INFO, WARN, ERROR = "INFO", "WARN", "ERROR"


def yes_no(value: bool | None) -> str:
    """An answer or vote as a word: yes, no, or ? for none (an abstention)."""
    return "?" if value is None else ("yes" if value else "no")


def plan_text(actions: list[str], replan: int) -> str:
    """A plan as the log shows it: a header (``plan``, or ``replan #n``) and one numbered action a line."""
    head = "plan" if replan == 0 else f"replan #{replan}"
    return f"{head}: {len(actions)} actions" + ("".join(f"\n  {i}: {a}" for i, a in enumerate(actions)))


def action_start_text(step: int, action: str) -> str:
    """The line of action ``a<step>`` starting."""
    return f"a{step}: start {action}"


def action_result_text(entry: dict) -> tuple[str, str]:
    """(text, level) for one entry of the board's ``actions``."""
    ms = (entry.get("done_s", 0.0) - entry.get("sent_s", 0.0)) * 1000
    ok = entry.get("state") == "succeeded"
    msg = f" ({entry['message']})" if entry.get("message") and not ok else ""
    return f"a{entry['step']}: {entry['state']} {entry['action']} in {ms:.0f} ms{msg}", (INFO if ok else ERROR)


def round_text(phase: str, action: str, atom: Atom, expected: bool, r: Round, view_no: int | None = None) -> str:
    """One line for the round, then one indented line per question with its answer."""
    head = f"{phase} {action}: {'' if expected else 'not '}{atom} — view {r.view}"
    if view_no is not None:
        head += f" (image #{view_no})"
    facts = [f"answers [{' '.join(yes_no(a) for a in r.answers)}] → vote {yes_no(r.vote)}"
             f" ({'consistent' if r.consistent else 'inconsistent'})"]
    if r.sufficient is not None:
        facts.append(f"view sufficient: {yes_no(r.sufficient)}")
    if r.direction is not None:
        facts.append(f"next view: {r.direction}" + ("" if r.moved else " (could not move)") + _refused(r))
    qa = [f"  Q: {q} → {yes_no(a)}" for q, a in zip(r.questions, r.answers)]
    return "\n".join([f"{head}: " + "; ".join(facts), *qa])


def _page_head(phase: str, action: str, atom: Atom, expected: bool, where: str) -> list[str]:
    return [f"# {'' if expected else 'not '}{atom}", "", f"*{phase}* check of **{action}**, {where}", ""]


def _qa_table(questions, answers: dict[int, bool | None], pending: str) -> list[str]:
    """The questions with the answers in so far; ``pending`` stands where none is (yet)."""
    return ["| # | question | answer |", "|---|---|---|",
            *(f"| {i + 1} | {q} | {yes_no(answers[i]) if i in answers else pending} |" for i, q in enumerate(questions))]


def round_markdown(phase: str, action: str, atom: Atom, expected: bool, r: Round) -> str:
    """The page of one round of looking at ``atom`` (``phase`` of ``action``): its questions and answers,
    the vote, the view's sufficiency and the next viewpoint chosen."""
    lines = _page_head(phase, action, atom, expected, f"view {r.view}")
    lines += _qa_table(r.questions, dict(enumerate(r.answers)), "not asked")
    lines += ["", f"- vote: **{yes_no(r.vote)}** ({'consistent' if r.consistent else 'inconsistent'})",
              f"- view sufficient: {yes_no(r.sufficient)}"]
    if r.direction is not None:
        lines.append(f"- next viewpoint: {r.direction}" + ("" if r.moved else " (could not move there)") + _refused(r))
    return "\n".join(lines)


#: what a check in progress is doing, by its stage (ActivePerception) or its round's (VerifyPredicate)
DOING = {"capturing": "capturing a frame …", "asking": "asking the model …", "judging the view":
         "asking whether the view is sufficient …", "choose": "asking the model where to look from …",
         "move": "moving to the next viewpoint …", "feel": "asking the gripper …",
         "done": "weighing the views so far …", "idle": "about to look …"}


def check_markdown(phase: str, action: str, atom: Atom, expected: bool, views: int, budget: int, stage: str,
                   questions=(), answers: dict[int, bool | None] | None = None, last: Round | None = None) -> str:
    """The page of a check while it runs: which view of how many, what it is doing now, and the
    questions of the round in flight with the answers as they arrive (else the last round's)."""
    lines = _page_head(phase, action, atom, expected, f"view {views + (stage in ('capturing', 'asking', 'judging the view'))}"
                                                     f" (budget K={budget} moves)")
    answers = answers or {}
    doing = DOING.get(stage, stage)
    if stage == "asking":
        doing = f"asking the model: {len(answers)} of {len(questions)} answered"
    lines += [f"**now:** {doing}", ""]
    if questions:
        lines += _qa_table(questions, answers, "…")
    elif last is not None:
        lines += _last_view(last)
    return "\n".join(lines)


def _last_view(r: Round) -> list[str]:
    return [f"last view ({r.view}):", "", *_qa_table(r.questions, dict(enumerate(r.answers)), "not asked"), "",
            f"- vote: **{yes_no(r.vote)}**, view sufficient: {yes_no(r.sufficient)}"]


def verdict_markdown(v: Verification, situation: Situation | None = None) -> str:
    """The page of a check once it is decided: its verdict, then its last round."""
    want = "" if v.expected else "not "
    lines = [f"# {want}{v.atom}", "", f"*{v.phase}* check of **{v.action}**: {_settled(v, f'**{v.outcome}**')}", ""]
    if situation is not None:
        lines += [f"⚠ {situation_text(situation)}", ""]
    if v.rounds:
        lines += _last_view(v.rounds[-1])
    return "\n".join(lines)


def _refused(r: Round) -> str:
    """The directions tried first that the robot could not move to, if any."""
    return f" after {', '.join(r.refused)} could not be reached" if r.refused else ""


def _settled(v: Verification, outcome: str) -> str:
    """``confirmed (observed true) after 2 views, 12 queries``, the outcome as given."""
    views = len(v.rounds)
    return f"{outcome} (observed {str(v.value).lower()}) after {views} view{'s' * (views != 1)}, {v.queries} queries"


def verification_text(v: Verification) -> tuple[str, str]:
    """The line of a settled verification and its level: a contradicted expectation is a warning."""
    want = "" if v.expected else "not "
    text = f"{v.phase} {v.action}: {want}{v.atom} {_settled(v, v.outcome)}"
    return text, (WARN if v.outcome == "contradicted" else INFO)


def situation_text(s: Situation, truth: str | None = None) -> str:
    """The line of a situation: its kind, step and action, the observation that raised it, and
    what the executive diagnosed it as (and why); after the episode, ``truth``: what the world's
    record says it was."""
    what = f" {'' if s.expected else 'not '}{s.atom} observed {str(s.observed).lower()}" if s.atom else ""
    detail = f" ({s.detail})" if s.detail else ""
    diagnosis = f" — diagnosed {s.diagnosis}: {s.diagnosis_basis}" if s.diagnosis else ""
    scored = f" — truth {truth} ({'right' if truth == s.diagnosis else 'wrong'})" if truth else ""
    return f"situation: {s.kind} at step {s.step}" + (f" {s.action}" if s.action else "") + what + detail \
        + diagnosis + scored


def change_text(c: Change) -> str:
    """The line of a change of belief: its cause, then the atoms added (+) and removed (-)."""
    added = ", ".join(f"+{a}" for a in sorted(map(str, c.added)))
    removed = ", ".join(f"-{a}" for a in sorted(map(str, c.removed)))
    return f"belief ({c.cause}): " + "; ".join(x for x in (added, removed) if x)
