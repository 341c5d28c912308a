"""The H2 measure: how many viewpoints a strategy spends on what its first view could not decide.

Paper H2 compares VLM-guided viewpoint selection with greedy perception by the viewpoints each
needs to resolve an uncertainty (its Fig. "Viewpoint efficiency"). Read off one episode's
report (:mod:`vap_bt.report`), whatever ran it:

* an *uncertain* check is one whose first view did not decide it (its verification's
  ``first_settled`` is False: the paraphrases split, the view was judged insufficient, or a
  surprise wanted a second picture). Checks the first view decided, reused values and the hand's
  checks (no move of the base shows the hand better) are not counted;
* its *viewpoints* are the moves it made to new views (``viewpoints``: a direction the robot
  could not reach is none). A check left *unresolved* is charged the strategy's whole budget: K
  (the report's ``config.budget``) for ``vlm`` and ``greedy``; ``greedy-all`` visits every
  viewpoint of its round whatever each shows, so what it visited is what it spent, resolved or not;
* it is *resolved* when its views decided a value (outcome confirmed or contradicted, on the
  VLM's basis); the gripper's word, or belief standing, is no resolution by looking;
* *settled accuracy*: of the resolved checks, those whose value matches the world's at the time
  (the runner's ``truth`` on each verification; a check without one is not scored).

:func:`viewpoint_measure` gives these for one report, with the per-check list (for a
histogram); :func:`pooled` combines several reports' (the checks pooled, not the means averaged).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

#: the strategy whose unresolved checks are charged what they visited, not K
EXHAUSTIVE = "greedy-all"


@dataclass(frozen=True)
class UncertainCheck:
    """One check whose first view did not decide it: what it was about, what it visited, what it
    is charged, and how it ended."""

    phase: str
    action: str
    predicate: str
    viewpoints: int  # moves made to new views
    charged: int  # viewpoints counted for the measure (K for an unresolved check, but greedy-all's)
    resolved: bool  # its views decided a value
    correct: bool | None  # the value against the world's (None: unresolved, or no truth attached)


def uncertain_checks(report: dict) -> list[UncertainCheck]:
    """The report's uncertain checks (see the module docstring), in the order they were made."""
    strategy, budget = report["config"]["viewpoints"], int(report["config"]["budget"])
    out = []
    for v in report["verifications"]:
        if v.get("first_settled") is not False:
            continue
        resolved = v["outcome"] in ("confirmed", "contradicted") and v["basis"] == "vlm"
        moved = int(v["viewpoints"])
        charged = moved if resolved or strategy == EXHAUSTIVE else budget
        correct = (v["value"] == v["truth"]) if resolved and v.get("truth") is not None else None
        out.append(UncertainCheck(v["phase"], v["action"], v["predicate"], moved, charged, resolved, correct))
    return out


def summary(checks: list[UncertainCheck]) -> dict:
    """The measure over ``checks``: how many, viewpoints per check (charged), the resolution rate,
    the settled accuracy (None where nothing to divide by), and the checks themselves."""
    n = len(checks)
    resolved = [c for c in checks if c.resolved]
    scored = [c for c in resolved if c.correct is not None]
    correct = sum(bool(c.correct) for c in scored)
    return {"uncertain": n, "resolved": len(resolved), "scored": len(scored), "correct": correct,
            "viewpoints_per_check": sum(c.charged for c in checks) / n if n else None,
            "resolution_rate": len(resolved) / n if n else None,
            "settled_accuracy": correct / len(scored) if scored else None,
            "checks": [asdict(c) for c in checks]}


def viewpoint_measure(report: dict) -> dict:
    """The H2 measure of one episode's report (see the module docstring), with the strategy and
    the budget K it ran with."""
    return {"strategy": report["config"]["viewpoints"], "budget": int(report["config"]["budget"]),
            **summary(uncertain_checks(report))}


def pooled(measures: list[dict]) -> dict:
    """Several measures (of one strategy's episodes) as one: their checks pooled."""
    checks = [UncertainCheck(**c) for m in measures for c in m["checks"]]
    return {"strategy": ",".join(sorted({m["strategy"] for m in measures})), "episodes": len(measures),
            **summary(checks)}
