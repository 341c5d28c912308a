"""A robot whose world runs in another process: what ``vap-bt serve --world remote`` binds skills to.

Motion skills bind to anything that offers the robot's drivers, its ``state()`` and its
``site_map()`` (:func:`vap_bt.robot.drivers.has_drivers`); a simulated world also takes the sim-only action
hook (``begin_action``/``end_action``). :class:`RemoteRobot` is that object over Zenoh, for a world
hosted by ``vap-bt sim`` (:mod:`vap_bt.app.sim_host`): the drivers and body are a
:class:`~vap_bt.transport.drivers.RemoteDrivers`, the hook a
:class:`~vap_bt.transport.world_hooks.ZenohActionHooks`. The skills — and the camera service built
on the same kit — cannot tell it from the world itself; a real robot's driver host would serve
the same driver keys and simply never answer the hook.
"""

from __future__ import annotations

import zenoh

from vap_bt.transport.drivers import RemoteDrivers
from vap_bt.transport.world_hooks import ZenohActionHooks


class RemoteRobot:
    """``robot``'s drivers, body and action hook, reached over ``session``."""

    name = "remote"

    def __init__(self, session: zenoh.Session, robot: str) -> None:
        self.robot = robot
        self._drivers = RemoteDrivers(session, robot)
        self._hooks = ZenohActionHooks(session, robot)

    @property
    def drivers(self) -> RemoteDrivers:
        """The robot's drivers and body over Zenoh: what the motion skills act through."""
        return self._drivers

    def state(self):
        return self._drivers.state()

    def site_map(self):
        return self._drivers.site_map()

    def begin_action(self, action: str, args: tuple[str, ...]) -> None:
        self._hooks.begin_action(action, args)

    def end_action(self, action: str | None = None, args: tuple[str, ...] | None = None) -> None:
        self._hooks.end_action(action, args)

    def close(self) -> None:
        self._hooks.close()
        self._drivers.close()
