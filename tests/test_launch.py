"""``vap-bt launch`` and ``vap-bt parts`` with real processes and real Zenoh on 127.0.0.1.

``launch`` runs in a process group of its own, as a person's shell would run it, and starts each
part in a group of its own; every test that starts one checks, from /proc, that once it has
exited no process of its group or of any part's group is left. The parts' pids come from
launch's own ``[launch] NAME: vap-bt … (pid N)`` lines, checked against /proc's list of its
children while they run.
"""

from __future__ import annotations

import collections
import json
import os
import re
import signal
import subprocess
import time
from pathlib import Path

import pytest
import yaml

from plugin_fixtures.zenoh_net import endpoint, free_port, session
from tools.bench.process_faults import Part, alive_in, start, vap_bt
from vap_bt.app import census, launch, serve, sim_host

pytestmark = pytest.mark.timeout(600)

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "launch" / "boil_water.yaml"
TASK = "trees/boil_water.yaml"
#: the task of the longest launch, in place of the example's boil_water: its episode is one plan of
#: five actions (about a quarter of boil_water's time in pybullet) — the subject here is the parts
SHORT = "collect_cup"
STARTED = re.compile(r"^\[launch\] (\S+): vap-bt .* \(pid (\d+)\)$", re.M)


def _example(tmp: Path, *more_parts: dict, report: str = "report.json", task: str = "boil_water") -> Path:
    """The shipped example, its executive's report in ``tmp``, its task (the sim's and the
    executive's) ``task``, with ``more_parts`` appended."""
    spec = yaml.safe_load(EXAMPLE.read_text())
    executive = next(p for p in spec["parts"] if p["command"] == "run")
    executive["args"] = [str(tmp / report) if a == "out/boil_water.json" else a for a in executive["args"]]
    for part in spec["parts"]:
        part["args"] = [f"trees/{task}.yaml" if a == TASK else a for a in part.get("args", [])]
    spec["parts"] += list(more_parts)
    return _write(tmp, spec)


def _write(tmp: Path, spec: dict) -> Path:
    path = tmp / "launch.yaml"
    path.write_text(yaml.safe_dump(spec))
    return path


def _launch(tmp: Path, file: Path, ep: str) -> Part:
    return start(tmp, "launch", vap_bt("launch", str(file), "--endpoint", ep))


def _children(pid: int) -> set[int]:
    """Pids of the live processes whose parent is ``pid``."""
    found = set()
    for entry in os.listdir("/proc"):
        try:
            fields = Path(f"/proc/{entry}/stat").read_text().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        if int(fields[1]) == pid and fields[0] != "Z":
            found.add(int(entry))
    return found


def _started(run: Part) -> dict[str, int]:
    return {name: int(pid) for name, pid in STARTED.findall(run.stderr())}


def _nothing_left(run: Part, pids: dict[str, int]) -> None:
    """Once ``launch`` has exited: no process of its group or of any part's group (each part's
    pid is its group's id) is alive."""
    groups = {run.proc.pid, *pids.values()}
    deadline = time.monotonic() + 5
    while alive_in(groups) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not alive_in(groups), f"left running: {alive_in(groups)}"


def _stop(run: Part) -> None:
    """A test that failed half-way: its launch and every part killed."""
    if run.proc.poll() is not None:
        return
    pids = _started(run)
    for pgid in (run.proc.pid, *pids.values()):
        try:
            os.killpg(pgid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    run.proc.wait(10)


def _parts_now(ep: str, *extra: str) -> subprocess.CompletedProcess:
    return subprocess.run(vap_bt("parts", "--connect", ep, *extra), capture_output=True, text=True, timeout=60,
                          cwd=ROOT)


@pytest.mark.slow(seconds=55)  # 57 s in the full run of 2026-12-05
def test_the_example_launched_as_four_parts_succeeds_the_world_confirms_it_and_nothing_is_left(tmp_path):
    """The example launch file's four parts (sim, arm's and base's skill servers, the executive),
    on the task :data:`SHORT`, plus a second run on the same parts; ``vap-bt parts`` lists them
    while the first runs."""
    ep = endpoint(free_port())
    again = {"name": "again", "command": "run",
             "args": [f"trees/{SHORT}.yaml", "--seed", "0", "--report", str(tmp_path / "again.json"), "--json", "-q"]}
    run = _launch(tmp_path, _example(tmp_path, again, task=SHORT), ep)
    try:
        # the executive's token is declared once it has found both servers: then all four are listed
        run.wait_for(r"\[executive\] ", 240, stream="stderr")
        deadline = time.monotonic() + 240
        while True:
            listing = json.loads(_parts_now(ep, "--json").stdout or '{"parts": []}')
            if any(p["kind"] == "executive" for p in listing["parts"]) or time.monotonic() > deadline:
                break
            time.sleep(1.0)
        pids = _started(run)
        assert list(pids) == ["sim", "arm", "base", "executive"], run.stderr()
        assert set(pids.values()) == _children(run.proc.pid)  # launch's lines name every child it has
        named = {(p["kind"], p["robot"]): p["name"] for p in listing["parts"]}
        assert set(named) == {("sim", ""), ("drivers", "base"), ("drivers", "ur5e"), ("skill server", "ur5e"),
                              ("skill server", "base"), ("executive", "")}, listing
        # each token names the process that holds it
        assert named["sim", ""].startswith(f"{SHORT}-{pids['sim']}-")
        assert named["skill server", "ur5e"].startswith(f"ur5e-{pids['arm']}-")
        assert named["skill server", "base"].startswith(f"base-{pids['base']}-")
        assert named["executive", ""].startswith(f"{SHORT}-{pids['executive']}-")
        table = _parts_now(ep)
        assert table.returncode == 0 and table.stdout.splitlines()[0].split() == ["PART", "ROBOT/NAME", "KEY"]
        assert f"skill server  ur5e/{named['skill server', 'ur5e']}" in table.stdout, table.stdout
        # a goal in flight, if one is caught within a minute (goals come and go: none is no failure)
        with session(connect=(ep,)) as s:
            deadline = time.monotonic() + 60
            while time.monotonic() < deadline and run.proc.poll() is None:
                _, goals = census.snapshot(s, timeout=1.0)
                if goals:
                    goal = goals[0]
                    assert goal.server == named["skill server", goal.robot], goal
                    assert goal.action in {"navigate", "find", "open", "takeout", "grasp", "placein", "close",
                                           "turnon", "fill", "placeon"}, goal
                    print(f"caught {goal}")  # shown with -s
                    break
                time.sleep(0.2)
        # another task against the same parts is refused in one line, the episode unharmed
        other = subprocess.run(vap_bt("run", str(ROOT / TASK), "--connect", ep),
                               capture_output=True, text=True, timeout=120, cwd=ROOT)
        assert other.returncode == 2
        assert other.stderr.strip().splitlines()[-1] == (
            f"vap-bt: --connect: the world at {ep} runs task '{SHORT}', not 'boil_water'")
        assert run.proc.wait(480) == 0, run.stderr()[-4000:]
    finally:
        _stop(run)
    _nothing_left(run, pids)
    out, err = run.stdout(), run.stderr()
    assert "Traceback" not in out + err
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["success"] and report["goal_satisfied"]  # the oracle is the sim process's
    assert report["world"]["name"] == "pybullet" and report["config"]["injection"] is False
    assert report["injected"] == []
    servers = report["processes"]["servers"]
    assert servers == {"ur5e": [named["skill server", "ur5e"]], "base": [named["skill server", "base"]]}
    # the same parts served another episode: the run reset the world it found at the goal
    second = json.loads((tmp_path / "again.json").read_text())
    assert second["success"] and second["goal_satisfied"], second["reason"]
    summary = json.loads("\n".join(line.removeprefix("[again] ") for line in out.splitlines()
                                   if line.startswith("[again] ")))
    assert summary["success"] and summary["goal_satisfied"]
    # every action either run executed reached the world through a skill server: announced there,
    # and each server logged its goal's acceptance and exactly one result
    executed = [a["action"] for r in (report, second) for a in r["actions_executed"]]
    assert re.findall(r"^\[sim\] vap-bt sim: \[[0-9.]+\] begin (.+)$", err, re.M) == executed
    accepted = re.findall(r"^\[(?:arm|base)\] vap-bt serve: \[[0-9.]+\] (?:ur5e|base) goal (\S+) (\S+?\(.*?\)) "
                          r"\[\w+\]: accepted$", err, re.M)
    assert collections.Counter(call for _, call in accepted) == collections.Counter(executed)
    ended = re.findall(r"goal (\S+) \S+?\(.*?\) \[\w+\]: (?:succeeded|aborted|canceled) after [0-9.]+ s: ", err)
    assert sorted(ended) == sorted(goal for goal, _ in accepted)
    # ready lines that read well, every part's line prefixed, and everything stopped cleanly
    assert (f"[arm] vap-bt serve: ready: ur5e skills [close, cut, fill, grasp, open, placein, placeon, push, takeout, "
            f"turnon] with the camera, on zenoh (connected to {ep})") in out.splitlines()
    assert (f"[base] vap-bt serve: ready: base skills [find, navigate], on zenoh (connected to {ep})"
            in out.splitlines())
    assert (f"[sim] vap-bt sim: ready: world {SHORT} (seed 0, injection off) with drivers of base and ur5e, the "
            f"simulated VLM on ur5e and the oracle, on zenoh (router listening on {ep})") in out.splitlines()
    for name in ("executive", "again", "arm", "base", "sim"):
        assert f"[launch] {name} exited with code 0" in err.splitlines(), name
    prefixed = re.compile(r"\[(launch|sim|arm|base|executive|again)\] ")
    assert all(prefixed.match(line) for line in out.splitlines() + err.splitlines())


@pytest.mark.slow
def test_ctrl_c_stops_every_part_and_launch_exits_with_the_executives_130(tmp_path):
    """SIGINT to launch as the executive surveys: it gets SIGINT (and writes its report so far),
    the servers and the sim SIGTERM; all exit cleanly and nothing is left."""
    ep = endpoint(free_port())
    run = _launch(tmp_path, _example(tmp_path), ep)
    try:
        run.wait_for(r"\[executive\] survey", 180, stream="stderr")
        pids = _started(run)
        assert set(pids) == {"sim", "arm", "base", "executive"}
        assert set(pids.values()) == _children(run.proc.pid)
        run.proc.send_signal(signal.SIGINT)
        assert run.proc.wait(60) == 130, run.stderr()[-3000:]
    finally:
        _stop(run)
    _nothing_left(run, pids)
    err = run.stderr()
    assert "Traceback" not in err + run.stdout()
    assert re.search(r"^\[executive\] vap-bt: interrupted \(phase: \w+\)$", err, re.M), err[-3000:]
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["interrupted"] is True
    assert (f"[base] vap-bt serve: ready: base skills [find, navigate], on zenoh (connected to {ep})"
            in run.stdout().splitlines())
    said = [line for line in err.splitlines() if line.startswith("[launch] ")]
    assert said[-8:] == [
        "[launch] interrupted: stopping every part, the executive first (it writes its report so far)",
        "[launch] stopping executive (SIGINT)", "[launch] executive exited with code 130",
        "[launch] stopping arm, base (SIGTERM)", "[launch] arm exited with code 0", "[launch] base exited with code 0",
        "[launch] stopping sim (SIGTERM)", "[launch] sim exited with code 0"]


@pytest.mark.slow
def test_run_connect_without_servers_names_every_missing_one_and_the_endpoint_it_tried(tmp_path):
    """The executive finds the sim and no skill server: its one line names both robots, the
    endpoint, and the command for each with that endpoint; launch exits with its 4."""
    ep = endpoint(free_port())
    spec = {"parts": [{"name": "sim", "command": "sim", "args": [TASK, "--no-injection"]},
                      {"name": "executive", "command": "run", "args": [TASK, "--peer-timeout", "1"]}]}
    run = _launch(tmp_path, _write(tmp_path, spec), ep)
    try:
        assert run.proc.wait(180) == 4, run.stderr()[-3000:]
    finally:
        _stop(run)
    pids = _started(run)
    _nothing_left(run, pids)
    executive = [line for line in run.stderr().splitlines() if line.startswith("[executive] ")]
    assert executive[-1] == (
        f"[executive] vap-bt: no skill server of robots base, ur5e is up at {ep} within 1 s: start "
        f"`vap-bt serve --robot base --world remote --connect {ep}` and "
        f"`vap-bt serve --robot ur5e --world remote --connect {ep}`")
    assert run.stderr().splitlines()[-1] == "[launch] sim exited with code 0"


def test_a_part_that_dies_before_it_is_ready_ends_the_launch_in_one_line(tmp_path):
    """One server of a stage comes up, the other cannot: the launch says which and why in one
    line, exits 4, stops the one that came up, and never starts the executive."""
    ep = endpoint(free_port())
    symbolic = ["--world", "symbolic", "--task", "trees/collect_cup.yaml"]
    spec = {"parts": [{"name": "arm", "command": "serve", "args": ["--robot", "ur5e", *symbolic, "--listen", ep]},
                      {"name": "ghost", "command": "serve", "args": ["--robot", "ghost", *symbolic]},
                      {"name": "executive", "command": "run", "args": [TASK]}]}
    run = _launch(tmp_path, _write(tmp_path, spec), ep)
    try:
        assert run.proc.wait(120) == 4, run.stderr()
    finally:
        _stop(run)
    pids = _started(run)
    assert set(pids) == {"arm", "ghost"}  # the executive never started
    _nothing_left(run, pids)
    assert "Traceback" not in run.stderr()
    assert run.stderr().strip().splitlines()[-1] == (
        f"vap-bt: launch: part ghost (vap-bt serve --robot ghost --world symbolic --task trees/collect_cup.yaml "
        f"--connect {ep}) exited with code 2 before it was ready; its last line: vap-bt: --robot: no skill plugin "
        "is bound to robot 'ghost' (robots with skills: base, ur5e)")


@pytest.mark.parametrize("text, field, message", [
    ("parts:\n  - {name: sim, command: simulate}\n", "parts.0.command", "Input should be 'sim', 'serve' or 'run'"),
    ("parts:\n  - {name: a, command: sim}\n  - {name: a, command: run}\n", "parts.1.name",
     "'a' names two parts: give every part a name of its own"),
    ("parts:\n  - {name: '[x]', command: sim}\n", "parts.0.name", "String should match pattern"),
    ("parts:\n  - {name: arm, command: serve, args: [--connect, x], endpoint: tcp/127.0.0.1:1}\n",
     "parts.0.endpoint", "part 'arm' says where it meets the others twice"),
    ("parts:\n  - {name: arm, command: serve, args: [{robot: ur5e}]}\n", "parts.0.args.0",
     "Input should be a valid string"),
    ("parts: []\n", "parts", "List should have at least 1 item"),
    ("endpoint: tcp/127.0.0.1:1\n", "parts", "Field required"),
    ("parts:\n  - {name: sim, command: sim, cwd: /tmp}\n", "parts.0.cwd", "Extra inputs are not permitted"),
], ids=["command", "duplicate-name", "name-chunk", "endpoint-twice", "args-words", "no-parts", "parts-missing",
        "unknown-field"])
def test_a_bad_launch_file_is_one_line_naming_the_file_and_field(tmp_path, cli, text, field, message):
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    code, out, err = cli("launch", path)
    assert code == 2 and out == ""
    assert len(err.splitlines()) == 1 and err.startswith(f"vap-bt: {path}: field {field}: {message}"), err


def test_a_bad_launch_file_from_the_shell_starts_nothing_and_exits_2(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("parts:\n  - name: sim\n    command: sim\n    args: [trees/boil_water.yaml\n")
    done = subprocess.run(vap_bt("launch", str(path)), capture_output=True, text=True, timeout=60, cwd=ROOT)
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr.splitlines() == [
        f"vap-bt: {path}:5: not valid YAML: expected ',' or ']', but got '<stream end>'"]


def test_the_example_launch_file_loads_and_launch_waits_for_the_ready_lines_the_parts_print():
    spec = launch.load(str(EXAMPLE))
    assert [(p.name, p.command) for p in spec.parts] == [("sim", "sim"), ("arm", "serve"), ("base", "serve"),
                                                        ("executive", "run")]
    assert spec.parts[3].args[-4:] == ["--seed", "0", "--report", "out/boil_water.json"]  # YAML's 0, a word
    assert launch.READY["sim"].match(sim_host.READY + ": world ...")
    assert launch.READY["serve"].match(serve.READY + ": ur5e skills [...]")
    assert not launch.READY["serve"].match(sim_host.READY + ": world ...")


def test_census_reads_each_kind_of_token():
    assert census.classify("vap/part/sim/boil_water-1-ab") == census.Part("sim", "", "boil_water-1-ab",
                                                                            "vap/part/sim/boil_water-1-ab")
    assert census.classify("vap/ur5e/driver-host").kind == "drivers"
    assert census.classify("vap/base/alive/base-2-cd") == census.Part("skill server", "base", "base-2-cd",
                                                                        "vap/base/alive/base-2-cd")
    key = "vap/ur5e/alive/arm/goal/takeout/5f1c-7"
    assert census.classify(key) == census.Goal("ur5e", "arm", "takeout", "5f1c-7", key)
    assert census.classify("vap/ur5e/driver-client/c0123") is None  # a connection, not a part
    assert census.classify("elsewhere/a/b") is None
    parts = [census.classify("vap/part/sim/s"), census.classify("vap/ur5e/alive/arm")]
    text = census.table(parts, [census.classify(key)])
    assert text.splitlines() == [
        "PART          ROBOT/NAME  KEY", "sim           s           vap/part/sim/s",
        "skill server  ur5e/arm    vap/ur5e/alive/arm", "", "goals in flight:",
        "ROBOT  SERVER  ACTION   GOAL", "ur5e   arm     takeout  5f1c-7"]
    assert census.table([], []).splitlines() == ["no parts alive", "", "no goals in flight"]


@pytest.mark.timeout(60)
def test_parts_watch_says_what_comes_and_goes_until_ctrl_c():
    """``vap-bt parts --watch`` against a skill server in this process: the server and its goal
    come (+) and go (-); SIGINT ends it, exit 0."""
    from plugin_fixtures.fact_world import FactWorld
    from plugin_fixtures.zenoh_net import wait_until
    from vap_bt.skill import performed_by_world
    from vap_bt.transport.client import ZenohSkillClient
    from vap_bt.transport.server import SkillServer

    ep = endpoint(free_port())
    world = FactWorld(duration=1.0, steps=5)
    with session(listen=(ep,)) as s:
        server = SkillServer(s, "ur5e", {"grasp": performed_by_world("grasp", world, "ur5e")}, name="arm").start()
        watch = subprocess.Popen(vap_bt("parts", "--watch", "--connect", ep), stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, text=True, cwd=ROOT)
        lines: list[str] = []
        try:
            def said(pattern: str) -> bool:
                lines.append(watch.stdout.readline().rstrip("\n"))
                return bool(re.search(pattern, lines[-1]))

            wait_until(lambda: said(r"\] \+ skill server ur5e/arm  \(vap/ur5e/alive/arm\)$"), 30)
            client = ZenohSkillClient(s, {"grasp": "ur5e"})
            handle = client.send_goal("grasp", ("cup", "table"))
            wait_until(lambda: said(rf"\] \+ goal {handle.goal_id} grasp on ur5e/arm  "), 10)
            wait_until(lambda: said(rf"\] - goal {handle.goal_id} grasp on ur5e/arm  "), 10)
            client.close()
            server.close()
            wait_until(lambda: said(r"\] - skill server ur5e/arm  "), 10)
            watch.send_signal(signal.SIGINT)
            assert watch.wait(10) == 0, watch.stderr.read()
        finally:
            if watch.poll() is None:
                watch.kill()
                watch.wait(10)
    assert "Traceback" not in watch.stderr.read()
