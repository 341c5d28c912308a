"""The ``vap-bt`` command line.

``vap-bt plan DOMAIN PROBLEM``       print a plan (Fast Downward through unified-planning)
``vap-bt run TASK.yaml``             run a task end to end and print a JSON report
``vap-bt run --domain D --problem P`` the same for any classical PDDL domain (what Fast Downward runs)
``vap-bt export TASK.yaml``          print the compiled tree as BehaviorTree.CPP XML
``vap-bt skills``                    list the installed skill plugins
``vap-bt serve --robot R``           host a robot's skills over Zenoh

Exit codes are documented in :mod:`vap_bt.errors`: 0 success, 1 goal not reached, 2 bad input,
3 no plan, 4 transport down. Errors print one line on stderr, never a traceback.
"""

from __future__ import annotations

import argparse
import json
import logging
import sys
from pathlib import Path

from vap_bt import report as report_mod
from vap_bt.errors import EXIT_BAD_INPUT, EXIT_GOAL_NOT_REACHED, EXIT_OK, InputError, VapBtError


def _progress(quiet: bool):
    return (lambda m: None) if quiet else (lambda m: print(m, file=sys.stderr, flush=True))


def cmd_plan(args) -> int:
    from vap_bt.domain.pddl import load_task
    from vap_bt.domain.planner import Planner

    task = load_task(args.domain, args.problem)
    plan = Planner(task, first_engine=args.engine).plan()
    print(plan)
    print(f"; {len(plan)} actions, cost {plan.cost}, {plan.engine}, {plan.seconds:.3f} s", file=sys.stderr)
    return EXIT_OK


def _load_run_task(args):
    from vap_bt import taskfile

    if args.task and (args.domain or args.problem):
        raise InputError("command line", "give a task file or --domain/--problem, not both")
    if args.task:
        return taskfile.load(args.task)
    if not (args.domain and args.problem):
        raise InputError("command line", "give a task file, or both --domain and --problem")
    spec = taskfile.TaskFile(name=Path(args.problem).stem, domain=str(Path(args.domain).resolve()),
                             problem=str(Path(args.problem).resolve()))
    return taskfile.from_spec(spec, base=Path.cwd(), where=args.problem)


def cmd_run(args) -> int:
    from vap_bt.runner import EpisodeInterrupted, RunConfig, Session

    task = _load_run_task(args)
    cfg = RunConfig.from_task(task, world=args.world, seed=args.seed, verify=args.verify, budget=args.budget,
                              vlm_error=args.vlm_error, injection=False if args.no_injection else None,
                              max_replans=args.max_replans, planner=args.planner, transport=args.transport,
                              early_stop=args.early_stop or None)
    progress = _progress(args.quiet)
    progress(f"task {task.name}: {task.spec.instruction or task.planning.source} "
             f"(world {cfg.world}, seed {cfg.seed}, verify {cfg.verify})")
    recorder = None
    if args.rerun:
        from vap_bt.viz import TreeRecorder  # only the viz room imports rerun

        recorder = TreeRecorder.open(args.rerun, name=f"{task.name} seed {cfg.seed}")
        progress(recorder.hint)
    session = Session(task, cfg, progress, recorder=recorder)
    rep: dict = {"success": False, "goal_satisfied": None, "reason": "interrupted", "seed": cfg.seed,
                 "command": report_mod.command_line()}
    try:
        rep = {**session.episode(), "command": report_mod.command_line()}
    except EpisodeInterrupted as stop:
        rep = {**stop.report, "command": report_mod.command_line(), "interrupted": True}
        raise
    finally:
        session.close()
        if args.report:  # written even when the run stops early, so nothing already known is lost
            report_mod.write(rep, args.report)
        if recorder is not None:
            recorder.serve_until_interrupted()
            recorder.close()
    summary = {k: rep[k] for k in ("success", "goal_satisfied", "reason", "seed", "replans", "vlm_queries",
                                   "wall_s")}
    summary["situations"] = rep["situations"]
    summary["injected"] = rep["injected"]
    summary["plans"] = [p["actions"] for p in rep["plans"]]
    summary["plan_costs"] = [p["cost"] for p in rep["plans"]]
    # which predicates the trees did not look at, and why (the full report lists every atom)
    summary["unchecked"] = {u["name"]: u["reason"] for u in rep.get("unchecked", [])}
    print(json.dumps(rep if args.full else summary, indent=2, default=str))
    ok = rep["success"] and rep["goal_satisfied"]
    return EXIT_OK if ok else EXIT_GOAL_NOT_REACHED


def cmd_export(args) -> int:
    """Plan a task and print its compiled tree as BehaviorTree.CPP XML."""
    from vap_bt.bt.compiler import compile_plan
    from vap_bt.bt.context import ExecutionContext, VerifyMode
    from vap_bt.bt.export import to_btcpp_xml
    from vap_bt.domain.planner import Planner
    from vap_bt.scene.graph import SceneGraph

    task = _load_run_task(args)
    planning = task.planning
    plan = Planner(planning).plan()
    ctx = ExecutionContext(graph=SceneGraph.of_facts(planning.init), vlm=None,
                           camera=None, skills=None, mode=VerifyMode.parse(args.verify or task.options.verify),
                           budget=task.options.budget, profile=task.profile)
    xml = to_btcpp_xml(compile_plan(ctx, plan.actions, planning.goal, planning.knowledge))
    if args.output:
        Path(args.output).write_text(xml)
    else:
        sys.stdout.write(xml)
    return EXIT_OK


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="vap-bt", description="Behaviour-tree executive with VLM-checked PDDL plans")
    p.add_argument("-v", "--verbose", action="store_true", help="debug logging")
    sub = p.add_subparsers(dest="command", required=True)

    sp = sub.add_parser("plan", help="print a plan for a PDDL domain and problem")
    sp.add_argument("domain")
    sp.add_argument("problem")
    sp.add_argument("--engine", choices=["fast-downward", "search"], default="fast-downward")
    sp.set_defaults(func=cmd_plan)

    sr = sub.add_parser("run", help="run a task (or a PDDL problem) end to end")
    sr.add_argument("task", nargs="?", help="task file (trees/*.yaml)")
    sr.add_argument("--domain")
    sr.add_argument("--problem")
    sr.add_argument("--world", choices=["symbolic", "pybullet"])
    sr.add_argument("--seed", type=int, default=0)
    sr.add_argument("--verify", choices=["both", "pre", "eff", "none"])
    sr.add_argument("--budget", type=int, help="viewpoint budget K")
    sr.add_argument("--vlm-error", type=float, help="symbolic VLM per-query error rate (default 0.05)")
    sr.add_argument("--no-injection", action="store_true", help="turn Table II situation injection off")
    sr.add_argument("--early-stop", action="store_true", help="stop a vote once it is decided")
    sr.add_argument("--max-replans", type=int)
    sr.add_argument("--planner", choices=["fast-downward", "search"], help="engine of the first plan")
    sr.add_argument("--transport", choices=["inproc", "zenoh"], default="zenoh",
                    help="zenoh (default): skill servers in this command, reached over a loopback Zenoh link; "
                         "inproc: skills called directly (fast campaigns)")
    sr.add_argument("--report", help="write the full JSON report here")
    sr.add_argument("--rerun", nargs="+", metavar="MODE",
                    help="live view in rerun: 'spawn' (a local viewer), 'serve [PORT]' (gRPC on 127.0.0.1, "
                         "default 9876), or 'save FILE.rrd'")
    sr.add_argument("--full", action="store_true", help="print the full report, not the summary")
    sr.add_argument("-q", "--quiet", action="store_true", help="no progress lines on stderr")
    sr.set_defaults(func=cmd_run)

    se = sub.add_parser("export", help="plan a task and print its tree as BehaviorTree.CPP XML")
    se.add_argument("task", nargs="?", help="task file (trees/*.yaml)")
    se.add_argument("--domain")
    se.add_argument("--problem")
    se.add_argument("--verify", choices=["both", "pre", "eff", "none"])
    se.add_argument("-o", "--output", help="write the XML here instead of stdout")
    se.set_defaults(func=cmd_export)

    _add_transport_commands(sub)
    return p


def _add_transport_commands(sub) -> None:
    try:
        from vap_bt.transport import serve
    except ImportError:  # the transport room is optional for plan/run
        return
    if hasattr(serve, "add_skills_arguments"):
        sk = sub.add_parser("skills", help="list installed skill plugins")
        serve.add_skills_arguments(sk)
        sk.set_defaults(func=serve.run_skills)
    if hasattr(serve, "add_serve_arguments"):
        sv = sub.add_parser("serve", help="host a robot's skills over Zenoh")
        serve.add_serve_arguments(sv)
        sv.set_defaults(func=serve.run_serve)



def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse already printed one line of usage error
        return EXIT_BAD_INPUT if exc.code else EXIT_OK
    logging.basicConfig(level=logging.DEBUG if args.verbose else logging.WARNING,
                        format="%(levelname)s %(name)s: %(message)s")
    try:
        return args.func(args)
    except VapBtError as exc:
        print(f"vap-bt: {exc}", file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        print("vap-bt: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # output piped into a reader that stopped early (head, less)
        sys.stderr.close()
        return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
