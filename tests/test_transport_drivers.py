"""The robot's drivers over real Zenoh sessions on 127.0.0.1: calls, motions, stops, a dead client.

The drivers served here are a minimal robot whose motions take the time their trajectories say
and end early when stopped (what every driver of :mod:`vap_bt.robot.drivers` must do); the
pybullet drivers are exercised end to end by the four-process test (test_processes.py).
"""

from __future__ import annotations

import threading
import time
from types import SimpleNamespace

import numpy as np
import pytest

from plugin_fixtures.zenoh_net import endpoint, free_port, session, wait_until
from vap_bt.robot.drivers import GripperState, JointState, JointTrajectory, Outcome
from vap_bt.robot.frame import Frame
from vap_bt.robot.site_map import RoomInfo, SiteMap
from vap_bt.robot.state import RobotState
from vap_bt.transport.drivers import DriverServer, RemoteDrivers

pytestmark = pytest.mark.timeout(60)

JOINTS = tuple(f"j{i}" for i in range(6))


class TimedPart:
    """A part whose motions take their duration, end early on ``stop()`` or ``cancelled()``."""

    def __init__(self) -> None:
        self._stop = threading.Event()
        self.started = threading.Event()
        self.log: list[str] = []

    def run(self, duration: float, cancelled) -> Outcome:
        self._stop.clear()
        self.started.set()
        t_end = time.monotonic() + duration
        while time.monotonic() < t_end:
            if cancelled():
                return Outcome(False, "cancelled")
            if self._stop.is_set():
                self.log.append("stopped")
                return Outcome(False, "stopped")
            time.sleep(0.002)
        self.log.append("completed")
        return Outcome(True)

    def stop(self) -> None:
        self._stop.set()


class Arm(TimedPart):
    def __init__(self) -> None:
        super().__init__()
        self.q = np.zeros(6)
        self.got: JointTrajectory | None = None

    def joint_state(self) -> JointState:
        return JointState(JOINTS, tuple(self.q), (0.0,) * 6)

    def tcp_pose(self) -> np.ndarray:
        T = np.eye(4)
        T[:3, 3] = (0.4, 0.1, 1.0)
        return T

    def follow(self, trajectory: JointTrajectory, cancelled) -> Outcome:
        self.got = trajectory
        r = self.run(trajectory.duration, cancelled)
        if r.completed:
            self.q = np.asarray(trajectory.positions[-1], float)
        return r


class Base(TimedPart):
    def __init__(self) -> None:
        super().__init__()
        self.at = (1.0, 2.0, 0.5)

    def pose(self):
        return self.at

    def odometry(self):
        return self.at

    def follow(self, path, speed, cancelled) -> Outcome:
        r = self.run(0.2 * len(path), cancelled)
        if r.completed:
            self.at = tuple(path[-1])
        return r


class Gripper:
    def __init__(self) -> None:
        self.width = 0.085

    def state(self) -> GripperState:
        return GripperState(self.width, self.width < 0.01)

    def move(self, width, force, cancelled) -> GripperState:
        self.width = width
        return self.state()


class Camera:
    def capture(self) -> Frame:
        return Frame("f-1", 0.5, (), rgb=np.full((4, 6, 3), 7, np.uint8), depth=np.ones((4, 6), np.float32))


class Body:
    def state(self) -> RobotState:
        return RobotState(0.5, "kitchen", (1.0, 2.0, 0.5), (0.0,) * 6, None, 0.085, False)

    def site_map(self) -> SiteMap:
        return SiteMap((RoomInfo("kitchen", "floor_kitchen", (0.0, 0.0, 4.0, 4.0)),))


@pytest.fixture
def link():
    port = free_port()
    drivers = SimpleNamespace(arm=Arm(), gripper=Gripper(), base=Base(), camera=Camera())
    with session(listen=(endpoint(port),)) as s_srv, session(connect=(endpoint(port),)) as s_cli:
        server = DriverServer(s_srv, "ur5e", drivers, Body()).start()
        remote = RemoteDrivers(s_cli, "ur5e")
        wait_until(lambda: _answers(remote), 3)
        yield drivers, remote, port
        remote.close()
        server.close()


def _answers(remote) -> bool:
    try:
        remote.base.pose()
        return True
    except Exception:  # noqa: BLE001 - not up yet
        return False


def _trajectory(seconds: float) -> JointTrajectory:
    t = np.linspace(0.0, seconds, 5)
    return JointTrajectory(JOINTS, t, np.outer(t / seconds, np.arange(1, 7) * 0.1), np.zeros((5, 6)))


def test_calls_and_a_motion_round_trip(link):
    drivers, remote, _ = link
    assert remote.arm.joint_state().joints == JOINTS
    assert np.allclose(remote.arm.tcp_pose()[:3, 3], (0.4, 0.1, 1.0))
    assert remote.base.pose() == (1.0, 2.0, 0.5)
    assert remote.camera.capture().rgb.shape == (4, 6, 3)
    assert remote.state().room == "kitchen" and remote.site_map().room("kitchen") is not None
    t0 = time.monotonic()
    r = remote.arm.follow(_trajectory(0.3), lambda: False)
    assert r.completed and time.monotonic() - t0 >= 0.3  # the call blocks for the motion
    assert np.allclose(drivers.arm.got.positions, _trajectory(0.3).positions)  # arrays arrive intact
    assert np.allclose(remote.arm.joint_state().positions, np.arange(1, 7) * 0.1)
    assert remote.gripper.move(0.0, 40.0, lambda: False).holding
    assert remote.base.follow([(2.0, 2.0, 0.0)], 0.5, lambda: False).completed and remote.base.pose() == (2.0, 2.0, 0.0)


def test_cancelling_stops_the_motion_within_a_control_cycle(link):
    drivers, remote, _ = link
    cancel_at = time.monotonic() + 0.3
    t0 = time.monotonic()
    r = remote.arm.follow(_trajectory(5.0), lambda: time.monotonic() > cancel_at)
    took = time.monotonic() - t0
    assert not r.completed and r.message == "cancelled"
    assert took < 0.3 + 0.25, f"the stop took {took - 0.3:.3f} s to end the motion"
    assert drivers.arm.log[-1] == "stopped"


def test_a_client_that_dies_mid_motion_has_its_motion_stopped(link):
    """The process that commanded a motion vanishes: the server stops the arm instead of
    finishing a trajectory for a skill that no longer exists."""
    drivers, _, port = link
    with session(connect=(endpoint(port),)) as doomed_session:
        doomed = RemoteDrivers(doomed_session, "ur5e")
        wait_until(lambda: _answers(doomed), 3)
        done: list[Outcome] = []
        threading.Thread(target=lambda: done.append(doomed.arm.follow(_trajectory(10.0), lambda: False)),
                         daemon=True).start()
        assert drivers.arm.started.wait(3)
        time.sleep(0.1)
        t_dead = time.monotonic()
    # the session is closed: its liveliness token is gone
    wait_until(lambda: drivers.arm.log and drivers.arm.log[-1] == "stopped", 3)
    assert time.monotonic() - t_dead < 1.0
