"""The ``vap-bt launch FILE.yaml`` command: the parts of a connected set-up, started and stopped as one.

A connected episode is four processes — ``vap-bt sim``, a ``vap-bt serve`` per robot, ``vap-bt
run --connect`` — that must start in order (the servers connect to the sim's router; the
executive looks for the servers) and should stop together. A launch file names them; ``launch``
starts each as a child process in a process group of its own, in stages: every ``sim`` part, then
every ``serve`` part, each stage once the one before has said it is ready, and the ``run`` part,
the executive, last (several ``run`` parts run one after another, in file order, against the same
parts: episodes on one world). Ready is the line ``vap-bt sim: ready`` or ``vap-bt serve: ready``
the commands print on stdout once everything they offer is declared: what a person watching sees
too, and no Zenoh session of launch's own to configure. Every line a part prints is passed on as
it comes, ``[name] line``, its stdout on stdout and its stderr on stderr; launch's own lines are
``[launch] …`` on stderr.

It ends when the executive does, with the executive's exit code (of several, the first that is
not 0), after stopping the others: the skill servers before the sim (a server whose sim goes
first exits 4), each group with SIGTERM and, after the file's ``stop_timeout``, SIGKILL; whatever
a part left in its group goes too, so nothing is left running. SIGINT or SIGTERM to launch
(Ctrl-C) goes to the executive as SIGINT, so that it writes its report so far and exits 130, and
then the rest are stopped the same way; a second one kills every group at once. A part that exits
or stays silent before it is ready ends the launch: one line names the part, its exit code and
its last line, everything started is stopped, and the exit code is 4 (the set-up could not be
brought up). A launch file without a ``run`` part hosts its parts until Ctrl-C (exit 0) or until
one of them exits (exit 4): the world and a robot's servers on one machine, the executive on
another.

Each part is told where to meet the others: a ``sim`` part ``--listen ENDPOINT``, the others
``--connect ENDPOINT`` — the part's own ``endpoint``, else ``vap-bt launch --endpoint``, else the
file's, else the sim's default — unless its arguments already say where (``--listen``,
``--connect``, ``--zenoh-config``). The parts run ``python -m vap_bt`` with this Python, in
the directory launch was started in, so relative paths in their arguments are relative to it.
Everything a launch is — schema, processes, output, stopping — is here, and none of the parts'
code is imported: launch drives them by their command lines only.
"""

from __future__ import annotations

import argparse
import os
import re
import shlex
import signal
import subprocess
import sys
import threading
import time
from dataclasses import dataclass, field
from typing import IO, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator

from vap_bt.app.arguments import add_settings
from vap_bt.errors import EXIT_INTERRUPTED, EXIT_OK, InputError, TransportError
from vap_bt.settings import SIM_ENDPOINT, Commands
from vap_bt.yaml_file import read_model

#: the start-up stages, in order; each part's command is one of them
STAGES = ("sim", "serve", "run")
#: the line that says a part is up (the ``READY`` of sim_host.py and serve.py), by command
READY = {"sim": re.compile(r"^vap-bt sim: ready\b"), "serve": re.compile(r"^vap-bt serve: ready\b")}
#: options by which a part's arguments say where it meets the others
WHERE = ("--listen", "--connect", "--zenoh-config")
#: how often the supervisor looks at its children (a signal handler only sets a flag)
POLL_S = 0.05

SCHEMA = """\
launch file (YAML):
  endpoint: ENDPOINT        where the parts meet: the sim's router (default tcp/127.0.0.1:7447;
                            --endpoint overrides it)
  ready_timeout: SECONDS    how long a sim or serve part may take to say ready (default 120)
  stop_timeout: SECONDS     SIGTERM (SIGINT for the executive) to SIGKILL, per stage (default 15)
  parts:                    in any order; started sim -> serve -> run, each stage once the
                            previous one is ready
    - name: NAME            the prefix of its lines, [NAME]: letters, digits, '_', '-', '.'
      command: sim|serve|run   the vap-bt command; run parts (the executive) run one after
                            another, in file order, each once the previous one has exited
      args: [ARG, ...]      its arguments, a list or one string split as a shell would
      endpoint: ENDPOINT    optional: where this part listens (sim) or connects (serve, run)

example (examples/launch/boil_water.yaml):
  parts:
    - {name: sim, command: sim, args: [trees/boil_water.yaml, --no-injection]}
    - {name: arm, command: serve, args: [--robot, ur5e, --world, remote]}
    - {name: base, command: serve, args: [--robot, base, --world, remote]}
    - {name: executive, command: run, args: [trees/boil_water.yaml, --no-injection, --seed, 0,
                                             --report, out/boil_water.json]}

exit code: the executive's (0 success, 1 goal not reached, ... 130 interrupted; with several run
parts the first that is not 0); 4 when a part exits or stays silent before it is ready; without a
run part, 0 when stopped by Ctrl-C or SIGTERM and 4 when a part exits on its own."""


class PartSpec(BaseModel):
    """One process of the set-up: a vap-bt command and its arguments."""

    model_config = ConfigDict(extra="forbid")
    name: str = Field(pattern=r"^[A-Za-z0-9_.\-]+$")
    command: Literal["sim", "serve", "run"]
    args: list[str] = []
    endpoint: str | None = None

    @field_validator("args", mode="before")
    @classmethod
    def _words(cls, value: object) -> object:
        """A string is split as a shell would; numbers (``--seed 0``) are words too."""
        if isinstance(value, str):
            return shlex.split(value)
        if isinstance(value, list):
            return [str(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else v for v in value]
        return value

    def says_where(self) -> bool:
        """Whether the part's own arguments already say where it meets the others (:data:`WHERE`); launch
        then adds no ``--listen`` or ``--connect``."""
        return any(a == opt or a.startswith(opt + "=") for a in self.args for opt in WHERE)


class LaunchFile(BaseModel):
    """A launch file as written (:data:`SCHEMA` explains each field): where the parts meet, how long they
    may take to come up and to stop, and the parts."""

    model_config = ConfigDict(extra="forbid")
    endpoint: str | None = None
    ready_timeout: float = Field(120.0, gt=0)
    stop_timeout: float = Field(15.0, gt=0)
    parts: list[PartSpec] = Field(min_length=1)


def load(path: str) -> LaunchFile:
    """The launch file at ``path``; anything wrong with it is one InputError naming the field."""
    spec = read_model(path, LaunchFile, "launch file", "endpoint:, parts: [{name:, command:, args:}, ...]")
    names: set[str] = set()
    for i, part in enumerate(spec.parts):
        where = f"{path}: field parts.{i}"
        if part.name in names or part.name == "launch":
            taken = "is launch's own prefix" if part.name == "launch" else "names two parts"
            raise InputError(f"{where}.name", f"{part.name!r} {taken}: give every part a name of its own")
        names.add(part.name)
        if part.endpoint and part.says_where():
            raise InputError(f"{where}.endpoint", f"part {part.name!r} says where it meets the others twice: "
                                                  f"endpoint: and {'/'.join(WHERE)} in its args; keep one")
    return spec


@dataclass
class _Child:
    """A started part: its process, whether it said ready, its last line."""

    spec: PartSpec
    argv: list[str]
    proc: subprocess.Popen
    ready: threading.Event = field(default_factory=threading.Event)
    last_line: str = ""
    readers: list[threading.Thread] = field(default_factory=list)
    told_exit: bool = False

    @property
    def name(self) -> str:
        return self.spec.name

    @property
    def shown(self) -> str:
        """Its command line as a person would type it."""
        return shlex.join(["vap-bt", *self.argv[3:]])

    def signal_group(self, sig: int) -> None:
        try:
            os.killpg(self.proc.pid, sig)  # its own group (start_new_session): whatever it started too
        except ProcessLookupError:
            pass

    def group_alive(self) -> bool:
        try:
            os.killpg(self.proc.pid, 0)
        except ProcessLookupError:
            return False
        return True


def exit_text(code: int) -> str:
    """A child's return code in words: the signal that killed it (a negative code), or its exit code."""
    return f"was killed by {signal.Signals(-code).name}" if code < 0 else f"exited with code {code}"


class Launcher:
    """Starts, watches and stops the parts of one launch file."""

    def __init__(self, spec: LaunchFile, endpoint: str | None = None) -> None:
        self.spec = spec
        self.endpoint = endpoint or spec.endpoint or SIM_ENDPOINT
        self.out, self.err = sys.stdout, sys.stderr
        self.children: list[_Child] = []
        self._write_lock = threading.Lock()
        self._signals = 0  # SIGINT/SIGTERM received: 1 stop in order, 2 or more kill at once

    # -- the run ---------------------------------------------------------------------------------

    def run(self) -> int:
        """Start the parts stage by stage, pass their lines on, and stop them all once the executive ends,
        a part fails to come up, or a signal comes; blocks until then and returns the launch's exit code."""
        previous = self._catch_signals()
        try:
            return self._run()
        finally:
            self._stop_all()
            self._restore_signals(previous)

    def _run(self) -> int:
        for stage in STAGES[:2]:
            parts = [p for p in self.spec.parts if p.command == stage]
            for part in parts:
                self._start(part)
            if not self._wait_ready([c for c in self.children if c.spec.command == stage]):
                self.say("interrupted while the parts were starting: stopping them")
                return EXIT_INTERRUPTED
        runs = [p for p in self.spec.parts if p.command == "run"]
        if not runs:
            return self._host()
        code = EXIT_OK
        for part in runs:  # one after another: they share one world
            if self._signals:
                return code or EXIT_INTERRUPTED
            ended = self._supervise(self._start(part))
            code = code or ended
        return code

    def _wait_ready(self, stage: list[_Child]) -> bool:
        """Until every part of ``stage`` is ready (True) or a signal came (False); a part that
        exits, or stays silent past ``ready_timeout``, is a TransportError naming it."""
        deadline = time.monotonic() + self.spec.ready_timeout
        while not all(c.ready.is_set() for c in stage):
            if self._signals:
                return False
            for child in self.children:
                if child.proc.poll() is not None:
                    self._drain(child)
                    who = "it was" if child in stage else "the others were"
                    raise TransportError(self._failure(child, f"{exit_text(child.proc.returncode)} before {who} ready"))
            if time.monotonic() > deadline:
                late = next(c for c in stage if not c.ready.is_set())
                raise TransportError(self._failure(late, f"did not say ready within {self.spec.ready_timeout:g} s"))
            time.sleep(POLL_S)
        return True

    def _failure(self, child: _Child, what: str) -> str:
        last = child.last_line or "(it printed nothing)"
        return f"launch: part {child.name} ({child.shown}) {what}; its last line: {last}"

    def _supervise(self, executive: _Child) -> int:
        """Until the executive exits: its exit code (128 + N if killed by signal N). A signal is
        passed on to it as SIGINT; the other parts' exits are said, not acted on."""
        while executive.proc.poll() is None:
            if self._signals:
                self.say("interrupted: stopping every part, the executive first (it writes its report so far)")
                self._reap([executive], signal.SIGINT)
                break
            self._tell_exits()
            time.sleep(POLL_S)
        self._drain(executive)
        code = executive.proc.returncode
        if not executive.told_exit:
            executive.told_exit = True
            self.say(f"{executive.name} {exit_text(code)}")
        return code if code >= 0 else 128 - code

    def _host(self) -> int:
        """No executive: until a signal (exit 0) or until a part exits (exit 4)."""
        self.say("every part is ready; Ctrl-C stops them")
        while not self._signals:
            for child in self.children:
                if child.proc.poll() is not None:
                    self._drain(child)
                    raise TransportError(self._failure(child, exit_text(child.proc.returncode)))
            time.sleep(POLL_S)
        return EXIT_OK

    def _tell_exits(self) -> None:
        for child in self.children:
            if not child.told_exit and child.proc.poll() is not None:
                child.told_exit = True
                self.say(f"{child.name} {exit_text(child.proc.returncode)}")

    # -- starting --------------------------------------------------------------------------------

    def _start(self, part: PartSpec) -> _Child:
        argv = [sys.executable, "-m", "vap_bt", part.command, *part.args]
        if not part.says_where():
            argv += ["--listen" if part.command == "sim" else "--connect", part.endpoint or self.endpoint]
        proc = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True, errors="replace", bufsize=1, start_new_session=True,
                                env={**os.environ, "PYTHONUNBUFFERED": "1"})  # lines as they are printed
        child = _Child(part, argv, proc)
        self.children.append(child)
        self.say(f"{part.name}: {child.shown} (pid {proc.pid})")
        for pipe, stream in ((proc.stdout, self.out), (proc.stderr, self.err)):
            reader = threading.Thread(target=self._relay, args=(child, pipe, stream), daemon=True,
                                      name=f"launch-{part.name}")
            reader.start()
            child.readers.append(reader)
        return child

    def _relay(self, child: _Child, pipe: IO[str], stream: IO[str]) -> None:
        """Pass ``child``'s lines on, prefixed, and notice its ready line."""
        ready = READY.get(child.spec.command) if stream is self.out else None
        for line in pipe:
            line = line.rstrip("\n")
            if line.strip():
                child.last_line = line
            self._write(stream, f"[{child.name}] {line}")
            if ready is not None and ready.match(line):
                child.ready.set()
        pipe.close()

    def _drain(self, child: _Child, timeout: float = 2.0) -> None:
        """Wait until everything ``child`` printed has been passed on (its pipes closed)."""
        deadline = time.monotonic() + timeout
        for reader in child.readers:
            reader.join(max(0.0, deadline - time.monotonic()))

    # -- stopping --------------------------------------------------------------------------------

    def _stop_all(self) -> None:
        """Every part stopped, executive first and the sim last; nothing left in their groups."""
        for stage in reversed(STAGES):
            parts = [c for c in self.children if c.spec.command == stage]
            self._reap(parts, signal.SIGINT if stage == "run" else signal.SIGTERM)
        for child in self.children:
            self._clear_group(child)
            self._drain(child, 1.0)

    def _reap(self, parts: list[_Child], sig: int) -> None:
        """Send ``sig`` to the running ``parts``, wait up to ``stop_timeout``, then SIGKILL."""
        running = [c for c in parts if c.proc.poll() is None]
        if not running:
            return
        self.say(f"stopping {', '.join(c.name for c in running)} ({signal.Signals(sig).name})")
        for child in running:
            child.signal_group(sig)
        deadline = time.monotonic() + self.spec.stop_timeout
        while any(c.proc.poll() is None for c in running) and time.monotonic() < deadline and self._signals < 2:
            time.sleep(POLL_S)
        for child in running:
            if child.proc.poll() is None:
                self.say(f"{child.name} still runs: SIGKILL")
                child.signal_group(signal.SIGKILL)
                child.proc.wait()
            if not child.told_exit:
                child.told_exit = True
                self._drain(child, 1.0)
                self.say(f"{child.name} {exit_text(child.proc.returncode)}")

    def _clear_group(self, child: _Child) -> None:
        """What ``child`` started and left behind (its group outlives it): SIGTERM, then SIGKILL."""
        if not child.group_alive():
            return
        child.signal_group(signal.SIGTERM)
        deadline = time.monotonic() + 2.0
        while child.group_alive() and time.monotonic() < deadline:
            time.sleep(POLL_S)
        if child.group_alive():
            child.signal_group(signal.SIGKILL)

    # -- output and signals ----------------------------------------------------------------------

    def say(self, text: str) -> None:
        """One ``[launch] …`` line on stderr."""
        self._write(self.err, f"[launch] {text}")

    def _write(self, stream: IO[str], line: str) -> None:
        with self._write_lock:  # one line at a time, whoever's it is
            try:
                stream.write(line + "\n")
                stream.flush()
            except (BrokenPipeError, ValueError):  # nobody reads any more: the parts still get stopped
                pass

    def _catch_signals(self) -> dict:
        if threading.current_thread() is not threading.main_thread():
            return {}
        previous = {sig: signal.getsignal(sig) for sig in (signal.SIGINT, signal.SIGTERM)}
        for sig in previous:
            signal.signal(sig, self._on_signal)
        return previous

    def _on_signal(self, signum: int, frame: object) -> None:
        self._signals += 1  # only a flag: the supervisor acts on it between its polls

    @staticmethod
    def _restore_signals(previous: dict) -> None:
        for sig, handler in previous.items():
            signal.signal(sig, handler)


def add_launch_arguments(p: argparse.ArgumentParser) -> None:
    """Declare ``vap-bt launch``'s options on ``p`` (from :mod:`vap_bt.settings`)."""
    add_settings(p, "launch", Commands)


def run_launch(args: argparse.Namespace) -> int:
    """``vap-bt launch``: load the launch file and run its parts to the end (blocks); returns the exit code
    the module docstring describes."""
    return Launcher(load(args.file), endpoint=args.endpoint).run()
