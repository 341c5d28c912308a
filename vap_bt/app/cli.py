"""The ``vap-bt`` command line.

``vap-bt plan DOMAIN PROBLEM``       print a plan (Fast Downward through unified-planning)
``vap-bt run TASK.yaml``             run a task end to end in its world; a summary table (``--json``: JSON)
``vap-bt run --domain D --problem P`` the same for any classical PDDL domain (what Fast Downward runs)
``vap-bt export TASK.yaml``          print the compiled tree as BehaviorTree.CPP XML
``vap-bt tree TASK.yaml``            print the compiled tree (ascii, dot or xml) without running it
``vap-bt skills``                    list the installed skill plugins
``vap-bt serve --robot R``           host a robot's skills over Zenoh
``vap-bt sim TASK.yaml``             host the pybullet world, its drivers, the simulated VLM and the oracle
``vap-bt run TASK.yaml --connect EP`` run the executive against a sim and skill servers already running
``vap-bt launch FILE.yaml``          start a connected set-up's parts (sim, servers, executive) as one
``vap-bt parts``                     list the parts alive on the Zenoh network and the goals in flight

Exit codes are documented in :mod:`vap_bt.errors`: 0 success, 1 goal not reached, 2 bad input,
3 no plan, 4 transport down, 5 the planner ran out of time, 130 interrupted (Ctrl-C; a run still
writes its report so far and prints its summary). Errors print one line on stderr, never a
traceback. Progress goes to stderr; stdout carries only a command's result (a run's summary table, or with ``--json`` its JSON).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import logging
import sys
from pathlib import Path

from vap_bt import report as report_mod
from vap_bt.errors import (EXIT_BAD_INPUT, EXIT_GOAL_NOT_REACHED, EXIT_INTERRUPTED, EXIT_OK, EXIT_PLANNING_TIMEOUT,
                            EXIT_UNSOLVABLE, InputError, VapBtError)


def _progress(quiet: bool):
    return (lambda m: None) if quiet else (lambda m: print(m, file=sys.stderr, flush=True))


def cmd_plan(args) -> int:
    """``vap-bt plan``: the plan on stdout; its length, cost, engine and planning time on stderr."""
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
    for flag, name in (("--domain", args.domain), ("--problem", args.problem)):
        if not Path(name).is_file():  # said here: from_spec would blame a task file's field
            raise InputError(name, f"no such file (given as {flag})")
    spec = taskfile.TaskFile(name=Path(args.problem).stem, domain=str(Path(args.domain).resolve()),
                             problem=str(Path(args.problem).resolve()))
    return taskfile.from_spec(spec, base=Path.cwd(), where=args.problem)


def cmd_run(args) -> int:
    """Run a task; stdout carries the result only: the summary table, or the JSON with ``--json``."""
    with _stdout_for_results(args) as stdout:
        return _run(args, stdout)


@contextlib.contextmanager
def _stdout_for_results(args):
    """With ``--json`` stdout carries the JSON and nothing else: while the run runs, anything printed
    to stdout (a plugin, a library) goes to stderr. Yields the stream the result goes to."""
    stdout = sys.stdout
    if not _wants_json(args):
        yield stdout
        return
    with contextlib.redirect_stdout(sys.stderr):
        yield stdout


def _wants_json(args) -> bool:
    return args.json or args.full


def _finish_run(args, rep: dict, stdout, recorder) -> None:
    """A finished run's last words: the summary table (stdout; on stderr beside ``--json``) and,
    with ``--json``, the JSON summary (``--full``: the whole report) alone on stdout."""
    from vap_bt import run_summary

    outputs = run_summary.Outputs(report=args.report, recording=_recording_text(recorder))
    table = run_summary.table(rep, outputs)
    if not _wants_json(args):
        print(table, file=stdout, flush=True)
        return
    if not args.quiet:
        print(table, file=sys.stderr, flush=True)
    doc = rep if args.full else run_summary.summary(rep, outputs)
    print(json.dumps(doc, indent=2, default=str), file=stdout, flush=True)


def _recording_text(recorder) -> str | None:
    """Where the live view went, for the summary (None: not recorded)."""
    if recorder is None:
        return None
    spec = recorder.recording.spec
    if spec.mode == "save":
        return f"{spec.path} (open it with `rerun {spec.path}`)"
    return recorder.hint.removeprefix("rerun: ")


def _run(args, stdout) -> int:
    from vap_bt.perception.goal_parsing import GoalParseError
    from vap_bt.app.runner import EpisodeInterrupted, RunConfig, Session, check_config

    task = _load_run_task(args)
    cfg = RunConfig.from_task(task, **RunConfig.given(args, "run"))  # the flags over the task file's options
    check_config(task, cfg)  # bad options in one line, before the first progress line
    remote = _remote_settings(args)
    progress = _progress(args.quiet)
    progress(f"task {task.name}: {task.spec.instruction or task.planning.source} "
             f"(world {cfg.world}, seed {cfg.seed}, verify {cfg.verify})")
    recorder = None
    if args.rerun:
        from vap_bt.viz import TreeRecorder  # only the viz room imports rerun

        recorder = TreeRecorder.open(args.rerun, name=f"{task.name} seed {cfg.seed}")
        progress(recorder.hint)
    session = None
    rep: dict | None = None  # the episode's report: finished, or as far as a Ctrl-C let it get
    try:
        session = Session(task, cfg, progress, recorder=recorder, remote=remote)
        rep = {**session.episode(), "command": report_mod.command_line()}
    except EpisodeInterrupted as stop:  # Ctrl-C, at any moment: the report so far ends the run as one would
        rep = {**stop.report, "command": report_mod.command_line()}
    except GoalParseError as exc:  # no episode to report, but what the VLM answered is kept
        if args.report:
            report_mod.write({"success": False, "goal_satisfied": None, "reason": "goal not parsed",
                              "seed": cfg.seed, "command": report_mod.command_line(),
                              "goal_parsing": exc.record.to_json()}, args.report)
        raise
    finally:
        if session is not None:
            session.close()
        if rep is not None:
            if args.report:  # written even when the run stops early, so nothing already known is lost
                report_mod.write(rep, args.report)
            _finish_run(args, rep, stdout, recorder)  # said before a served recording waits for Ctrl-C
        if recorder is not None:
            recorder.serve_until_interrupted(say=lambda m: print(m, file=sys.stderr, flush=True))
            recorder.close()
    if rep["interrupted"]:
        print(f"vap-bt: interrupted (phase: {rep['phase']})", file=sys.stderr, flush=True)
        return EXIT_INTERRUPTED
    ok = rep["success"] and rep["goal_satisfied"]
    no_plan = {"unsolvable": EXIT_UNSOLVABLE, "timeout": EXIT_PLANNING_TIMEOUT}.get(rep.get("no_initial_plan"))
    return EXIT_OK if ok else no_plan or EXIT_GOAL_NOT_REACHED


def _remote_settings(args):
    """``--connect``/``--zenoh-config``: the parts run elsewhere (:mod:`vap_bt.app.connected`)."""
    if not (args.connect or args.zenoh_config):
        if args.listen:
            raise InputError("--listen", "only with --connect (the executive then listens there as a Zenoh peer); "
                                         "the embedded run picks a free loopback port itself")
        return None
    if args.transport == "inproc":
        raise InputError("--transport", "inproc runs the skills in this process; --connect reaches them over Zenoh")
    from vap_bt.transport.config import part_settings

    return part_settings(args)


def _compiled_tree(args):
    """Plan a task from its stated initial state and compile the plan into the executive's tree.

    Planning only: no world runs and nothing is perceived, so the tree is the one the executive
    would start from if the first survey saw exactly what the task file states."""
    from vap_bt.bt.compiler import compile_plan
    from vap_bt.bt.context import ExecutionContext
    from vap_bt.domain.planner import Planner
    from vap_bt.scene.graph import SceneGraph
    from vap_bt.settings import RunConfig
    from vap_bt.strategy import Strategy

    task = _load_run_task(args)
    settings = RunConfig.chosen(task, **RunConfig.given(args, args.command))  # --verify over options.verify
    planning = task.planning
    if not planning.goal:
        raise InputError(f"{task.path}: field goal", "export plans goal: atoms; a goal in words is parsed only "
                                                     "by a run (vap-bt run --vlm openai|gemini)")
    if settings["verify"] == "vlm_planner":
        raise InputError("--verify", "vlm_planner compiles no tree: the VLM names each action as the run goes")
    plan = Planner(planning).plan()
    ctx = ExecutionContext(graph=SceneGraph.of_facts(planning.init), vlm=None,
                           camera=None, skills=None, strategy=Strategy.parse(settings["verify"]),
                           budget=settings["budget"], profile=task.profile)
    return compile_plan(ctx, plan.actions, planning.goal, planning.knowledge)


def _write(text: str, output: str | None) -> None:
    if output:
        Path(output).write_text(text)
    else:
        sys.stdout.write(text)


def cmd_export(args) -> int:
    """Plan a task and print its compiled tree as BehaviorTree.CPP XML."""
    from vap_bt.bt.export import to_btcpp_xml

    _write(to_btcpp_xml(_compiled_tree(args)), args.output)
    return EXIT_OK


def _dot(graph) -> str:
    """py_trees' dot graph as text, its node IDs quoted: py_trees names a node by its behaviour's
    name, and pydot leaves ``a0: find(cup)`` bare, which Graphviz reads as node ``a0``, port ``find(cup)``."""
    def quoted(name: str) -> str:
        return name if name.startswith('"') else '"' + name.replace('"', '\\"') + '"'

    for node in graph.get_nodes():  # pydot has split the name at its colon into name and "port"
        node.obj_dict["name"] = quoted(node.get_name() + (node.obj_dict.pop("port", None) or ""))
    for edge in graph.get_edges():
        edge.obj_dict["points"] = tuple(quoted(x) for x in edge.obj_dict["points"])
    return graph.to_string()


def cmd_tree(args) -> int:
    """Plan a task and print its compiled tree without running it: py_trees' ascii or dot display,
    or the BehaviorTree.CPP v4 XML of ``export``."""
    import py_trees

    from vap_bt.bt.export import to_btcpp_xml

    root = _compiled_tree(args)
    if args.format == "xml":
        text = to_btcpp_xml(root)
    elif args.format == "dot":
        text = _dot(py_trees.display.dot_tree(root))
    else:
        text = py_trees.display.ascii_tree(root)
    _write(text, args.output)
    return EXIT_OK


def _examples(*lines: str) -> dict:
    """``add_parser``/``ArgumentParser`` keywords that end a command's ``--help`` with examples."""
    return {"epilog": "examples:\n" + "\n".join(f"  {l}" for l in lines),
            "formatter_class": argparse.RawDescriptionHelpFormatter}


def build_parser() -> argparse.ArgumentParser:
    """The ``vap-bt`` parser: every command with its options (declared in :mod:`vap_bt.settings`) and
    examples."""
    from vap_bt.app.arguments import add_settings
    from vap_bt.settings import Commands, RunConfig, RunOutput, TaskSource, TreeOutput, Zenoh

    p = argparse.ArgumentParser(prog="vap-bt", description="Behaviour-tree executive with VLM-checked PDDL plans",
                                **_examples("vap-bt run trees/collect_cup.yaml      # in the pybullet household",
                                            "vap-bt run trees/collect_cup.yaml --world symbolic",
                                            "vap-bt tree trees/collect_cup.yaml",
                                            "vap-bt run trees/boil_water.yaml --rerun save run.rrd",
                                            "vap-bt COMMAND --help   (examples for each command)"))
    add_settings(p, "vap-bt", Commands)
    sub = p.add_subparsers(dest="command", required=True)

    sp = sub.add_parser("plan", help="print a plan for a PDDL domain and problem", **_examples(
        "vap-bt plan tests/domains/gripper-domain.pddl tests/domains/gripper-p4.pddl",
        "vap-bt plan tests/domains/blocksworld-domain.pddl tests/domains/blocksworld-p6.pddl --engine search"))
    add_settings(sp, "plan", Commands)
    sp.set_defaults(func=cmd_plan)

    sr = sub.add_parser("run", help="run a task (or a PDDL problem) end to end", **_examples(
        "vap-bt run trees/boil_water.yaml                      # in its world: the pybullet household",
        "vap-bt run trees/collect_cup.yaml --world symbolic --seed 3 --report out/r.json",
        "vap-bt run trees/boil_water.yaml --no-injection --rerun save run.rrd   # record the live view",
        "vap-bt run trees/boil_water.yaml --world symbolic --verify none   # the closed-world baseline",
        "vap-bt run trees/cut_lemon.yaml --world symbolic --json > summary.json   # for scripts",
        "vap-bt run --domain tests/domains/gripper-domain.pddl --problem tests/domains/gripper-p4.pddl"),
        description="Runs a task in its world: the task file's world: (the household's say pybullet), else\n"
                    "symbolic; --world overrides; a PDDL domain and problem run symbolic. Progress goes to\n"
                    "stderr; at the end stdout gets a summary table, or with --json only the JSON summary.\n"
                    "Exit codes: 0 success (the world confirms it), 1 goal not reached, 2 bad input,\n"
                    "3 no plan exists from what the robot saw, 4 transport down, 5 the planner ran\n"
                    "out of time, 130 interrupted (Ctrl-C: the report so far and the summary are still\n"
                    "written).")
    add_settings(sr, "run", TaskSource, RunConfig, Zenoh, RunOutput)
    sr.set_defaults(func=cmd_run)

    se = sub.add_parser("export", help="plan a task and print its tree as BehaviorTree.CPP XML", **_examples(
        "vap-bt export trees/collect_cup.yaml -o tree.xml",
        "vap-bt export trees/pick_plate.yaml --verify eff"))
    add_settings(se, "export", TaskSource, RunConfig, TreeOutput)
    se.set_defaults(func=cmd_export)

    st = sub.add_parser("tree", help="plan a task and print its compiled tree without running it", **_examples(
        "vap-bt tree trees/collect_cup.yaml                      # py_trees' ascii tree",
        "vap-bt tree trees/collect_cup.yaml --format dot | dot -Tsvg > tree.svg",
        "vap-bt tree trees/boil_water.yaml --format xml --verify eff   # BehaviorTree.CPP v4 XML"),
        description="Plans from the task file's stated initial state (planning only: no world runs, "
                    "nothing is perceived) and prints the tree the executive would start with.")
    add_settings(st, "tree", TaskSource, RunConfig, TreeOutput)
    st.set_defaults(func=cmd_tree)

    _add_transport_commands(sub)
    return p


def _add_transport_commands(sub) -> None:
    try:
        from vap_bt.app import serve
    except ImportError:  # the transport room is optional for plan/run
        return
    if hasattr(serve, "add_skills_arguments"):
        sk = sub.add_parser("skills", help="list installed skill plugins", **_examples(
            "vap-bt skills", "vap-bt skills --json"))
        serve.add_skills_arguments(sk)
        sk.set_defaults(func=serve.run_skills)
    if hasattr(serve, "add_serve_arguments"):
        sv = sub.add_parser("serve", help="host a robot's skills over Zenoh", **_examples(
            "vap-bt serve --robot ur5e --world symbolic --task trees/collect_cup.yaml",
            "vap-bt serve --robot base --robot ur5e --world pybullet --task trees/boil_water.yaml"))
        serve.add_serve_arguments(sv)
        sv.set_defaults(func=serve.run_serve)
    from vap_bt.app import sim_host

    sm = sub.add_parser("sim", help="host the pybullet world, its drivers, the simulated VLM and the oracle over Zenoh",
                        **_examples(
        "vap-bt sim trees/boil_water.yaml --no-injection          # the router on tcp/127.0.0.1:7447",
        "vap-bt serve --robot ur5e --world remote                 # in another shell",
        "vap-bt serve --robot base --world remote                 # in a third",
        "vap-bt run trees/boil_water.yaml --connect tcp/127.0.0.1:7447"),
        description=sim_host.DESCRIPTION)
    sim_host.add_sim_arguments(sm)
    sm.set_defaults(func=sim_host.run_sim)

    from vap_bt.app import census, launch

    examples = _examples("vap-bt launch examples/launch/boil_water.yaml   # sim, arm, base, executive; Ctrl-C ends",
                         "vap-bt launch examples/launch/boil_water.yaml --endpoint tcp/127.0.0.1:7450",
                         "vap-bt parts                                    # in another shell, while it runs")
    la = sub.add_parser("launch", help="start a connected set-up's parts from a launch file, stop them together",
                        description=launch.__doc__.split("\n\n")[0].replace("``", ""),
                        epilog=f"{launch.SCHEMA}\n\n{examples['epilog']}",
                        formatter_class=argparse.RawDescriptionHelpFormatter)
    launch.add_launch_arguments(la)
    la.set_defaults(func=launch.run_launch)

    pa = sub.add_parser("parts", help="list the parts alive on the Zenoh network and the goals in flight",
                        description=census.__doc__.split("\n\n")[0].replace("``", ""), **_examples(
        "vap-bt parts                                      # the sim's router at tcp/127.0.0.1:7447",
        "vap-bt parts --connect tcp/127.0.0.1:7450 --json",
        "vap-bt parts --watch                              # parts and goals as they come and go"))
    census.add_parts_arguments(pa)
    pa.set_defaults(func=census.run_parts)



def main(argv: list[str] | None = None) -> int:
    """The ``vap-bt`` entry point: runs the command ``argv`` names (default: the process's arguments) and
    returns its exit code (:mod:`vap_bt.errors`)."""
    try:
        return _command(argv)
    except KeyboardInterrupt:  # before a run has begun (imports, the task file), or a command without a report
        print("vap-bt: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED


def _command(argv: list[str] | None) -> int:
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
    except BrokenPipeError:  # output piped into a reader that stopped early (head, less)
        sys.stderr.close()
        return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
