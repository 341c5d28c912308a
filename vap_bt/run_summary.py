"""What ``vap-bt run`` prints when a run ends: a short table for a person, JSON for a script.

The full report (``--report FILE``, :mod:`vap_bt.report`) holds everything about an episode. At
the end of a run a person wants a few lines — did it work *as the world confirms it*, in which
world and with which seed, what it took (actions, situations, replans, VLM queries, time) and
where the report and the recording went — and a script wants the same facts as JSON on stdout
with nothing else there (``--json``). Both are read off the report, so neither can say more than
it does: a success the executive claims and the world denies is printed as a failure.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass


@dataclass(frozen=True)
class Outputs:
    """Where a run wrote what a person may want to open afterwards (None: not written)."""

    report: str | None = None
    recording: str | None = None  # the recorder's own hint: where the live view went, how to see it


def verdict(rep: dict) -> str:
    """Success in words, as the world confirms it (the executive's claim alone is not enough)."""
    claimed, holds = rep["success"], rep["goal_satisfied"]
    if claimed and holds:
        return "yes (the world confirms the goal)"
    if claimed:
        return "NO: the executive claimed success but the world denies the goal"
    stopped = f" (phase: {rep['phase']})" if rep.get("interrupted") else ""  # Ctrl-C: in which phase
    return f"no: {rep['reason']}{stopped}" + (" (yet the goal holds in the world)" if holds else "")


def summary(rep: dict, outputs: Outputs = Outputs()) -> dict:
    """The JSON summary ``vap-bt run --json`` prints: the report's headline facts."""
    out = {k: rep[k] for k in ("success", "goal_satisfied", "reason", "interrupted", "phase", "seed", "replans",
                               "vlm_queries", "wall_s")}
    out["task"] = rep["task"]["name"]
    out["world"] = rep["world"]["name"]
    out["actions_executed"] = len(rep["actions_executed"])
    out["situations"] = rep["situations"]
    out["injected"] = rep["injected"]
    out["plans"] = [p["actions"] for p in rep["plans"]]
    out["plan_costs"] = [p["cost"] for p in rep["plans"]]
    # which predicates the trees did not look at, and why (the full report lists every atom)
    out["unchecked"] = {u["name"]: u["reason"] for u in rep.get("unchecked", [])}
    out["report"] = outputs.report
    out["recording"] = outputs.recording
    return out


def _counted(items, what: str) -> str:
    """``3 detected (precondition x2, effect)``: how many, and of which kinds."""
    kinds = Counter(i["kind"] for i in items).most_common()
    named = ", ".join(k if n == 1 else f"{k} x{n}" for k, n in kinds)
    return f"{len(items)} {what}" + (f" ({named})" if named else "")


def rows(rep: dict, outputs: Outputs = Outputs()) -> list[tuple[str, str]]:
    """The summary table's rows, (label, text), in the order a person reads them."""
    cfg, task = rep["config"], rep["task"]
    actions = rep["actions_executed"]
    failed = sum(a.get("state") != "succeeded" for a in actions)
    plans = f"{len(rep['plans'])} plan{'s' if len(rep['plans']) != 1 else ''}"
    if rep.get("vlm_planner"):  # the VLM-planner baseline has no plan: the model named each action
        plans = f"named one at a time by the VLM ({len(rep['vlm_planner']['steps'])} steps)"
    replans = f"{rep['replans']}"
    if rep["replan_ms"]:
        replans += f" (slowest {max(rep['replan_ms']):.0f} ms)"
    return [
        ("task", task["name"] + (f" ({task['file']})" if task.get("file") else "")),
        ("world", f"{rep['world']['name']}, seed {rep['seed']}, verify {cfg['verify']}, "
                  f"injection {'on' if cfg['injection'] else 'off'}"),
        ("success", verdict(rep)),
        ("actions", f"{len(actions)} executed" + (f", {failed} failed" if failed else "") + f"; {plans}"),
        ("situations", f"{_counted(rep['situations'], 'detected')}; "
                       + _counted(rep["injected"], "in the world's record")),
        ("replans", replans),
        ("VLM queries", f"{rep['vlm_queries']} ({rep['vlm'].get('backend', cfg['vlm'])})"),
        ("wall time", f"{rep['wall_s']:.1f} s"),
        ("report", outputs.report or "not written (--report FILE writes it)"),
        ("recording", outputs.recording or "none (--rerun save FILE.rrd records the live view)"),
    ]


def table(rep: dict, outputs: Outputs = Outputs()) -> str:
    """The rows as aligned text, one per line."""
    lines = rows(rep, outputs)
    width = max(len(label) for label, _ in lines)
    return "\n".join(f"{label:<{width}}  {text}" for label, text in lines)
