"""The embedded default: skill servers and the executive in one command, talking over Zenoh.

``vap-bt run`` needs no separate ``vap-bt serve``: this starts one Zenoh session for the
servers (listening on a free loopback port, or on what the user configured), a skill server per
robot that the skills name (the robot interfaces — camera, body, map — and the world-side
simulated VLM on the arm's server), and a second session for the executive that connects to the
first. Goals, feedback, results, cancels, frames, robot state, VLM questions and liveliness all
cross a real Zenoh link — the same path a multi-machine deployment takes — only the machine is
one; the executive's side holds Zenoh clients and nothing of the world. The world (and the VLM
that reads its capture records) sits behind one lock because the servers' threads share it.
"""

from __future__ import annotations

import socket
from dataclasses import dataclass, field
from typing import Any, Callable

from vap_bt.skill import Skill
from vap_bt.transport.client import ZenohRobot, ZenohSkillClient, ZenohVLM
from vap_bt.transport.config import TransportSettings, open_session
from vap_bt.app.locked_world import LockedWorld
from vap_bt.transport.server import SkillServer


#: the robot that carries the wrist camera: its server hosts the camera service (and, embedded,
#: the world-side VLM beside it)
CAMERA_ROBOT = "ur5e"


def free_loopback_endpoint() -> str:
    """A Zenoh TCP endpoint on a loopback port that is free now (another process may take it before the
    servers bind it)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return f"tcp/127.0.0.1:{s.getsockname()[1]}"


@dataclass
class EmbeddedTransport:
    """Servers for ``skills`` on ``world`` plus the client side, over a loopback Zenoh link."""

    world: Any
    skills: dict[str, Skill]
    vlm: Any | None = None  # a world-side VLM to serve beside the camera
    camera_robot: str = CAMERA_ROBOT
    #: the camera service over the (locked) world the servers share (default: the world itself)
    camera_for: Callable[[Any], Any] = lambda world: world
    server_settings: TransportSettings | None = None
    servers: list[SkillServer] = field(default_factory=list, init=False)

    def __post_init__(self) -> None:
        endpoint = free_loopback_endpoint()
        server_conf = self.server_settings or TransportSettings(listen=(endpoint,))
        client_conf = TransportSettings(connect=server_conf.listen or (endpoint,))
        self.locked = LockedWorld(self.world)
        camera = self.camera_for(self.locked)
        self._server_session = open_session(server_conf)
        routes = {action: skill.robot for action, skill in self.skills.items()}
        robots = sorted(set(routes.values()))
        camera_robot = self.camera_robot if self.camera_robot in robots else robots[0]
        for robot in robots:
            mine = {a: type(s)(self.locked) for a, s in self.skills.items() if s.robot == robot}
            here = robot == camera_robot
            vlm = LockedWorld(self.vlm, self.locked.lock) if here and self.vlm is not None else None
            self.servers.append(SkillServer(self._server_session, robot, mine, camera=camera if here else None,
                                            vlm=vlm).start())
        self._client_session = open_session(client_conf)
        self.client = ZenohSkillClient(self._client_session, routes)
        self.robot = ZenohRobot(self._client_session, camera_robot)
        self.vlm_client = None if self.vlm is None else ZenohVLM(self._client_session, camera_robot,
                                                                 self.vlm.describe())

    def close(self) -> None:
        self.client.close()
        self.robot.close()
        if self.vlm_client is not None:
            self.vlm_client.close()
        for s in self.servers:
            s.close()
        self._client_session.close()
        self._server_session.close()
