"""Who may start and cancel goals once the Zenoh network is locked down with Zenoh's own config.

The router runs ``examples/zenoh/router.json5`` (user/password on every link, access control by
role) and the skill server and executive ``skills.json5`` and ``executive.json5`` — the files
``docs/SECURITY.md`` points to — each moved to a free loopback port with ``--listen``/``--connect``
as the command line does it (:class:`TransportSettings`). The server is the real
:class:`SkillServer`, over a world that records on the server's side every action it was asked to
perform and whether that action saw a cancel: what must not happen is asserted there, not only on
the client. Mutual TLS is checked the same way with certificates made by ``openssl``.
test_transport_auth.py covers the bare user/password router without access control.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import time
from contextlib import ExitStack
from pathlib import Path

import pytest
import zenoh

from plugin_fixtures.fact_world import FactWorld
from plugin_fixtures.zenoh_net import endpoint, free_port, wait_until
from vap_bt.errors import TransportError
from vap_bt.skill import GoalState, performed_by_world
from vap_bt.transport import keys
from vap_bt.transport.client import ZenohGoalHandle, ZenohSkillClient
from vap_bt.transport.config import TransportSettings, build_config, open_session
from vap_bt.transport.messages import CancelRequest, GoalStatus, encode
from vap_bt.transport.server import SkillServer

pytestmark = pytest.mark.timeout(60)

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "zenoh"
DICTIONARY = "/etc/vap-bt/zenoh-users.txt"  # where router.json5 expects it
ACCEPT_S = 1.0  # how long a client waits for a goal's accept/reject here
LONG_S = 2.0  # a goal long enough to try to cancel it


class RecordingWorld(FactWorld):
    """The server side's record: every action performed, and whether it ended on a cancel."""

    def __init__(self) -> None:
        super().__init__(duration=0.0, steps=40)
        self.started: list[tuple[str, tuple[str, ...]]] = []
        self.cancel_seen: list[bool] = []

    def perform(self, action, args, ctx):
        self.started.append((action, tuple(args)))
        outcome = super().perform(action, args, ctx)
        self.cancel_seen.append(ctx.cancelled())
        return outcome


def _client_file(tmp: Path, name: str, mode: str, user: str | None = None, password: str = "") -> str:
    """A session's own config (its endpoint comes from ``connect=``): no credentials, or these."""
    conf: dict = {"mode": mode, "scouting": {"multicast": {"enabled": False}}}
    if user:
        conf["transport"] = {"auth": {"usrpwd": {"user": user, "password": password}}}
    path = tmp / f"{name}.json5"
    path.write_text(json.dumps(conf))
    return str(path)


@pytest.fixture
def locked(tmp_path):
    """(router endpoint, world, executive client) with the example files; server and router up."""
    (tmp_path / "users.txt").write_text("skills:CHANGE-ME-skills\nexecutive:CHANGE-ME-executive\n")
    router_file = tmp_path / "router.json5"
    router_file.write_text((EXAMPLES / "router.json5").read_text().replace(DICTIONARY, str(tmp_path / "users.txt")))
    ep = endpoint(free_port())
    world = RecordingWorld()
    with ExitStack() as up:  # closed in reverse, whatever failed to start
        up.callback(open_session(TransportSettings(config_file=str(router_file), listen=(ep,))).close)
        server_s = open_session(TransportSettings(config_file=str(EXAMPLES / "skills.json5"), connect=(ep,)))
        up.callback(server_s.close)
        up.callback(SkillServer(server_s, "ur5e", _skills(world), name="arm").start().close)
        executive = _executive(ep)
        up.callback(executive.close)
        yield ep, world, executive


def _skills(world: RecordingWorld) -> dict:
    """``open`` on the arm, the goal to cancel; ``find`` on the base, free for an intruder's goal
    (so that a goal refused is refused by the network, not because a resource was busy)."""
    return {"open": performed_by_world("open", world, "ur5e", "arm"),
            "find": performed_by_world("find", world, "ur5e", "base")}


def _executive(ep: str) -> ZenohSkillClient:
    session = open_session(TransportSettings(config_file=str(EXAMPLES / "executive.json5"), connect=(ep,)))
    client = ZenohSkillClient(session, {"open": "ur5e"}, accept_timeout=ACCEPT_S, owns_session=True)
    wait_until(lambda: "arm" in client.servers("ur5e"), 3)
    return client


def _long_goal(world: RecordingWorld, client: ZenohSkillClient, what: str) -> ZenohGoalHandle:
    world.duration = LONG_S
    handle = client.send_goal("open", (what,))
    assert handle.wait_answered(2) is GoalState.ACTIVE
    # accepted is not yet begun: on a loaded machine a cancel could beat the start, and the world
    # would then never see the action it is asked about
    wait_until(lambda: ("open", (what,)) in world.started, 5)
    return handle


def _cancel(session: zenoh.Session, goal_id: str) -> None:
    """What a goal's cancel is on the wire (ZenohGoalHandle.cancel), sent by anyone."""
    session.put(keys.goal_cancel("ur5e", goal_id), encode(CancelRequest(goal_id)))


@pytest.mark.slow
def test_without_credentials_a_peer_can_neither_start_nor_cancel_a_goal(locked, tmp_path):
    ep, world, executive = locked
    running = _long_goal(world, executive, "fridge")

    # refused at the router, in one line and at once (client mode) or after --peer-timeout (peer)
    refused_link = "credentials or TLS refused"  # the port answers, the router refuses the session
    for name, mode, user, password, message in (
            ("anon-client", "client", None, "", refused_link),
            ("anon-peer", "peer", None, "", "no Zenoh peer or router answered within 0.5 s"),
            ("wrong-password", "client", "executive", "guess", refused_link),
            ("unknown-user", "client", "intruder", "CHANGE-ME-executive", refused_link)):
        conf = TransportSettings(config_file=_client_file(tmp_path, name, mode, user, password), connect=(ep,),
                                 peer_timeout=0.5)
        t0 = time.monotonic()
        with pytest.raises(TransportError, match=message):
            open_session(conf)
        assert time.monotonic() - t0 < 1.5, name

    # a session opened regardless of that check is alone: its goal is refused within the accept
    # timeout, and its cancel of the running goal goes nowhere
    anon = zenoh.open(build_config(TransportSettings(config_file=_client_file(tmp_path, "raw", "peer"), connect=(ep,))))
    intruder = ZenohSkillClient(anon, {"find": "ur5e"}, accept_timeout=ACCEPT_S, owns_session=True)
    try:
        t0 = time.monotonic()
        refused = intruder.send_goal("find", ("cup",))
        assert refused.wait(ACCEPT_S + 1) is GoalState.REJECTED
        assert time.monotonic() - t0 < ACCEPT_S + 1
        assert "no skill server for 'find' on robot 'ur5e' answered" in refused.result().message
        _cancel(anon, running.goal_id)
    finally:
        intruder.close()
    assert running.wait(LONG_S + 2) is GoalState.SUCCEEDED
    assert world.started == [("open", ("fridge",))]  # the server never saw the intruder's goal ...
    assert world.cancel_seen == [False]  # ... nor its cancel

    # with the right credentials both work: the config does not simply block everything
    mine = _long_goal(world, executive, "microwave")
    mine.cancel()
    assert mine.wait(2) is GoalState.CANCELED
    assert "open stopped by cancel" in mine.result().message
    assert world.started == [("open", ("fridge",)), ("open", ("microwave",))]
    assert world.cancel_seen == [False, True]


@pytest.mark.slow
def test_an_authenticated_peer_needs_the_role_to_start_or_cancel_and_none_forges_results(locked):
    ep, world, executive = locked
    running = _long_goal(world, executive, "fridge")

    # the skills credentials authenticate, but that role may not ask for goals nor cancel them
    server_like = open_session(TransportSettings(config_file=str(EXAMPLES / "skills.json5"), connect=(ep,)))
    wrong_role = ZenohSkillClient(server_like, {"find": "ur5e"}, accept_timeout=ACCEPT_S, owns_session=True)
    # a second executive may cancel (see below) but not publish a result in a server's name
    other_s = open_session(TransportSettings(config_file=str(EXAMPLES / "executive.json5"), connect=(ep,)))
    try:
        refused = wrong_role.send_goal("find", ("cup",))
        assert refused.wait(ACCEPT_S + 1) is GoalState.REJECTED
        assert "no skill server for 'find' on robot 'ur5e' answered" in refused.result().message
        _cancel(server_like, running.goal_id)
        forged = GoalStatus(running.goal_id, GoalState.SUCCEEDED, None, None, "arm")
        other_s.put(keys.goal_status("ur5e", running.goal_id), encode(forged))
        time.sleep(0.3)
        assert running.state() is GoalState.ACTIVE  # the forged result never reached the executive
        assert running.wait(LONG_S + 2) is GoalState.SUCCEEDED
        assert running.result().message == "open done"  # the server's own result
        assert world.started == [("open", ("fridge",))] and world.cancel_seen == [False]

        # rules are per key, not per goal: anyone with the executive role can cancel any goal
        mine = _long_goal(world, executive, "microwave")
        _cancel(other_s, mine.goal_id)
        assert mine.wait(2) is GoalState.CANCELED
        assert world.cancel_seen == [False, True]
    finally:
        wrong_role.close()
        other_s.close()


def _openssl(*args: str, cwd: Path) -> None:
    subprocess.run(["openssl", *args], cwd=cwd, check=True, capture_output=True, timeout=30)


def _pki(tmp: Path) -> Path:
    """A CA and, signed by it, a certificate for the router (127.0.0.1) and one for a client; and a
    self-signed certificate that claims to be that client."""
    pki = tmp / "pki"
    pki.mkdir()
    ec = ("-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes")
    _openssl("req", "-x509", *ec, "-keyout", "ca.key", "-out", "ca.pem", "-days", "2", "-subj", "/CN=vap-test-ca",
             cwd=pki)
    for name in ("router", "executive"):
        _openssl("req", *ec, "-keyout", f"{name}.key", "-out", f"{name}.csr", "-subj", f"/CN={name}", cwd=pki)
        (pki / f"{name}.ext").write_text("subjectAltName=IP:127.0.0.1\n")
        _openssl("x509", "-req", "-in", f"{name}.csr", "-CA", "ca.pem", "-CAkey", "ca.key", "-CAcreateserial",
                 "-out", f"{name}.pem", "-days", "2", "-extfile", f"{name}.ext", cwd=pki)
    _openssl("req", "-x509", *ec, "-keyout", "rogue.key", "-out", "rogue.pem", "-days", "2", "-subj", "/CN=executive",
             cwd=pki)
    return pki


def _tls_file(tmp: Path, name: str, conf: dict) -> str:
    path = tmp / f"{name}.json5"
    path.write_text(json.dumps({"scouting": {"multicast": {"enabled": False}}, **conf}))
    return str(path)


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("openssl") is None, reason="needs openssl to make certificates")
def test_mutual_tls_admits_only_a_certificate_of_the_ca(tmp_path):
    pki = _pki(tmp_path)
    ep = f"tls/127.0.0.1:{free_port()}"
    router = open_session(TransportSettings(config_file=_tls_file(tmp_path, "router", {
        "mode": "router", "listen": {"endpoints": [ep]},
        "transport": {"link": {"tls": {"root_ca_certificate": str(pki / "ca.pem"), "enable_mtls": True,
                                       "listen_certificate": str(pki / "router.pem"),
                                       "listen_private_key": str(pki / "router.key")}}}})))
    world = RecordingWorld()
    def client_tls(name: str) -> dict:
        return {"root_ca_certificate": str(pki / "ca.pem"), "enable_mtls": True,
                "connect_certificate": str(pki / f"{name}.pem"), "connect_private_key": str(pki / f"{name}.key")}

    def session(name: str, tls: dict | None) -> zenoh.Session:
        conf = {"mode": "client", "connect": {"endpoints": [ep]}}
        if tls is not None:
            conf["transport"] = {"link": {"tls": tls}}
        return open_session(TransportSettings(config_file=_tls_file(tmp_path, name, conf), peer_timeout=0.5))

    server_s = session("server", client_tls("executive"))
    server = SkillServer(server_s, "ur5e", _skills(world), name="arm").start()
    try:
        for name, tls in (("plain", None), ("ca-only", {"root_ca_certificate": str(pki / "ca.pem")}),
                          ("rogue", client_tls("rogue"))):
            with pytest.raises(TransportError, match="credentials or TLS refused"):
                session(name, tls)  # no certificate of our CA: the router closes the link
        executive = ZenohSkillClient(session("executive", client_tls("executive")), {"open": "ur5e"},
                                     owns_session=True)
        try:
            wait_until(lambda: "arm" in executive.servers("ur5e"), 3)
            assert executive.send_goal("open", ("fridge",)).wait(3) is GoalState.SUCCEEDED
            handle = _long_goal(world, executive, "oven")
            handle.cancel()
            assert handle.wait(2) is GoalState.CANCELED
            assert world.cancel_seen == [False, True]
        finally:
            executive.close()
    finally:
        server.close()
        server_s.close()
        router.close()
