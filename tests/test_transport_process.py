"""A skill server in its own process dies or hangs mid-goal: the client must notice, fast.

SIGKILL closes the TCP link, so the server's liveliness token vanishes at once (goal ABORTED
within 0.5 s). SIGSTOP keeps the socket open; only the link lease (2 s by default) tells, so the
goal must fail within 3 s. The server is ``python -m vap_bt serve`` over the facts
world, exactly as ``vap-bt serve`` runs.
"""

from __future__ import annotations

import os
import signal
import subprocess
import time

import pytest

from plugin_fixtures.zenoh_net import (endpoint, free_port, serve_command, server_process, session,
                                       wait_until)
from vap_bt.plugins import discover_skills, routes
from vap_bt.skill import GoalState
from vap_bt.transport.client import ZenohSkillClient

pytestmark = pytest.mark.timeout(60)


def _goal_in_flight(port: int):
    s = session(connect=(endpoint(port),))
    cli_session = s.__enter__()
    client = ZenohSkillClient(cli_session, routes(discover_skills()))
    wait_until(lambda: client._alive["ur5e"], 3)
    handle = client.send_goal("grasp", ("cup", "table"))
    assert handle.wait_answered(3) is GoalState.ACTIVE
    return s, client, handle


@pytest.mark.slow
@pytest.mark.parametrize("sig, limit", [(signal.SIGKILL, 0.5), (signal.SIGSTOP, 3.0)])
def test_dead_or_hung_server_fails_its_goal(sig, limit):
    port = free_port()
    with server_process(port, duration=30) as proc:
        ctx, client, handle = _goal_in_flight(port)
        try:
            t0 = time.monotonic()
            os.kill(proc.pid, sig)
            handle.wait(limit + 1)
            elapsed = time.monotonic() - t0
            assert handle.state() is GoalState.ABORTED
            assert handle.result().message == "server vanished"
            assert elapsed < limit, f"noticed after {elapsed:.2f} s"
        finally:
            proc.kill()  # a stopped peer would stall the session's close
            client.close()
            ctx.__exit__(None, None, None)


@pytest.mark.slow
def test_serve_stops_cleanly_on_sigterm_and_refuses_bad_input():
    port = free_port()
    with server_process(port) as proc:
        proc.send_signal(signal.SIGTERM)
        assert proc.wait(10) == 0
    cmd, env = serve_command("--robot", "r2d2", "--world", "nowhere:World")
    bad = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=60)
    assert bad.returncode == 2
    assert bad.stderr.strip().splitlines() == [
        "vap-bt: --robot: no skill plugin is bound to robot 'r2d2' (robots with skills: base, ur5e)"
    ]
    port = free_port()
    cmd, env = serve_command("--world", "fact_world:FactWorld", "--connect", endpoint(port),
                             "--peer-timeout", "0.5")
    unreachable = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=60)
    assert unreachable.returncode == 4, unreachable.stderr
    assert f"cannot reach a Zenoh peer or router at {endpoint(port)}: nothing listens there" in unreachable.stderr
    assert "Traceback" not in unreachable.stderr
