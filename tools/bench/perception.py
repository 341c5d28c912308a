"""Verification protocols and viewpoint strategies side by side, over the same seeded episodes of every task.

Every episode runs with the simulated VLM behind its local OpenAI-compatible endpoint
(``--vlm sim-http``: the openai client end to end, the same answers as in-process), Table II
injection on, the simulated model vlm-2 (docs/perception.md), in-process skills. Per task and seed, one run each of

* ``paper`` — the paper's Alg. 2 (every paraphrase, one after the other, then sufficiency);
* ``lean-nolp`` — the lean protocol against a backend that returns no logprobs (the client does
  not ask for them): early stop, questions in flight at once, reuse of unchanged atoms;
* ``lean`` — the lean protocol with logprobs (one confident answer stands for the vote);
* ``greedy`` — the paper's protocol with greedy viewpoints (predefined ones around the target),
  against ``paper``'s VLM-suggested ones (the paper's H2);
* ``one-look`` — the paper's protocol believing the first settled view of a surprise or a goal,
  as Alg. 2 does (the executive's default looks a second time from a new picture);

and, for the first ``--wall-seeds`` seeds, ``paper`` and ``lean`` again with ``--latency`` seconds
(0.3) added by the endpoint to every request: the VLM wall time per action (time with a query in
flight, ``vlm.wall_s`` of the report). Those reruns must be the same episodes as without the
latency (the answers are seeded per query, not per order): the bench checks it.

Figures: VLM round trips (queries) per executed action; verification accuracy against the oracle
(the report's ``perception.verifications``: values a sense settled — looked at or felt — that
matched the world at that moment; values the lean protocol reused are counted apart, outside the
denominator), pooled, with a Wilson 95 % interval; viewpoints per uncertainty resolution: over
the checks whose first view did not decide (more than one view), the moves made in those that a
later view settled (consistent answers, judged sufficient); checks that ended on the verdict's
fallback — the budget spent, insufficient views agreeing — are counted apart: no viewpoint
resolved them.
Targets are the issue's (lean without logprobs <= 1/2 and with logprobs <= 1/4 of
the paper's round trips at equal or better accuracy; lean's VLM wall time <= 1/5 of the paper's;
VLM-guided viewpoints <= 1.5 per resolution and below greedy).

    python tools/bench/perception.py [--seeds 2] [--wall-seeds 1] [--jobs 2] [--world pybullet]
                                     [--latency 0.3] [--tasks collect_cup,cut_lemon] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import math
import multiprocessing
import os
import random
import sys
import tempfile
import time
import traceback
from collections import defaultdict
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tools.bench.intervals import wilson  # noqa: E402
from vap_bt.report import verification_counts, versions  # noqa: E402
from vap_bt.sim.observability import RELATION_CLASS  # noqa: E402

#: name -> RunConfig overrides (besides world, seed, vlm="sim-http", transport="inproc")
CONFIGS = {
    "paper": {"protocol": "paper"},
    "lean-nolp": {"protocol": "lean", "vlm_logprobs": False},
    "lean": {"protocol": "lean"},
    "greedy": {"protocol": "paper", "viewpoints": "greedy"},
    "one-look": {"protocol": "paper", "second_look": False},
}
TIMED = ("paper", "lean")  # rerun with the endpoint's latency
LABELS = {"paper": "paper", "lean-nolp": "lean without logprobs", "lean": "lean with logprobs",
          "greedy": "paper, greedy viewpoints", "one-look": "paper, one look (Alg. 2)"}


@dataclass(frozen=True)
class Unit:
    """One episode to run: a task file, a seed, a configuration, the endpoint's added latency."""

    task: str
    seed: int
    config: str
    world: str
    latency: float = 0.0
    vlm: str = "sim-http"  # "sim": the in-process model, to check that the endpoint gives the same episodes

    @property
    def name(self) -> str:
        return self.config + (f"@{self.latency:g}s" if self.latency else "") + (" in-process" if self.vlm == "sim" else "")


def _own_directory() -> None:
    """Each worker in a directory of its own: Fast Downward's translator writes ``output.sas`` into
    the working directory, and two planners sharing one read each other's tasks."""
    os.chdir(tempfile.mkdtemp(prefix="vap-bench-"))


def run(unit: Unit) -> dict:
    """Run one episode in this (worker) process; a crash is a row saying so, not the end of the bench."""
    try:
        return _run(unit)
    except Exception:  # noqa: BLE001 - reported in the table, with its traceback in the JSON
        return {"task": unit.task, "seed": unit.seed, "config": unit.config, "latency": unit.latency,
                "vlm": unit.vlm, "run_s": 0.0, "error": traceback.format_exc()}


def _run(unit: Unit) -> dict:
    from vap_bt import taskfile
    from vap_bt.app.runner import RunConfig, Session

    task = taskfile.load(ROOT / "trees" / f"{unit.task}.yaml")
    cfg = RunConfig.from_task(task, world=unit.world, vlm=unit.vlm, transport="inproc", vlm_noise=1.0,
                              vlm_latency=unit.latency, **CONFIGS[unit.config])
    t0 = time.perf_counter()
    session = Session(task, cfg)
    try:
        rep = session.episode(unit.seed)
        model = session.endpoint.vlm if session.endpoint is not None else session.vlm
        judged = judgements(model.ledger)
    finally:
        session.close()
    return {"task": unit.task, "seed": unit.seed, "config": unit.config, "latency": unit.latency, "vlm": unit.vlm,
            "run_s": round(time.perf_counter() - t0, 2), **figures(rep), "judged": judged}


#: observability bands of the single-view accuracy table (docs/perception.md)
BANDS = (0.0, 0.25, 0.5, 0.75, 1.01)
#: stated-probability bins of the calibration curve
BINS = tuple(0.5 + 0.05 * k for k in range(11))


def band(o: float) -> str:
    k = next(i for i in range(len(BANDS) - 1) if o < BANDS[i + 1])
    return f"{BANDS[k]:.2f}-{min(BANDS[k + 1], 1.0):.2f}"


def judgements(ledger) -> dict:
    """The simulated model's yes/no answers of one episode against the truth at capture (world
    side: every answer the model gave, measured, not assumed): per relation class and
    observability band [right, answered, abstained]; the calibration bins [answers, stated sum,
    right]; the sufficiency answers by [said yes when sufficient, sufficient, said yes when not, not]."""
    table, calib, suff = defaultdict(lambda: [0, 0, 0]), defaultdict(lambda: [0, 0.0, 0]), [0, 0, 0, 0]
    for j in ledger:
        if j.purpose == "sufficiency":
            i = 0 if j.truth else 2
            suff[i] += bool(j.answer)
            suff[i + 1] += 1
            continue
        cell = table[f"{j.relation}|{band(j.observability)}"]
        if j.answer is None:
            cell[2] += 1
            continue
        right = j.answer == j.truth
        cell[0] += right
        cell[1] += 1
        if j.confidence is not None:
            b = calib[min(int((j.confidence - 0.5) / 0.05), 9)]
            b[0] += 1
            b[1] += j.confidence
            b[2] += right
    return {"table": dict(table), "calibration": {str(k): v for k, v in calib.items()}, "sufficiency": suff}


def figures(rep: dict) -> dict:
    """What the bench reads off one report."""
    survey_frames = {r["view"] for s in rep["perception"]["surveys"] for st in s["states"] for r in st["rounds"]}
    requests = rep["vlm"].get("requests", [])  # the in-process model keeps no request records
    survey = [r for r in requests if r["frame_id"] in survey_frames]
    uncertain = [v for v in rep["verifications"] if v["views"] > 1]
    # resolved by a viewpoint: a later view settled it (consistent answers, judged sufficient);
    # a check whose budget ran out and whose insufficient views merely agreed (the verdict's
    # fallback) found no view that resolved it, and is counted apart
    decided = [v for v in uncertain if v["outcome"] in ("confirmed", "contradicted")]
    resolved = [v for v in decided if v["rounds"][-1]["consistent"] and v["rounds"][-1]["sufficient"]]
    pv = rep["perception"]["verifications"]
    first, by_relation = defaultdict(lambda: [0, 0]), defaultdict(list)
    for v in rep["verifications"]:
        relation = RELATION_CLASS.get(v["predicate"].split("(")[0], "other")
        by_relation[relation].append(v)
        vote = v["rounds"][0]["vote"] if v["rounds"] else None
        if vote is not None and "first_truth" in v:  # the first view's majority vote, against its capture
            first[relation][0] += vote == v["first_truth"]
            first[relation][1] += 1
    # the value a check settled on by looking (not felt, not reused), against the world when it settled
    counts = {rel: verification_counts(vs) for rel, vs in by_relation.items()}
    settled = {rel: [c["looked_correct"], c["looked"]] for rel, c in counts.items() if c["looked"]}
    return {
        "first_view": dict(first), "settled": dict(settled),
        "success": bool(rep["success"] and rep["goal_satisfied"]), "claimed": bool(rep["success"]),
        "goal_satisfied": bool(rep["goal_satisfied"]), "reason": rep["reason"],
        "actions": len(rep["actions_executed"]), "queries": rep["vlm_queries"],
        "survey_queries": len(survey), "by_purpose": rep["vlm"]["by_purpose"],
        "unanswered": sum(r["outcome"] != "answer" for r in requests),
        "served": rep["vlm"].get("served", {}).get("counts"),
        "verified": pv["n"], "correct": pv["correct"], "unsettled": pv["unsettled"], "reused": pv["reused"],
        "vlm_wall_s": rep["vlm"]["wall_s"], "survey_wall_s": round(sum(r["latency_s"] for r in survey), 4),
        "uncertain": len(uncertain), "resolved": len(resolved), "agreed": len(decided) - len(resolved),
        "moves_resolved": sum(v["views"] - 1 for v in resolved), "moves_uncertain": sum(v["views"] - 1 for v in uncertain),
        "fingerprint": json.dumps([rep["verifications"], [p["actions"] for p in rep["plans"]]], sort_keys=True),
        "wall_s": rep["wall_s"],
    }


#: resamples for the bootstrap intervals of the viewpoint figures (seeded: the bench is reproducible)
BOOTSTRAP = 2000


def _per_resolution(rows: list[dict]) -> float:
    resolved = sum(r["resolved"] for r in rows)
    return sum(r["moves_resolved"] for r in rows) / resolved if resolved else math.nan


def bootstrap(pairs: list[tuple[dict, dict]], seed: int = 0) -> tuple[float, float]:
    """95 % percentile interval of (viewpoints per resolution of the first) minus (of the second),
    resampling whole episodes — a (task, seed) with its row under each configuration — since the
    checks of one episode are not independent of each other."""
    rng = random.Random(seed)
    diffs = []
    for _ in range(BOOTSTRAP):
        pick = [pairs[rng.randrange(len(pairs))] for _ in pairs]
        d = _per_resolution([a for a, _ in pick]) - _per_resolution([b for _, b in pick])
        if not math.isnan(d):
            diffs.append(d)
    diffs.sort()
    if not diffs:
        return math.nan, math.nan
    return diffs[int(0.025 * len(diffs))], diffs[min(len(diffs) - 1, int(0.975 * len(diffs)))]


def _merged(rows: list[dict], key: str) -> dict[str, list]:
    """Per-relation counts of ``key`` summed over rows."""
    out: dict[str, list] = defaultdict(lambda: [0, 0])
    for r in rows:
        for rel, (k, n) in r[key].items():
            out[rel][0] += k
            out[rel][1] += n
    return out


def _accuracy(counts: dict[str, list]) -> dict:
    """Per relation and over all: [right, n, accuracy, Wilson 95 % interval]."""
    total = [sum(c[0] for c in counts.values()), sum(c[1] for c in counts.values())]
    return {rel: [k, n, round(k / n, 4) if n else None, [round(x, 4) for x in wilson(k, n)]]
            for rel, (k, n) in sorted({**counts, "all": total}.items())}


def model_figures(rows: list[dict]) -> dict:
    """The simulated model measured over every answer of ``rows``' episodes: single-view accuracy
    per relation and observability band, the calibration curve and its expected calibration
    error, and how its sufficiency answers split."""
    table, calib, suff = defaultdict(lambda: [0, 0, 0]), defaultdict(lambda: [0, 0.0, 0]), [0, 0, 0, 0]
    for r in rows:
        for cell, counts in r["judged"]["table"].items():
            table[cell] = [a + b for a, b in zip(table[cell], counts)]
        for b, counts in r["judged"]["calibration"].items():
            calib[b] = [a + x for a, x in zip(calib[b], counts)]
        suff = [a + b for a, b in zip(suff, r["judged"]["sufficiency"])]
    answered = sum(c[0] for c in calib.values())
    ece = sum(abs(c[1] / c[0] - c[2] / c[0]) * c[0] / answered for c in calib.values() if c[0]) if answered else math.nan
    return {"single_view": {cell: [k, n, a, round(k / n, 4) if n else None, [round(x, 4) for x in wilson(k, n)]]
                            for cell, (k, n, a) in sorted(table.items())},
            "calibration": {f"{0.5 + 0.05 * int(b):.2f}": {"answers": c[0], "stated": round(c[1] / c[0], 4),
                                                           "accuracy": round(c[2] / c[0], 4)}
                            for b, c in sorted(calib.items(), key=lambda x: int(x[0])) if c[0]},
            "ece": round(ece, 4),
            "sufficiency": {"said_sufficient_when_sufficient": round(suff[0] / suff[1], 4) if suff[1] else None,
                            "sufficient": suff[1],
                            "said_sufficient_when_not": round(suff[2] / suff[3], 4) if suff[3] else None,
                            "insufficient": suff[3]}}


def pooled(rows: list[dict]) -> dict:
    s = lambda key: sum(r[key] for r in rows)  # noqa: E731
    actions = s("actions")
    lo, hi = wilson(s("correct"), s("verified"))
    return {"episodes": len(rows), "success": s("success"), "claimed_but_denied": sum(r["claimed"] and not r["goal_satisfied"] for r in rows),
            "actions": actions, "queries": s("queries"), "survey_queries": s("survey_queries"),
            "per_action": s("queries") / actions if actions else math.nan,
            "checks_per_action": (s("queries") - s("survey_queries")) / actions if actions else math.nan,
            "verified": s("verified"), "correct": s("correct"), "accuracy": s("correct") / s("verified") if s("verified") else math.nan,
            "accuracy_95": [round(lo, 4), round(hi, 4)], "unsettled": s("unsettled"), "reused": s("reused"),
            "unanswered": s("unanswered"),
            "vlm_wall_s": s("vlm_wall_s"), "wall_per_action": s("vlm_wall_s") / actions if actions else math.nan,
            "checks_wall_per_action": (s("vlm_wall_s") - s("survey_wall_s")) / actions if actions else math.nan,
            "first_view": _accuracy(_merged(rows, "first_view")), "settled": _accuracy(_merged(rows, "settled")),
            "uncertain": s("uncertain"), "resolved": s("resolved"), "agreed": s("agreed"),
            "viewpoints_per_resolution": _per_resolution(rows),
            "moves_per_resolution_all": s("moves_uncertain") / s("resolved") if s("resolved") else math.nan}


def units(tasks: list[str], args) -> list[Unit]:
    timed = [Unit(t, seed, c, args.world, args.latency) for seed in range(args.wall_seeds) for c in TIMED for t in tasks]
    plain = [Unit(t, seed, c, args.world) for seed in range(args.seeds) for c in CONFIGS for t in tasks]
    checks = [Unit(t, 0, c, args.world, vlm="sim") for c in TIMED for t in tasks] if args.check else []
    return timed + plain + checks  # the long ones first, so that the pool ends together


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=2, help="seeds per task for round trips, accuracy, viewpoints")
    ap.add_argument("--wall-seeds", type=int, default=1, help="seeds per task rerun with the latency (paper, lean)")
    ap.add_argument("--latency", type=float, default=0.3, help="seconds the endpoint adds to every request")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--world", choices=["pybullet", "symbolic"], default="pybullet")
    ap.add_argument("--tasks", help="comma-separated task names (default: every file in trees/)")
    ap.add_argument("--json", help="write the rows and the summary here")
    ap.add_argument("--check", action="store_true",
                    help="also run seed 0 of paper and lean with the in-process sim VLM: the same episodes?")
    args = ap.parse_args(argv)
    tasks = args.tasks.split(",") if args.tasks else sorted(p.stem for p in (ROOT / "trees").glob("*.yaml"))
    todo = units(tasks, args)
    rows = collect(todo, args.jobs)
    summary = summarise(rows, args)
    print_summary(summary, args)
    if args.json:
        Path(args.json).write_text(json.dumps({"command": " ".join(["python", *sys.argv]), "args": vars(args),
                                               "versions": versions(), "summary": summary, "rows": rows},
                                              indent=1, default=str))
    return 0


def collect(todo: list[Unit], jobs: int) -> list[dict]:
    rows, durations = [], defaultdict(list)
    t0 = time.perf_counter()
    with ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("spawn"), initializer=_own_directory) as pool:
        pending = {pool.submit(run, u): u for u in todo}
        left = list(todo)
        for f in as_completed(pending):
            u = pending[f]
            left.remove(u)
            row = f.result()
            rows.append(row)
            if "error" in row:
                print(f"  {u.task} seed {u.seed} {u.name} CRASHED: {row['error'].splitlines()[-1]}", file=sys.stderr)
                continue
            durations[u.name].append(row["run_s"])
            elapsed = time.perf_counter() - t0
            eta = sum(_expected(durations, x.name) for x in left) / jobs
            print(f"[{len(rows)}/{len(todo)} episodes, {len(rows) / elapsed * 60:.1f}/min, about {eta / 60:.1f} min left]"
                  f"  {u.task} seed {u.seed} {u.name}: {row['queries']} queries, {row['actions']} actions, "
                  f"{row['correct']}/{row['verified']} correct, {'ok' if row['success'] else row['reason'][:40]}",
                  file=sys.stderr, flush=True)
    return rows


def _expected(durations: dict[str, list[float]], name: str) -> float:
    """An episode's expected duration: the mean of those of its kind so far, else of all so far."""
    done = durations.get(name) or [d for ds in durations.values() for d in ds]
    return sum(done) / len(done) if done else 0.0


def summarise(all_rows: list[dict], args) -> dict:
    rows = [r for r in all_rows if "error" not in r and r["vlm"] == "sim-http"]
    plain = {c: pooled([r for r in rows if r["config"] == c and not r["latency"]]) for c in CONFIGS}
    timed = {c: pooled([r for r in rows if r["config"] == c and r["latency"]]) for c in TIMED}
    key = lambda r: (r["task"], r["seed"], r["config"])  # noqa: E731
    base = {key(r): r["fingerprint"] for r in rows if not r["latency"]}
    reruns = [r for r in rows if r["latency"] and key(r) in base]
    same = sum(base[key(r)] == r["fingerprint"] for r in reruns)
    inproc = [r for r in all_rows if "error" not in r and r["vlm"] == "sim" and key(r) in base]
    same_inproc = sum(base[key(r)] == r["fingerprint"] for r in inproc)
    p, nolp, lean, greedy = (plain[c] for c in ("paper", "lean-nolp", "lean", "greedy"))
    by_episode = defaultdict(dict)
    for r in rows:
        if not r["latency"] and r["config"] in ("paper", "greedy"):
            by_episode[(r["task"], r["seed"])][r["config"]] = r
    pairs = [(e["paper"], e["greedy"]) for e in by_episode.values() if len(e) == 2]
    ratio = lambda a, b: a / b if b else math.nan  # noqa: E731
    return {
        "model": model_figures([r for r in rows if not r["latency"]]),
        "plain": plain, "timed": timed, "latency_reruns_same": [same, len(reruns)],
        "in_process_same": [same_inproc, len(inproc)],
        # VLM-guided minus greedy viewpoints per resolution, and its interval over the episodes both ran
        "viewpoints_difference": p["viewpoints_per_resolution"] - greedy["viewpoints_per_resolution"],
        "viewpoints_difference_95": [round(x, 3) for x in bootstrap(pairs)],
        "crashed": [f"{r['task']} seed {r['seed']} {r['config']}" for r in all_rows if "error" in r],
        "ratios": {"lean_nolp_round_trips": ratio(nolp["per_action"], p["per_action"]),
                   "lean_round_trips": ratio(lean["per_action"], p["per_action"]),
                   "lean_wall": ratio(timed["lean"]["wall_per_action"], timed["paper"]["wall_per_action"]),
                   "lean_checks_wall": ratio(timed["lean"]["checks_wall_per_action"],
                                             timed["paper"]["checks_wall_per_action"])},
        "targets": {
            "first_view_accuracy<0.97": p["first_view"]["all"][3][1] < 0.97,
            "settled_above_first_view": p["settled"]["all"][3][0] > p["first_view"]["all"][3][1],
            "lean_nolp_round_trips<=1/2": ratio(nolp["per_action"], p["per_action"]) <= 0.5,
            "lean_round_trips<=1/4": ratio(lean["per_action"], p["per_action"]) <= 0.25,
            "lean_nolp_accuracy>=paper": nolp["accuracy"] >= p["accuracy"],
            "lean_accuracy>=paper": lean["accuracy"] >= p["accuracy"],
            "lean_wall<=1/5": ratio(timed["lean"]["wall_per_action"], timed["paper"]["wall_per_action"]) <= 0.2,
            "vlm_viewpoints<=1.5": p["viewpoints_per_resolution"] <= 1.5,
            "vlm_viewpoints<greedy": p["viewpoints_per_resolution"] < greedy["viewpoints_per_resolution"]},
    }


def _pct(x) -> str:
    return "   -  " if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:6.3f}"


def print_summary(s: dict, args) -> None:
    plain, timed = s["plain"], s["timed"]
    print(f"\n{args.world}, {args.seeds} seed(s) per task; VLM wall time over {args.wall_seeds} seed(s) at "
          f"{args.latency * 1000:.0f} ms per request")
    print(f"{'':26s} {'episodes':>8s} {'ok':>4s} {'actions':>7s} {'RT/action':>9s} {'checks':>7s} "
          f"{'verified':>8s} {'accuracy':>8s} {'95% interval':>15s} {'unsettled':>9s} {'reused':>6s}")
    for c, label in LABELS.items():
        x = plain[c]
        print(f"{label:26s} {x['episodes']:8d} {x['success']:4d} {x['actions']:7d} {x['per_action']:9.2f} "
              f"{x['checks_per_action']:7.2f} {x['verified']:8d} {x['accuracy']:8.4f} "
              f"{x['accuracy_95'][0]:7.3f}-{x['accuracy_95'][1]:.3f} {x['unsettled']:9d} {x['reused']:6d}")
    r = s["ratios"]
    print(f"round trips per action vs paper: lean without logprobs {r['lean_nolp_round_trips']:.3f}, "
          f"with logprobs {r['lean_round_trips']:.3f}")
    print("\naccuracy per relation: the first view's vote (against the truth at its capture) and the value a "
          "check settled on by looking (confirmed or contradicted), Wilson 95 % intervals")
    for c, label in LABELS.items():
        x = plain[c]
        for rel in sorted(set(x["first_view"]) | set(x["settled"])):
            f, t = x["first_view"].get(rel, [0, 0, None, [0, 1]]), x["settled"].get(rel, [0, 0, None, [0, 1]])
            print(f"  {label:26s} {rel:8s} first view {f[0]:5d}/{f[1]:<5d} {_pct(f[2])} [{f[3][0]:.3f}-{f[3][1]:.3f}]"
                  f"   settled {t[0]:5d}/{t[1]:<5d} {_pct(t[2])} [{t[3][0]:.3f}-{t[3][1]:.3f}]")
    m = s["model"]
    print(f"\nthe simulated model over every answer ({sum(v[1] for v in m['single_view'].values())} answered): "
          f"single-view accuracy per relation and observability band")
    for cell, (k, n, a, acc, ci) in m["single_view"].items():
        rel, b = cell.split("|")
        print(f"  {rel:8s} o {b}  {k:5d}/{n:<5d} {_pct(acc)} [{ci[0]:.3f}-{ci[1]:.3f}]  abstained {a}")
    print(f"  calibration (stated -> accuracy): " + ", ".join(f"{v['stated']:.2f}->{v['accuracy']:.2f} ({v['answers']})"
                                                           for v in m["calibration"].values()))
    print(f"  expected calibration error {m['ece']:.3f}; sufficiency said 'yes' for {_pct(m['sufficiency']['said_sufficient_when_sufficient'])} "
          f"of sufficient views and {_pct(m['sufficiency']['said_sufficient_when_not'])} of insufficient ones")
    print(f"\nVLM wall time per action at {args.latency * 1000:.0f} ms/request "
          f"(checks only: without the survey's sequential questions):")
    for c in TIMED:
        x = timed[c]
        print(f"  {LABELS[c]:24s} {x['wall_per_action']:7.2f} s   checks only {x['checks_wall_per_action']:7.2f} s   "
              f"({x['episodes']} episodes, {x['actions']} actions, {x['queries']} queries)")
    print(f"  lean / paper: {r['lean_wall']:.3f}  (checks only {r['lean_checks_wall']:.3f}); reruns with latency the "
          f"same episodes as without: {s['latency_reruns_same'][0]}/{s['latency_reruns_same'][1]}")
    if s["in_process_same"][1]:
        print(f"  in-process sim VLM runs the same episodes as through the endpoint: "
              f"{s['in_process_same'][0]}/{s['in_process_same'][1]}")
    print("\nviewpoints per uncertainty resolution (paper protocol; checks whose first view did not decide):")
    for c in ("paper", "greedy"):
        x = plain[c]
        print(f"  {'VLM-guided' if c == 'paper' else 'greedy':12s} {x['viewpoints_per_resolution']:5.2f} moves per "
              f"resolution ({x['resolved']} resolved by a view that settled, of {x['uncertain']} uncertain; "
              f"{x['agreed']} decided by agreeing views with the budget spent; all moves / resolutions "
              f"{x['moves_per_resolution_all']:.2f})")
    lo, hi = s["viewpoints_difference_95"]
    print(f"  VLM-guided minus greedy: {s['viewpoints_difference']:+.2f}, 95 % bootstrap interval over episodes {lo:+.2f} to {hi:+.2f}")
    if s["crashed"]:
        print(f"\ncrashed (left out above): {', '.join(s['crashed'])}")
    print("\ntargets: " + ", ".join(f"{k} {'met' if v else 'NOT met'}" for k, v in s["targets"].items()))


if __name__ == "__main__":
    sys.exit(main())
