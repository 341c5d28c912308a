"""Skill goals over real Zenoh sessions on 127.0.0.1: the full goal life cycle, in one process.

A server session and a client session talk over TCP loopback on a port of their own; nothing is
mocked. Process-level failures (SIGKILL, SIGSTOP) are in test_transport_process.py.
"""

from __future__ import annotations

import logging
import math
import re
import struct
import time

import numpy as np
import pytest
import zenoh

from plugin_fixtures.fact_world import FactWorld
from plugin_fixtures.zenoh_net import endpoint, free_port, session, wait_until
from vap_bt.domain.atoms import Atom
from vap_bt.skill import GoalState, Skill, SkillResult, performed_by_world
from vap_bt.transport import keys
from vap_bt.robot.camera import Aim, Viewpoint
from vap_bt.transport.client import ZenohRobot, ZenohSkillClient
from vap_bt.transport.messages import SCHEMA, GoalRequest, encode
from vap_bt.transport.server import SkillServer

pytestmark = pytest.mark.timeout(30)


class Explodes(Skill):
    action = "explode"

    def execute(self, args, ctx):
        raise RuntimeError("boom")


def arm_skills(world) -> dict[str, Skill]:
    """The arm's actions performed by the fact world (it has no drivers to move), and one that raises."""
    skills = {a: performed_by_world(a, world, "ur5e", "arm") for a in ("grasp", "placeon", "open")}
    return {**skills, "explode": Explodes(world)}


@pytest.fixture
def net():
    """(world, server, client) for robot ur5e on a fresh loopback port."""
    port = free_port()
    world = FactWorld(duration=0.3, steps=3)
    with session(listen=(endpoint(port),)) as s_srv, session(connect=(endpoint(port),)) as s_cli:
        server = SkillServer(s_srv, "ur5e", arm_skills(world), camera=world, name="arm").start()
        routes = {a: "ur5e" for a in server.skills}
        client = ZenohSkillClient(s_cli, routes)
        wait_until(lambda: "arm" in client._alive["ur5e"], 3)
        yield world, server, client, s_cli
        client.close()
        server.close()


def test_goal_reports_feedback_then_result(net):
    world, _, client, _ = net
    handle = client.send_goal("grasp", ("cup", "table"))
    seen = {handle.wait_answered(2)}
    progress = []
    while not handle.state().terminal:
        if handle.feedback() is not None:
            progress.append(handle.feedback().progress)
        time.sleep(0.01)
    assert GoalState.ACTIVE in seen
    assert handle.wait(2) is GoalState.SUCCEEDED
    assert handle.result().success and "grasp done" in handle.result().message
    assert progress and min(progress) < 1.0  # feedback arrived while the goal ran
    assert handle.feedback().progress == 1.0
    assert world.oracle.holds(Atom("holding", ("cup",)))


def test_failed_action_is_aborted_with_the_worlds_reason(net):
    _, _, client, _ = net
    handle = client.send_goal("placeon", ("cup", "table"))  # not holding the cup
    assert handle.wait(3) is GoalState.ABORTED
    assert "preconditions do not hold" in handle.result().message


def test_a_skill_that_raises_aborts_its_goal_not_the_server(net):
    _, _, client, _ = net
    handle = client.send_goal("explode", ())
    assert handle.wait(3) is GoalState.ABORTED
    assert "RuntimeError: boom" in handle.result().message
    assert client.send_goal("open", ("fridge",)).wait(3) is GoalState.SUCCEEDED


def test_cancel_reaches_the_skill(net):
    world, _, client, _ = net
    world.duration, world.steps = 5.0, 100
    handle = client.send_goal("grasp", ("cup", "table"))
    assert handle.wait_answered(2) is GoalState.ACTIVE
    # accepted is not begun: a cancel that overtakes the worker ends the goal before the skill
    # runs (about 2 % of the time on a loaded machine); its first feedback says it has begun
    wait_until(lambda: handle.feedback() is not None, 2)
    handle.cancel()
    assert handle.wait(2) is GoalState.CANCELED
    assert "stopped by cancel" in handle.result().message
    assert not world.oracle.holds(Atom("holding", ("cup",)))


def test_unknown_action_is_rejected(net):
    _, _, client, s_cli = net
    unrouted = client.send_goal("fly", ("cup",))
    assert unrouted.state() is GoalState.REJECTED
    assert "no skill plugin binds action 'fly'" in unrouted.result().message
    # routed to the robot, but no server there hosts it
    lost = ZenohSkillClient(s_cli, {"fly": "ur5e"}, accept_timeout=2)
    handle = lost.send_goal("fly", ("cup",))
    assert handle.wait(2.5) is GoalState.REJECTED
    assert "no skill server for 'fly' on robot 'ur5e' answered" in handle.result().message
    lost.close()


def test_busy_resource_is_rejected_with_a_reason(net):
    world, _, client, _ = net
    world.duration, world.steps = 5.0, 100
    first = client.send_goal("grasp", ("cup", "table"))
    assert first.wait_answered(2) is GoalState.ACTIVE
    second = client.send_goal("open", ("fridge",))
    assert second.wait(2) is GoalState.REJECTED
    assert f"resource 'arm' of robot ur5e is busy with goal {first.goal_id}" in second.result().message
    first.cancel()
    assert first.wait(2) is GoalState.CANCELED
    world.duration = 0.0
    assert client.send_goal("open", ("fridge",)).wait(2) is GoalState.SUCCEEDED  # freed


def test_garbage_and_foreign_schema_requests_get_an_error_reply(net):
    _, _, _, s_cli = net
    key = keys.skill("ur5e", "grasp")
    replies = list(s_cli.get(key, payload=b"not a frame", timeout=2))
    assert replies[0].err is not None and "bad magic" in replies[0].err.payload.to_string()
    frame = encode(GoalRequest("x-1", "grasp", ("cup", "table")))
    foreign = frame[:4] + struct.pack("<I", 9) + frame[8:]  # the schema field
    replies = list(s_cli.get(key, payload=foreign, timeout=2))
    assert f"peer speaks message schema 9, this side speaks {SCHEMA}" in replies[0].err.payload.to_string()


def test_robot_interfaces_over_zenoh(net):
    world, _, _, s_cli = net
    robot = ZenohRobot(s_cli, "ur5e", timeout=3)
    frame = robot.capture(Aim(("cup", "ghost"), (1.0, 2.0, 0.5)))
    local = world.capture(Aim(("cup", "ghost")))
    assert [(d.label, d.name) for d in frame.detections] == [("cup", "")]  # a class, never which cup
    assert frame.aim == ("cup", "ghost") and frame.frame_id != local.frame_id
    for name, dtype in (("rgb", np.uint8), ("depth", np.float32), ("masks", np.int32)):
        assert getattr(frame, name).dtype == dtype
        np.testing.assert_array_equal(getattr(frame, name), getattr(local, name))
    assert frame.intrinsics == (500.0, 500.0, 3.0, 2.0) and frame.camera_pose.shape == (4, 4)
    assert (frame.masks == frame.detections[0].mask_id).sum() == 4
    assert robot.state().room == "kitchen" and robot.state().gripper_holding is False
    assert [r.name for r in robot.site_map().rooms] == ["kitchen", "hall"]
    assert robot.goto_view(Viewpoint("kitchen", Aim(("table",)))) is True
    assert robot.goto_view(Viewpoint("attic", Aim(("table",)))) is False
    assert robot.move_view(Aim(("cup",)), "left") is True
    assert robot.move_view(Aim(("cup",)), "sideways") is False
    robot.close()


def test_two_robots_do_not_see_each_others_goals():
    port = free_port()
    w1, w2 = FactWorld(), FactWorld()
    heard: list[str] = []
    with session(listen=(endpoint(port),)) as srv, session(connect=(endpoint(port),)) as cli:
        s1 = SkillServer(srv, "r1", arm_skills(w1), name="one").start()
        s2 = SkillServer(srv, "r2", arm_skills(w2), name="two").start()
        spy = cli.declare_subscriber("vap/r2/**", lambda s: heard.append(str(s.key_expr)))
        c1 = ZenohSkillClient(cli, {"grasp": "r1"})
        wait_until(lambda: "one" in c1._alive["r1"], 3)
        assert c1.send_goal("grasp", ("cup", "table")).wait(3) is GoalState.SUCCEEDED
        assert w1.performed == [("grasp", ("cup", "table"))] and w2.performed == []
        assert set(c1._alive) == {"r1"}  # it never subscribed to r2's namespace
        time.sleep(0.1)
        assert heard == []
        spy.undeclare()
        c1.close()
        s1.close()
        s2.close()


SERVER_LOG = "vap_bt.transport.server"


def _goal_lines(caplog, goal_id: str) -> list[str]:
    return [r.getMessage() for r in caplog.records if r.name == SERVER_LOG and f" {goal_id} " in r.getMessage()]


def test_each_goal_is_logged_one_line_per_event_its_feedback_at_most_once_a_second(net, caplog):
    """Accepted, then feedback — the first sample at once, then at most a line a second, saying how
    many samples it skipped — then the result: each line names robot, goal id, action and skill."""
    world, _, client, _ = net
    world.duration, world.steps = 2.2, 44  # "started", then a feedback sample every 50 ms
    caplog.set_level(logging.INFO, logger=SERVER_LOG)
    t0 = time.monotonic()
    handle = client.send_goal("grasp", ("cup", "table"))
    assert handle.wait(10) is GoalState.SUCCEEDED
    elapsed = time.monotonic() - t0
    name = f"ur5e goal {handle.goal_id} grasp(cup, table) [Performed_grasp]"
    wait_until(lambda: any(" succeeded after " in line for line in _goal_lines(caplog, handle.goal_id)), 2)
    lines = _goal_lines(caplog, handle.goal_id)
    feedback = [line for line in lines if line.startswith(f"{name}: feedback ")]
    assert lines[0] == f"{name}: accepted" and len(lines) == len(feedback) + 2, lines
    assert re.fullmatch(rf"{re.escape(name)}: succeeded after \d+\.\d\d s: grasp done", lines[-1]), lines[-1]
    assert feedback[0] == f"{name}: feedback 0% grasp(cup, table) started"  # the skill's first sample
    assert 2 <= len(feedback) <= 1 + math.ceil(elapsed), feedback  # 45 samples in 2.2 s: about 3 lines
    skipped = [int(re.search(r"\((\d+) more samples? since the last line\)$", line)[1]) for line in feedback[1:]]
    assert len(feedback) + sum(skipped) <= 45 and all(n > 0 for n in skipped), feedback


def test_a_goal_in_flight_has_a_liveliness_token_and_rejections_and_cancels_are_logged(net, caplog):
    """``vap-bt parts`` sees a running goal by its token; a goal the busy arm refuses, the cancel
    and the result are each one line."""
    from vap_bt.app import census

    world, _, client, s_cli = net
    world.duration, world.steps = 5.0, 100
    caplog.set_level(logging.INFO, logger=SERVER_LOG)
    handle = client.send_goal("grasp", ("cup", "table"))
    assert handle.wait_answered(2) is GoalState.ACTIVE
    key = keys.goal_alive("ur5e", "arm", "grasp", handle.goal_id)
    wait_until(lambda: census.snapshot(s_cli, 1.0)[1] == [census.Goal("ur5e", "arm", "grasp", handle.goal_id, key)], 3)
    busy = client.send_goal("open", ("fridge",))
    assert busy.wait(2) is GoalState.REJECTED
    handle.cancel()
    assert handle.wait(3) is GoalState.CANCELED
    wait_until(lambda: census.snapshot(s_cli, 1.0)[1] == [], 3)  # withdrawn once the result is out
    name = f"ur5e goal {handle.goal_id} grasp(cup, table) [Performed_grasp]"
    lines = [line for line in _goal_lines(caplog, handle.goal_id) if ": feedback " not in line]
    assert lines == [f"{name}: accepted", f"{name}: cancel requested", lines[-1]]
    assert re.fullmatch(rf"{re.escape(name)}: canceled after \d+\.\d\d s: grasp stopped by cancel", lines[-1])
    assert _goal_lines(caplog, busy.goal_id) == [
        f"ur5e goal {busy.goal_id} open(fridge): rejected: resource 'arm' of robot ur5e is busy with goal "
        f"{handle.goal_id}; send open again when it has ended"]
