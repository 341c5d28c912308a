"""Where a rerun recording goes: a viewer we start, a loopback gRPC server, or a file.

The command line says ``--rerun spawn``, ``--rerun serve [PORT]`` or ``--rerun save FILE.rrd``;
:meth:`SinkSpec.parse` turns those words into a spec and :func:`open_recording` opens a
``rerun.RecordingStream`` on it. Three rules shape it:

* **loopback only.** Nothing here listens on another interface. ``serve`` hosts rerun's gRPC
  proxy through ``rerun.GrpcServerSink(bind_ip="127.0.0.1")`` (``rr.serve_grpc`` and
  ``rr.serve_web_viewer`` take no address and bind every interface). ``spawn`` starts the viewer
  executable itself with ``--bind 127.0.0.1`` — ``rr.spawn`` would leave the viewer's own server
  on its default, every interface — and streams to it with a gRPC client sink.
* **one clear message.** A viewer that cannot start (no display, no executable, a port in use)
  raises :class:`ViewerError`, a :class:`~vap_bt.errors.VapBtError` whose one line the CLI prints;
  never a traceback. Without a display the viewer is not even tried.
* **rerun does not fail loudly.** A busy port or a viewer that dies after starting only shows in
  rerun's own log, so the port is probed first and the started viewer is watched for a moment.
"""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Literal, Sequence

import rerun as rr

from vap_bt.errors import EXIT_TRANSPORT, InputError, VapBtError

LOOPBACK = "127.0.0.1"
#: rerun's customary port; ``serve`` uses it unless told otherwise
DEFAULT_SERVE_PORT = 9876
#: how long a freshly spawned viewer must stay alive before it counts as started
SPAWN_GRACE_S = 1.5
SPAWN_TIMEOUT_S = 15.0
Mode = Literal["spawn", "serve", "save"]
#: A file is read after the run, so its rows are gathered for seconds into few large chunks:
#: with rerun's default (a chunk every 200 ms), a pybullet episode's 5,000 rows made 2,500 chunks,
#: each with its own Arrow header — more bytes than the data, and a web viewer ingests a few
#: chunks per drawn frame. A stream to a viewer keeps the default, for latency. A run stopped
#: by Ctrl-C still closes the sink, which flushes; only a killed process loses its last seconds.
FILE_BATCHING = rr.ChunkBatcherConfig(flush_tick=5.0, flush_num_bytes=8 * 2**20)
USAGE = "--rerun spawn | --rerun serve [PORT] | --rerun save FILE.rrd"


class ViewerError(VapBtError):
    """The recording's sink could not be brought up (the viz counterpart of a transport error)."""

    exit_code = EXIT_TRANSPORT


@dataclass(frozen=True)
class SinkSpec:
    """Where a recording goes, as the command line said: ``mode`` (spawn, serve, save) with its port or
    file."""

    mode: Mode
    path: Path | None = None  # save
    port: int | None = None  # serve (default 9876); spawn (default: a free port)

    @classmethod
    def parse(cls, words: Sequence[str] | str) -> "SinkSpec":
        """``["spawn"]``, ``["serve"]``, ``["serve", "9877"]``, ``["save", "run.rrd"]``; a single
        string is split on whitespace (``"save run.rrd"``) or on a colon (``"save:run.rrd"``)."""
        if isinstance(words, str):
            words = words.split(":", 1) if ":" in words and " " not in words else words.split()
        words = [w for w in words if w]
        if not words:
            raise InputError("--rerun", f"missing mode; use {USAGE}")
        mode, rest = words[0], words[1:]
        if mode == "spawn" and not rest:
            return cls("spawn")
        if mode == "serve" and len(rest) <= 1:
            if not rest:
                return cls("serve", port=DEFAULT_SERVE_PORT)
            if not rest[0].isdigit() or not 0 < int(rest[0]) < 65536:
                raise InputError("--rerun serve", f"port must be a number in 1..65535, not {rest[0]!r}")
            return cls("serve", port=int(rest[0]))
        if mode == "save" and len(rest) == 1:
            path = Path(rest[0])
            if path.suffix != ".rrd":
                raise InputError("--rerun save", f"the file should end in .rrd, not {path.name!r}")
            return cls("save", path=path)
        raise InputError("--rerun", f"cannot read {' '.join(words)!r}; use {USAGE}")

    def __str__(self) -> str:
        return {"spawn": "spawn", "serve": f"serve {self.port}", "save": f"save {self.path}"}[self.mode]


@dataclass
class OpenRecording:
    """A recording stream on its sink, and how a person gets to see it."""

    stream: rr.RecordingStream
    spec: SinkSpec
    url: str | None = None  # serve/spawn: the gRPC proxy address a viewer connects to
    viewer: subprocess.Popen | None = None  # spawn: the viewer we started (left running on close)

    @property
    def hint(self) -> str:
        """The line telling a person where the recording goes and how to look at it."""
        if self.spec.mode == "save":
            return f"rerun: recording to {self.spec.path} (open it with `rerun {self.spec.path}`)"
        if self.spec.mode == "serve":
            return f"rerun: serving on {self.url} (view it with `rerun {self.url}`)"
        return f"rerun: streaming to the viewer started on {self.url}"

    def close(self) -> None:
        """Flush and close the sink: the file gets its footer; a served stream stops being served."""
        try:
            self.stream.flush(timeout_sec=10.0)
        finally:
            self.stream.disconnect()


def open_recording(spec: SinkSpec, application_id: str = "vap_bt", recording_name: str | None = None,
                   blueprint=None) -> OpenRecording:
    """A recording stream on ``spec``'s sink, with its name and default blueprint. A directory that does
    not exist is an :class:`InputError`; a port in use or a viewer that will not start, a
    :class:`ViewerError`."""
    stream = rr.RecordingStream(application_id, batcher_config=FILE_BATCHING if spec.mode == "save" else None)
    if recording_name:
        stream.send_recording_name(recording_name)
    if spec.mode == "save":
        path = spec.path.expanduser()
        if not path.parent.is_dir():
            raise InputError("--rerun save", f"no such directory {str(path.parent)!r}")
        stream.set_sinks(rr.FileSink(str(path)), default_blueprint=blueprint)
        return OpenRecording(stream, spec)
    if spec.mode == "serve":
        port = spec.port or DEFAULT_SERVE_PORT
        if not _port_free(port):
            raise ViewerError(f"cannot serve the rerun recording: {LOOPBACK}:{port} is in use "
                              f"(choose another port: --rerun serve PORT)")
        sink = rr.GrpcServerSink(bind_ip=LOOPBACK, port=port)
        stream.set_sinks(sink, default_blueprint=blueprint)
        return OpenRecording(stream, spec, url=str(sink.uri))
    viewer, url = spawn_viewer(spec.port)
    stream.set_sinks(rr.GrpcSink(url), default_blueprint=blueprint)
    return OpenRecording(stream, spec, url=url, viewer=viewer)


def spawn_viewer(port: int | None = None, grace_s: float = SPAWN_GRACE_S) -> tuple[subprocess.Popen, str]:
    """Start the native viewer listening on loopback; returns the process and its proxy URL.

    Raises :class:`ViewerError` without starting anything when there is no display, and with the
    viewer's own last error line when it exits during ``grace_s`` after it began listening.
    """
    if sys.platform.startswith("linux") and not any(
            os.environ.get(v) for v in ("DISPLAY", "WAYLAND_DISPLAY", "WAYLAND_SOCKET")):
        raise ViewerError("cannot spawn a rerun viewer: there is no display (DISPLAY and WAYLAND_DISPLAY "
                          "are unset); use --rerun serve and connect a viewer from a desktop, "
                          "or --rerun save FILE.rrd")
    exe = viewer_executable()
    port = port or _free_port()
    if not _port_free(port):
        raise ViewerError(f"cannot spawn a rerun viewer: {LOOPBACK}:{port} is in use")
    log = tempfile.NamedTemporaryFile("w+", prefix="vap_bt-rerun-viewer-", suffix=".log", delete=False)
    proc = subprocess.Popen([exe, "--bind", LOOPBACK, "--port", str(port), "--expect-data-soon"],
                            stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                            start_new_session=True)  # the viewer outlives a Ctrl-C of the run
    deadline = time.monotonic() + SPAWN_TIMEOUT_S
    listening_since: float | None = None
    while True:
        if proc.poll() is not None:
            reason = _last_error(log.name)
            log.close()
            os.unlink(log.name)
            raise ViewerError(f"cannot spawn a rerun viewer: it exited with code {proc.returncode}: {reason}")
        if listening_since is None and _listening(port):
            listening_since = time.monotonic()
        if listening_since is not None and time.monotonic() - listening_since >= grace_s:
            return proc, f"rerun+http://{LOOPBACK}:{port}/proxy"
        if time.monotonic() > deadline:
            proc.terminate()
            raise ViewerError(f"cannot spawn a rerun viewer: it did not listen on {LOOPBACK}:{port} "
                              f"within {SPAWN_TIMEOUT_S:.0f} s (log: {log.name})")
        time.sleep(0.05)


def viewer_executable() -> str:
    """The ``rerun`` executable of this environment (next to the interpreter), else on PATH."""
    import shutil

    here = Path(sys.executable).parent / "rerun"
    if here.exists():
        return str(here)
    found = shutil.which("rerun")
    if found is None:
        raise ViewerError("cannot spawn a rerun viewer: no `rerun` executable (install rerun-sdk)")
    return found


def _last_error(log_path: str) -> str:
    """The viewer's most telling line: its ``Error:`` line, else the last non-empty line."""
    import re

    text = re.sub(r"\x1b\[[0-9;]*m", "", Path(log_path).read_text(errors="replace"))
    lines = [l.strip() for l in text.splitlines() if l.strip()]
    errors = [l for l in lines if l.startswith("Error") or " ERROR " in l or "panicked" in l]
    return (errors or lines or ["no output"])[-1]


def _port_free(port: int) -> bool:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        try:
            s.bind((LOOPBACK, port))
        except OSError:
            return False
    return True


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind((LOOPBACK, 0))
        return s.getsockname()[1]


def _listening(port: int) -> bool:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.settimeout(0.2)
        return s.connect_ex((LOOPBACK, port)) == 0
