"""The embedded default: skill servers and the executive in one command, talking over Zenoh.

``vap-bt run`` needs no separate ``vap-bt serve``: this starts one Zenoh session for the
servers (listening on a free loopback port, or on what the user configured), a skill server per
robot that the skills name (the wrist camera on the arm's server), and a second session for the
executive that connects to the first. Goals, feedback, results, cancels, camera requests and
liveliness all cross a real Zenoh link — the same path a multi-machine deployment takes — only
the machine is one. The world sits behind a lock because the servers' worker threads share it.
"""

from __future__ import annotations

import socket
from dataclasses import dataclass, field
from typing import Any

from vap_bt.skill import Skill
from vap_bt.transport.client import ZenohCamera, ZenohSkillClient
from vap_bt.transport.config import TransportSettings, open_session
from vap_bt.transport.locked_world import LockedWorld
from vap_bt.transport.server import SkillServer


def free_loopback_endpoint() -> str:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return f"tcp/127.0.0.1:{s.getsockname()[1]}"


@dataclass
class EmbeddedTransport:
    """Servers for ``skills`` on ``world`` plus the client side, over a loopback Zenoh link."""

    world: Any
    skills: dict[str, Skill]
    camera_robot: str = "ur5e"
    server_settings: TransportSettings | None = None
    servers: list[SkillServer] = field(default_factory=list, init=False)

    def __post_init__(self) -> None:
        endpoint = free_loopback_endpoint()
        server_conf = self.server_settings or TransportSettings(listen=(endpoint,))
        client_conf = TransportSettings(connect=server_conf.listen or (endpoint,))
        self.locked = LockedWorld(self.world)
        self._server_session = open_session(server_conf)
        routes = {action: skill.robot for action, skill in self.skills.items()}
        robots = sorted(set(routes.values()))
        camera_robot = self.camera_robot if self.camera_robot in robots else robots[0]
        for robot in robots:
            mine = {a: type(s)(self.locked) for a, s in self.skills.items() if s.robot == robot}
            self.servers.append(SkillServer(self._server_session, robot, mine,
                                            camera=self.locked if robot == camera_robot else None).start())
        self._client_session = open_session(client_conf)
        self.client = ZenohSkillClient(self._client_session, routes)
        self.camera = ZenohCamera(self._client_session, camera_robot)

    def close(self) -> None:
        self.client.close()
        self.camera.close()
        for s in self.servers:
            s.close()
        self._client_session.close()
        self._server_session.close()
