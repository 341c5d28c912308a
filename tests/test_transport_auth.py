"""User/password authentication on a Zenoh router: without credentials, no goal starts.

A Python session in ``mode: "router"`` listens on 127.0.0.1 with ``transport/auth/usrpwd`` and a
dictionary file. The skill server and an authorised client join it with credentials through a
``--zenoh-config`` file (passed through untouched); a client without credentials is refused by the
router — ``zenoh.open`` does not say so, :func:`open_session` does — and a session opened
regardless cannot reach the server.
"""

from __future__ import annotations

import json

import pytest
import zenoh

from plugin_fixtures.fact_world import FactWorld
from vap_bt.skill import performed_by_world
from plugin_fixtures.zenoh_net import endpoint, free_port, wait_until
from vap_bt.errors import TransportError
from vap_bt.skill import GoalState
from vap_bt.transport.client import ZenohSkillClient
from vap_bt.transport.config import TransportSettings, open_session
from vap_bt.transport.server import SkillServer

pytestmark = pytest.mark.timeout(30)


def _config(path, mode: str, router: str, user: dict | None, listen: bool = False) -> str:
    conf = {
        "mode": mode,
        "scouting": {"multicast": {"enabled": False}},
        "listen": {"endpoints": [router] if listen else []},
        "connect": {"endpoints": [] if listen else [router]},
    }
    if user:
        conf["transport"] = {"auth": {"usrpwd": user}}
    path.write_text(json.dumps(conf))
    return str(path)


@pytest.mark.slow
def test_session_without_credentials_cannot_start_a_goal(tmp_path):
    router_ep = endpoint(free_port())
    (tmp_path / "users.txt").write_text("executive:s3cret\nskills:t0ken\n")
    router_conf = _config(tmp_path / "router.json5", "router", router_ep,
                          {"user": "router", "password": "x",
                           "dictionary_file": str(tmp_path / "users.txt")}, listen=True)
    router = open_session(TransportSettings(config_file=router_conf))
    server_s = open_session(TransportSettings(config_file=_config(
        tmp_path / "srv.json5", "client", router_ep, {"user": "skills", "password": "t0ken"})))
    server = SkillServer(server_s, "ur5e", {"grasp": performed_by_world("grasp", FactWorld(), "ur5e", "arm")}, name="arm").start()
    try:
        # the authorised executive gets its goal done through the router
        good_s = open_session(TransportSettings(config_file=_config(
            tmp_path / "good.json5", "client", router_ep, {"user": "executive", "password": "s3cret"})))
        good = ZenohSkillClient(good_s, {"grasp": "ur5e"}, owns_session=True)
        wait_until(lambda: "arm" in good._alive["ur5e"], 3)
        assert good.send_goal("grasp", ("cup", "table")).wait(3) is GoalState.SUCCEEDED
        good.close()

        # refused either way, as one TransportError: a peer-mode session opens alone (the
        # check catches it), a client-mode session fails inside zenoh.open
        anonymous = _config(tmp_path / "anon.json5", "peer", router_ep, None)
        wrong = _config(tmp_path / "wrong.json5", "client", router_ep,
                        {"user": "executive", "password": "guess"})
        refused = r"cannot reach a Zenoh peer or router at tcp/127\S+: something listens there, but no Zenoh peer"
        with pytest.raises(TransportError, match=refused):
            open_session(TransportSettings(config_file=anonymous, peer_timeout=1.0))
        with pytest.raises(TransportError, match=refused):
            open_session(TransportSettings(config_file=wrong, peer_timeout=1.0))

        # even a session opened without the check reaches nobody: the goal is refused
        raw = zenoh.open(zenoh.Config.from_file(anonymous))
        intruder = ZenohSkillClient(raw, {"grasp": "ur5e"}, accept_timeout=1.0, owns_session=True)
        handle = intruder.send_goal("grasp", ("cup", "table"))
        assert handle.wait(2) is GoalState.REJECTED
        assert "no skill server for 'grasp' on robot 'ur5e' answered" in handle.result().message
        intruder.close()
    finally:
        server.close()
        server_s.close()
        router.close()
