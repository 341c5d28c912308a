"""The executive against parts that run elsewhere: ``vap-bt run TASK --connect ENDPOINT``.

The embedded default (:mod:`.embedded`) starts the skill servers itself; here they are already
running — ``vap-bt sim`` hosts the world, its robot's drivers, the simulated VLM and the oracle;
``vap-bt serve --robot ur5e --world remote`` and ``--robot base`` host the skills, the arm's
server the camera service — and the executive only connects (to the sim's router, by default).
:class:`ConnectedTransport` offers the same three things as :class:`~.embedded.EmbeddedTransport`
(``client``, ``robot``, ``vlm_client``) plus ``world``, a
:class:`~vap_bt.transport.world_services.RemoteWorld` for the runner's report only.

Before the episode starts it makes sure every part is there: the world's oracle answers (and
runs this task), and every robot the skill plugins route to has a live skill server; otherwise
one :class:`~vap_bt.errors.TransportError` (exit 4) names every robot without one, the endpoint
it looked at, and the command that starts each missing server there. Once they are all there the
executive declares its own liveliness token, ``vap/part/executive/<task>-<pid>-<zid>``, so that
``vap-bt parts`` lists it beside the others.
"""

from __future__ import annotations

import time

from vap_bt import plugins
from vap_bt.errors import InputError, TransportError
from vap_bt.transport import keys
from vap_bt.transport.client import ZenohRobot, ZenohSkillClient, ZenohVLM
from vap_bt.transport.config import SIM_ENDPOINT, TransportSettings, open_session
from vap_bt.app.embedded import CAMERA_ROBOT
from vap_bt.transport.world_services import RemoteWorld


class ConnectedTransport:
    """Clients for skill servers, camera, VLM and world that other processes host."""

    def __init__(self, settings: TransportSettings, task_name: str, world_side_vlm: bool = True) -> None:
        self.settings = settings
        self._session = open_session(settings)
        try:
            self.world = RemoteWorld(self._session)
            info = self.world.info()
            if info.get("task") != task_name:
                raise InputError("--connect", f"the world at {self.where} runs task {info.get('task')!r}, "
                                              f"not {task_name!r}")
            routes = plugins.routes(plugins.discover_skills())
            self.client = ZenohSkillClient(self._session, routes, rejoin_timeout=settings.rejoin_timeout)
            self._wait_for_servers(sorted(set(routes.values())), settings.peer_timeout)
            self._token = self._session.liveliness().declare_token(
                keys.part("executive", keys.instance(task_name, self._session.zid())))
            self.robot = ZenohRobot(self._session, CAMERA_ROBOT, settings.camera_timeout)
            self.vlm_client = (ZenohVLM(self._session, CAMERA_ROBOT, info.get("vlm"), settings.camera_timeout)
                               if world_side_vlm else None)
        except BaseException:
            self._session.close()
            raise

    @property
    def where(self) -> str:
        """Where the executive looks for the parts, for messages: the endpoints it connects to, or the
        configured router."""
        return ", ".join(self.settings.connect) or "the configured router"

    def _wait_for_servers(self, robots: list[str], timeout: float) -> None:
        deadline = time.monotonic() + timeout
        while missing := [r for r in robots if not self.client.servers(r)]:
            if time.monotonic() > deadline:
                self.client.close()
                starts = " and ".join(f"`vap-bt serve --robot {r} --world remote{self._reach}`" for r in missing)
                raise TransportError(f"no skill server of robot{'s' * (len(missing) > 1)} {', '.join(missing)} is "
                                     f"up at {self.where} within {timeout:g} s: start {starts}")
            time.sleep(0.02)

    @property
    def _reach(self) -> str:
        """The options that make a skill server reach the sim this executive reached: none for the
        default endpoint, nor for a ``--zenoh-config`` (the servers' file is not the executive's)."""
        if self.settings.connect == (SIM_ENDPOINT,):
            return ""
        return "".join(f" --connect {ep}" for ep in self.settings.connect)

    def describe(self) -> dict:
        """For the report: where the parts were."""
        return {"connect": list(self.settings.connect), "config_file": self.settings.config_file,
                "servers": {r: sorted(self.client.servers(r)) for r in sorted(set(self.client.routes.values()))}}

    def close(self) -> None:
        self._token.undeclare()
        self.client.close()
        self.robot.close()
        if self.vlm_client is not None:
            self.vlm_client.close()
        self.world.close()
        self._session.close()
