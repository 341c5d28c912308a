"""Helpers for tests over real Zenoh sessions on 127.0.0.1: free ports, sessions, servers.

Every test gets its own port (found by binding a socket, since not every Zenoh endpoint accepts
port 0), so tests never see each other's traffic. Server subprocesses are started through
``python -m vap_bt serve`` with the facts world and always killed on exit.
"""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import time
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

import zenoh

from vap_bt.transport.config import TransportSettings, open_session

FIXTURES = Path(__file__).resolve().parent


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def endpoint(port: int) -> str:
    return f"tcp/127.0.0.1:{port}"


@contextmanager
def session(listen: tuple[str, ...] = (), connect: tuple[str, ...] = (),
            timeout: float = 3.0) -> Iterator[zenoh.Session]:
    s = open_session(TransportSettings(listen=listen, connect=connect, peer_timeout=timeout))
    try:
        yield s
    finally:
        s.close()


def serve_command(*args: str) -> tuple[list[str], dict[str, str]]:
    """argv and environment for ``python -m vap_bt serve`` able to load the facts world."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(FIXTURES), os.environ.get("PYTHONPATH", "")])}
    return [sys.executable, "-m", "vap_bt", "serve", *args], env


@contextmanager
def server_process(port: int, *extra: str, robot: str = "ur5e",
                   duration: float = 0.0) -> Iterator[subprocess.Popen]:
    """``vap-bt serve`` for ``robot`` over the facts world, listening on ``port``."""
    cmd, env = serve_command("--robot", robot, "--world", "fact_world:FactWorld",
                             "--world-arg", f"duration={duration}", "--listen", endpoint(port), *extra)
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    try:
        line = proc.stdout.readline()
        if "ready" not in line:
            proc.kill()
            raise RuntimeError(f"server did not start: {line!r} {proc.stderr.read()}")
        yield proc
    finally:
        if proc.poll() is None:
            proc.kill()
        proc.wait(timeout=10)
        proc.stdout.close()
        proc.stderr.close()


def wait_until(predicate, timeout: float, step: float = 0.005) -> float:
    """Seconds until ``predicate()`` held; raises AssertionError after ``timeout``."""
    t0 = time.monotonic()
    while not predicate():
        if time.monotonic() - t0 > timeout:
            raise AssertionError(f"condition not met within {timeout} s")
        time.sleep(step)
    return time.monotonic() - t0
