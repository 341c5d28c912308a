"""Per-episode measures read off a report: viewpoints per uncertain check, failure mode, diagnoses.

**Uncertain checks** (H2) are :mod:`vap_bt.viewpoint_measure`'s: a looked-at check whose first
view did not decide it, charged the viewpoints it moved to (an unresolved one the budget K, but
``greedy-all``'s what it visited); ``resolved`` when its views decided a value, ``correct`` when
that value is the world's (the ``truth`` the runner attaches).

**Failure mode** of an episode that did not succeed, first rule that applies:

1. ``visual ambiguity`` — it claimed the goal and the world denies it; or it stopped because it
   could not see an atom (``stuck: could not see ...``); or a wrong belief was never corrected:
   the last looked-at check of some atom settled a value the world denies;
2. ``state/access`` — no plan (``no initial plan``, ``no plan after ...``): the state as believed
   leaves no way to the goal, or a place or thing cannot be reached;
3. ``manipulation`` — skill failures used up the replans: it ended ``stuck: execution of ...``
   or with the replanning budget exhausted while most of its situations were execution failures;
4. ``other`` — the rest (the time budget, a stuck check loop of another kind, a transport down);
   an episode that raised is ``crash``.

**Diagnoses.** Where a report's situations carry ``diagnosis`` and ``diagnosis_truth`` (what
the executive concluded went wrong, and what the world says did), each pair; None when the report
has no such keys (the table then says so).

**Situation trail** (``situation_trail``, in ``episodes.jsonl`` only, not the CSV): each situation
as the report has it, cut short — kind, action, atom, the skill's words, diagnosis and its basis,
the truth and the kinds of the world's events the truth rests on. A confusion in the table is a
count; the trail says which situations make it, so a change to the diagnosis rule can be sized on
a campaign's rows instead of on episodes run again by hand.
"""

from __future__ import annotations

import re

from vap_bt.viewpoint_measure import uncertain_checks

VISUAL, ACCESS, MANIPULATION, OTHER, CRASH = "visual ambiguity", "state/access", "manipulation", "other", "crash"
#: failure modes, in the order tables and plots list them
FAILURE_MODES = (VISUAL, ACCESS, MANIPULATION, OTHER, CRASH)
#: the row columns this module adds
COLUMNS = ("uncertain_viewpoints", "uncertain_resolved", "uncertain_correct", "failure_mode", "diagnoses")
#: the row key of the situation trail (the log's rows only: a list of records is no CSV cell)
TRAIL = "situation_trail"
#: how much of a situation's free text (the skill's words, the diagnosis' basis) the trail keeps
TRAIL_TEXT = 120


def of(report: dict) -> dict:
    """Every measure of one episode's report, as row columns."""
    checks = uncertain_checks(report)
    return {"uncertain_viewpoints": [c.charged for c in checks], "uncertain_resolved": sum(c.resolved for c in checks),
            "uncertain_correct": sum(bool(c.correct) for c in checks), "failure_mode": failure_mode(report),
            "diagnoses": diagnoses(report), TRAIL: situation_trail(report)}


def failure_mode(report: dict) -> str | None:
    """Why an episode failed, by the rules of the module docstring (None: it succeeded)."""
    claimed, holds = report["success"], report["goal_satisfied"]
    if claimed and holds:
        return None
    reason = report["reason"] or ""
    if claimed or reason.startswith("stuck: could not see") or wrong_belief_kept(report):
        return VISUAL
    if reason.startswith(("no initial plan", "no plan after")):
        return ACCESS
    kinds = [s["kind"] for s in report["situations"]]
    if reason.startswith("stuck: execution") or (
            reason.startswith("replanning budget") and 2 * kinds.count("execution") >= len(kinds)):
        return MANIPULATION
    return OTHER


def wrong_belief_kept(report: dict) -> bool:
    """Whether the last looked-at check of some atom settled a value the world denies."""
    last = {c["predicate"]: c for c in report["verifications"] if c["basis"] == "vlm" and "truth" in c}
    return any(c["value"] != c["truth"] for c in last.values())


def diagnoses(report: dict) -> list[list[str]] | None:
    """``[diagnosis, diagnosis_truth]`` of each situation that has them; None when none has the keys."""
    pairs = [[str(s["diagnosis"]), str(s["diagnosis_truth"])] for s in report["situations"]
             if "diagnosis" in s and "diagnosis_truth" in s]
    return pairs if pairs or not report["situations"] else None


def situation_trail(report: dict) -> list[dict]:
    """Each situation of ``report``, cut short (the module docstring's trail)."""
    events = report.get("injected") or []
    return [{"kind": s["kind"], "action": s.get("action"), "predicate": s.get("predicate"),
             "detail": (s.get("detail") or "")[:TRAIL_TEXT], "diagnosis": s.get("diagnosis"),
             "basis": (s.get("diagnosis_basis") or "")[:TRAIL_TEXT], "truth": s.get("diagnosis_truth"),
             "events": [events[i]["kind"] for i in s.get("truth_events") or () if i < len(events)]}
            for s in report["situations"]]


def situation_class(t: dict) -> str:
    """What raised a trail's situation, in words shared by its kind: a failed skill by what it
    said, names and numbers taken out ("blocked", "tap out of reach", "no clear way to"), a check
    by its kind and predicate ("effect holding", "unseen filled at the goal")."""
    if t["kind"] == "execution":
        detail = t.get("detail") or ""
        words = re.sub(r"^\w+\([^)]*\) stopped: ", "", detail)  # "open(oven) stopped: blocked: ..."
        if words == detail:
            words = re.sub(r"^\w+: ", "", words)  # the thing the skill names first: "oven: the hand is full"
            words = re.sub(r"^\w+ (is|was) ", "", words)  # "cup is not where ..." as "not where ..."
        return "skill: " + re.sub(r"\s*\(.*", "", words.split(":")[0]).strip()
    predicate = (t.get("predicate") or "").split("(")[0]
    goal = t.get("action") is None and (t.get("detail") or "").startswith("goal")
    return f"{t['kind']} {predicate}".strip() + (" at the goal" if goal else "")
