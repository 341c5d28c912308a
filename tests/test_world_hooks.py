"""The sim-only action hook over real Zenoh sessions on 127.0.0.1: a skill server's announcement
reaches the pybullet world before the call returns, so the situation is armed before the skill's
first driver command; a world that is not there leaves the goal unannounced, with a warning."""

from __future__ import annotations

import logging

import pytest
from driver_scripts import kitchen, world_of
from plugin_fixtures.zenoh_net import endpoint, free_port, session

from vap_bt.sim.situations import SituationModel, SituationSpec
from vap_bt.transport import keys
from vap_bt.outcome import Outcome
from vap_bt.transport.messages import decode
from vap_bt.transport.world_hooks import ActionHookServer, ZenohActionHooks

SCENE = kitchen({"microwave": "type: appliance, state: closed"})


@pytest.fixture
def net():
    port = free_port()
    with session(listen=(endpoint(port),)) as sim, session(connect=(endpoint(port),)) as skills:
        yield sim, skills


@pytest.mark.slow
def test_an_announced_goal_is_drawn_and_armed_in_the_world_before_begin_returns(net, tmp_path):
    sim, skills = net
    model = SituationModel(table=(SituationSpec("turnon", "turnon_fails_object_off", 1.0, effect=False),))
    world = world_of(tmp_path, "hooks", SCENE, model)
    server = ActionHookServer(sim, ("ur5e", "base"), world)
    hooks = ZenohActionHooks(skills, "ur5e")
    try:
        hooks.begin_action("turnon", ("microwave", "cup"))
        assert world.injection.active is not None and world.injection.active.action == "turnon"
        assert not world.injection.effect("turnon")  # armed: a press would not register
        assert [s.kind for s in world.injected()] == ["turnon_fails_object_off"]
        hooks.end_action("close", ("microwave",))  # a late end of another action: ignored
        assert world.injection.active is not None
        hooks.end_action("turnon", ("microwave", "cup"))
        assert world.injection.active is None and world.injection.effect("turnon")
        ZenohActionHooks(skills, "base").begin_action("navigate", ("kitchen", "hall", "door"))  # the base's robot too
        assert world.injection.active.action == "navigate"
    finally:
        hooks.close()
        server.close()
        world.close()


def test_a_bad_event_gets_a_refusal_not_a_dead_server(net):
    sim, skills = net

    class Recording:
        def __init__(self):
            self.calls = []

        def begin_action(self, action, args):
            self.calls.append(("begin", action, args))

        def end_action(self, action=None, args=None):
            self.calls.append(("end", action, args))

    world = Recording()
    server = ActionHookServer(sim, ("ur5e",), world)
    try:
        hooks = ZenohActionHooks(skills, "ur5e")
        hooks.begin_action("grasp", ("cup", "table"))
        replies = list(skills.get(keys.world_action("ur5e"), payload=b"garbage", timeout=2))
        ack = decode(replies[0].ok.payload.to_bytes(), Outcome)
        assert not ack.completed and "bad action event" in ack.message
        hooks.end_action()
        assert world.calls == [("begin", "grasp", ("cup", "table")), ("end", None, None)]
        hooks.close()
    finally:
        server.close()


def test_without_a_world_the_goal_goes_unannounced_with_a_warning(net, caplog):
    _, skills = net
    hooks = ZenohActionHooks(skills, "ur5e", timeout=0.3)
    with caplog.at_level(logging.WARNING, logger="vap_bt.transport.world_hooks"):
        hooks.begin_action("grasp", ("cup", "table"))
    assert "no simulated world acknowledged begin grasp" in caplog.text
    hooks.close()
