"""A world shared by several threads, one call at a time.

A skill server runs one worker thread per resource (the arm's goals beside the base's) and
answers camera queries on yet another, all against one world. Simulators such as pybullet are not
thread-safe, so ``vap-bt serve`` binds skills and camera to a :class:`LockedWorld`: the same world behind a
re-entrant lock, which serialises every method call. A world that *is* thread-safe and wants
true overlap (a real robot's adapter) can be handed to :class:`~vap_bt.transport.server.SkillServer`
directly.
"""

from __future__ import annotations

import threading
from typing import Any


class LockedWorld:
    """Proxy for ``world`` whose methods run under one lock; attributes pass through."""

    def __init__(self, world: Any, lock: threading.RLock | None = None) -> None:
        self._world = world
        self._lock = lock or threading.RLock()

    @property
    def lock(self) -> threading.RLock:
        """The lock every call goes under: give it to another :class:`LockedWorld` whose object must take
        turns with this world (the simulated VLM that reads it)."""
        return self._lock

    @property
    def unwrapped(self) -> Any:
        """The world behind the proxy; calls made on it do not take the lock."""
        return self._world

    def __getattr__(self, attr: str) -> Any:
        value = getattr(self._world, attr)
        if not callable(value):
            return value
        lock = self._lock

        def locked(*args: Any, **kwargs: Any) -> Any:
            with lock:
                return value(*args, **kwargs)

        return locked
