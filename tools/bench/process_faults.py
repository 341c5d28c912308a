"""Process faults with real processes and real Zenoh sessions: what the executive does when a part fails.

    .venv/bin/python tools/bench/process_faults.py [--runs 3] [--faults kill,hang,restart,camera,vlm]

Each run is one boil_water episode (seed 0, no injection) as four processes on a free loopback
port — ``vap-bt sim``, ``vap-bt serve --robot ur5e|base --world remote``, ``vap-bt run
--connect`` — each in a process group of its own, and one fault injected at a fixed point of
the episode (a line the sim or the executive prints):

==========  ===========================================================================================
kill        the base's skill server SIGKILLed 0.1 s into the first ``find`` (the arm's, mid-takeout,
            is tests/test_processes.py's)
hang        the arm's skill server SIGSTOPped 0.3 s into ``open(cabinet)``: its socket stays open,
            only the link lease tells
restart     the arm's server SIGKILLed 0.3 s into ``open(cabinet)``, and a new ``vap-bt serve
            --robot ur5e --world remote`` started at once
camera      the arm's server is ``vap-bt serve`` with its camera's capture handler patched (in that
            process only, :data:`SILENT_CAMERA`) to never answer once a flag file exists; the flag
            is made when the sim announces ``open(cabinet)``: the frame of its effect check never comes
vlm         ``--vlm openai --vlm-url`` at a local OpenAI-compatible server (:class:`FlakyVLM`, a
            thread of this process) that answers every question with its first option after
            0.1 s (slow), and closes its socket when the executive's first action has succeeded
            (down): the checks of its effects find nobody to ask
==========  ===========================================================================================

Outcome of a run, from the executive's exit code, report and stderr:

* **replan** — the episode went on past the fault and replanned (a restarted server picked up);
* **retry within budget** — it went on without a replan (a request retried and answered);
* **clean abort** — exit 1, a report whose reason is ``transport down: ...``, no traceback;
* **hang** — the executive had not ended :data:`HANG_S` s after the fault (then it is killed);
* **crash** — a traceback, no report, or an exit code README does not document for this.

"orphans" counts processes of the run's process groups (and any child of them) still alive after
the parts were stopped (SIGCONT, SIGTERM, 30 s, SIGKILL) — each is killed then. The table is
markdown on stdout; progress on stderr. tests/test_process_faults.py asserts on the same runs.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Iterator

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

TASK = str(ROOT / "trees" / "boil_water.yaml")
SEED = "0"  # boil_water without injection succeeds on this seed as four processes
FAULTS = ("kill", "hang", "restart", "camera", "vlm")
OUTCOMES = ("replan", "retry within budget", "clean abort", "hang", "crash")
#: seconds after the fault by which the executive must have ended (the rejoin wait and the
#: camera's timeout are 30 s each; the episode after a restart runs up to four minutes more)
HANG_S = 400.0
#: the arm's server whose capture handler never answers once the flag file (argv[1]) exists
SILENT_CAMERA = """
import os, sys, time
from vap_bt.transport import server
flag, answer = sys.argv[1], server.SkillServer._capture
def _capture(self, payload):
    while os.path.exists(flag):  # the frame never comes: no reply, no error
        time.sleep(0.5)
    return answer(self, payload)
server.SkillServer._capture = _capture
from vap_bt.app.cli import main
sys.exit(main(sys.argv[2:]))
"""


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@dataclass
class Part:
    """One process of the episode, its output in files (a pipe nobody reads would stall it)."""

    name: str
    proc: subprocess.Popen
    out: Path
    err: Path

    def stdout(self) -> str:
        return self.out.read_text()

    def stderr(self) -> str:
        return self.err.read_text()

    def wait_for(self, pattern: str, timeout: float, stream: str = "stdout") -> re.Match:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            found = re.search(pattern, self.stdout() if stream == "stdout" else self.stderr())
            if found:
                return found
            if self.proc.poll() is not None:
                break
            time.sleep(0.01)
        raise RuntimeError(f"{self.name}: no {pattern!r} on {stream} (exit {self.proc.poll()}):\n"
                           f"{self.stdout()[-2000:]}\n{self.stderr()[-4000:]}")


def vap_bt(*args: str) -> list[str]:
    return [sys.executable, "-m", "vap_bt", *args]


def start(tmp: Path, name: str, argv: list[str]) -> Part:
    """``argv`` in its own process group, from the checkout's root (so ``-m vap_bt`` and ``-c``
    import this checkout's vap_bt), its output in ``tmp/NAME.out`` and ``.err``."""
    out, err = tmp / f"{name}.out", tmp / f"{name}.err"
    with out.open("w") as o, err.open("w") as e:
        proc = subprocess.Popen(argv, stdout=o, stderr=e, stdin=subprocess.DEVNULL, cwd=ROOT,
                                start_new_session=True)  # its own process group: killpg reaches its children
    return Part(name, proc, out, err)


def alive_in(pgids: set[int]) -> list[int]:
    """Pids of live (not zombie) processes in any of the process groups ``pgids``, from /proc."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            stat = Path(f"/proc/{entry}/stat").read_text()
        except OSError:
            continue
        fields = stat.rsplit(")", 1)[1].split()  # after "pid (comm)": state ppid pgrp ...
        if fields[0] != "Z" and int(fields[2]) in pgids:
            found.append(int(entry))
    return found


def stop_all(parts: list[Part]) -> int:
    """Stop every part (SIGCONT for a stopped one, SIGTERM, 30 s, then SIGKILL); the number of
    processes of their groups still alive after that, killed then."""
    pgids = {p.proc.pid for p in parts}
    for p in parts:
        if p.proc.poll() is None:
            for sig in (signal.SIGCONT, signal.SIGTERM):
                try:
                    os.killpg(p.proc.pid, sig)
                except ProcessLookupError:
                    pass
    deadline = time.monotonic() + 30
    for p in parts:
        try:
            p.proc.wait(max(0.1, deadline - time.monotonic()))
        except subprocess.TimeoutExpired:
            os.killpg(p.proc.pid, signal.SIGKILL)
            p.proc.wait(10)
    end = time.monotonic() + 5
    while alive_in(pgids) and time.monotonic() < end:
        time.sleep(0.05)
    left = alive_in(pgids)
    for pid in left:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    return len(left)


class FlakyVLM:
    """An OpenAI-compatible chat-completions server on 127.0.0.1: every question answered with
    its first allowed option (``guided_choice``; "yes" otherwise) after ``latency`` s, until
    :meth:`down` closes its listening socket (connections refused from then on)."""

    def __init__(self, latency: float = 0.1) -> None:
        self.latency, self.answered = latency, 0
        outer = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args) -> None:
                pass

            def do_GET(self) -> None:  # the run's one probe before the episode
                self._send(404, {"error": "not here"})

            def do_POST(self) -> None:
                body = json.loads(self.rfile.read(int(self.headers.get("content-length", 0))) or b"{}")
                time.sleep(outer.latency)
                answer = (body.get("guided_choice") or ["yes"])[0]
                outer.answered += 1
                self._send(200, {"id": "x", "object": "chat.completion", "model": body.get("model"),
                                 "choices": [{"index": 0, "finish_reason": "stop",
                                              "message": {"role": "assistant", "content": answer}}]})

            def _send(self, code: int, doc: dict) -> None:
                data = json.dumps(doc).encode()
                self.send_response(code)
                self.send_header("content-type", "application/json")
                self.send_header("content-length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)

        self.httpd = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.httpd.daemon_threads = True
        self.url = f"http://127.0.0.1:{self.httpd.server_address[1]}/v1"
        self._thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)
        self._thread.start()

    def down(self) -> None:
        if self._thread.is_alive():
            self.httpd.shutdown()
            self.httpd.server_close()


@dataclass
class Result:
    fault: str
    outcome: str
    exit_code: int | None
    end_s: float | None  # fault -> the executive's exit
    orphans: int
    reason: str
    report: dict = field(default_factory=dict)
    stderr: str = ""
    after_fault: str = ""  # the executive's stderr from the fault on

    def line(self) -> str:
        end = "-" if self.end_s is None else f"{self.end_s:.1f} s"
        return f"{self.fault}: {self.outcome}, exit {self.exit_code}, ended {end} after the fault; {self.reason}"


def classify(code: int | None, report: dict, stderr: str, after_fault: str) -> str:
    if code is None:
        return "hang"
    if "Traceback" in stderr or not report or code not in (0, 1):
        return "crash"
    if str(report.get("reason", "")).startswith("transport down"):
        return "clean abort" if code == 1 else "crash"
    return "replan" if "replan #" in after_fault else "retry within budget"


@dataclass
class Episode:
    """The parts of one episode: by name, every one started (stopped on exit), what was left."""

    endpoint: str
    running: dict[str, Part] = field(default_factory=dict)
    every: list[Part] = field(default_factory=list)
    orphans: int = 0

    def start(self, tmp: Path, name: str, argv: list[str]) -> Part:
        part = self.running[name] = start(tmp, name, argv)
        self.every.append(part)
        return part


@contextmanager
def _episode(tmp: Path, arm_argv: list[str] | None = None) -> Iterator[Episode]:
    """The sim and both skill servers up; every part started stopped on exit."""
    e = Episode(f"tcp/127.0.0.1:{free_port()}")
    try:
        e.start(tmp, "sim", vap_bt("sim", TASK, "--seed", SEED, "--no-injection", "--listen", e.endpoint))
        e.running["sim"].wait_for(r"vap-bt sim: ready", 180)
        for robot, name in (("ur5e", "arm"), ("base", "base")):
            argv = vap_bt("serve", "--robot", robot, "--world", "remote", "--connect", e.endpoint)
            e.start(tmp, name, argv if name != "arm" or arm_argv is None else [*arm_argv, *argv[3:]])
        for name in ("arm", "base"):
            e.running[name].wait_for(r"vap-bt serve: ready", 120)
        yield e
    finally:
        e.orphans = stop_all(e.every)


def run_fault(fault: str, tmp: Path, *run_args: str) -> Result:
    """One episode with ``fault`` injected (see the module docstring); ``run_args`` go to
    ``vap-bt run`` (the tests shorten its waits: ``--rejoin-timeout``, ``--camera-timeout``)."""
    tmp.mkdir(parents=True, exist_ok=True)
    flag = tmp / "camera-silent"
    vlm = FlakyVLM() if fault == "vlm" else None
    arm = [sys.executable, "-c", SILENT_CAMERA, str(flag)] if fault == "camera" else None
    code = end_s = None
    report: dict = {}
    stderr = after = ""
    try:
        with _episode(tmp, arm) as e:
            extra = ["--vlm", "openai", "--vlm-url", vlm.url, "--vlm-model", "flaky"] if vlm else []
            run = e.start(tmp, "run", vap_bt("run", TASK, "--connect", e.endpoint, "--seed", SEED, "--no-injection",
                                             "--report", str(tmp / "report.json"), *extra, *run_args))
            sim, running = e.running["sim"], e.running
            if fault == "kill":
                sim.wait_for(r"\] begin find\(", 300, stream="stderr")
                time.sleep(0.1)
                os.killpg(running["base"].proc.pid, signal.SIGKILL)
            elif fault in ("hang", "restart"):
                sim.wait_for(r"\] begin open\(", 300, stream="stderr")
                time.sleep(0.3)
                os.killpg(running["arm"].proc.pid, signal.SIGSTOP if fault == "hang" else signal.SIGKILL)
                if fault == "restart":
                    e.start(tmp, "arm2", vap_bt("serve", "--robot", "ur5e", "--world", "remote", "--connect", e.endpoint))
            elif fault == "camera":
                sim.wait_for(r"\] begin open\(", 300, stream="stderr")
                flag.touch()
            elif fault == "vlm":
                run.wait_for(r"\n  a0: succeeded", 600, stream="stderr")
                vlm.down()
            at = time.monotonic()
            mark = len(run.stderr())
            try:
                code = run.proc.wait(HANG_S)
                end_s = time.monotonic() - at
            except subprocess.TimeoutExpired:
                code = None
            stderr = run.stderr()
            after = stderr[mark:]
            if (tmp / "report.json").exists():
                report = json.loads((tmp / "report.json").read_text())
            flag.unlink(missing_ok=True)  # the stuck capture handler returns: the arm can stop on SIGTERM
    finally:
        if vlm is not None:
            vlm.down()
    reason = str(report.get("reason", "no report" if code is not None else "killed: no end"))
    return Result(fault, classify(code, report, stderr, after), code, end_s, e.orphans, reason, report, stderr, after)


def table(results: list[Result]) -> str:
    lines = ["| fault | runs | replan | retry within budget | clean abort | hang | crash | median time to end | orphans |",
             "|---|---|---|---|---|---|---|---|---|"]
    for fault in dict.fromkeys(r.fault for r in results):
        rs = [r for r in results if r.fault == fault]
        counts = [sum(r.outcome == o for r in rs) for o in OUTCOMES]
        ends = [r.end_s for r in rs if r.end_s is not None]
        median = f"{statistics.median(ends):.1f} s" if ends else "-"
        lines.append(f"| {fault} | {len(rs)} | " + " | ".join(map(str, counts))
                     + f" | {median} | {sum(r.orphans for r in rs)} |")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--runs", type=int, default=3, help="runs per fault (default 3)")
    p.add_argument("--faults", default=",".join(FAULTS), help=f"comma-separated, of {', '.join(FAULTS)}")
    p.add_argument("--keep", help="keep each run's logs and report under this folder")
    args = p.parse_args(argv)
    faults = [f for f in args.faults.split(",") if f]
    bad = [f for f in faults if f not in FAULTS]
    if bad:
        p.error(f"unknown fault(s) {', '.join(bad)}")
    from tools.progress import Progress

    progress = Progress(total=len(faults) * args.runs, unit="runs")
    results = []
    with tempfile.TemporaryDirectory(prefix="process_faults-") as scratch:
        base = Path(args.keep) if args.keep else Path(scratch)
        for fault in faults:
            for i in range(args.runs):
                r = run_fault(fault, base / f"{fault}-{i}")
                results.append(r)
                print(r.line(), file=sys.stderr, flush=True)
                progress.step()
    print(table(results))
    return 0


if __name__ == "__main__":
    sys.exit(main())
