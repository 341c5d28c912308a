"""How ``vap-bt serve`` gets the world its skills act on.

A world is named either by one of the built-in names — ``symbolic`` or ``pybullet``, which need
a task file (``--task``) and are built exactly as ``vap-bt run`` builds them — or by a factory
spec ``package.module:callable`` for any other world (a real robot's adapter, a test world). The
factory is called with the ``--world-arg KEY=VALUE`` pairs as keyword arguments; values arrive as
strings and the factory converts what it needs. Every failure is one :class:`InputError`.
"""

from __future__ import annotations

import importlib
from typing import Any

from vap_bt.errors import InputError

BUILTIN_WORLDS = ("symbolic", "pybullet")


def make_world(spec: str, task: str | None = None, seed: int = 0,
               world_args: dict[str, str] | None = None) -> Any:
    """The world named by ``spec`` (see the module docstring)."""
    if spec in BUILTIN_WORLDS:
        return _builtin(spec, task, seed)
    if ":" not in spec:
        raise InputError("--world", f"unknown world {spec!r}: use {', '.join(BUILTIN_WORLDS)} "
                                    "or package.module:callable")
    factory = _resolve(spec)
    try:
        return factory(**(world_args or {}))
    except TypeError as exc:
        raise InputError("--world-arg", f"{spec} does not take these arguments: {exc}") from None


def parse_world_args(pairs: list[str]) -> dict[str, str]:
    """``--world-arg KEY=VALUE`` pairs as keyword arguments for a world factory (the values stay strings);
    a malformed pair is an :class:`InputError`."""
    out: dict[str, str] = {}
    for pair in pairs:
        key, sep, value = pair.partition("=")
        if not sep or not key.isidentifier():
            raise InputError("--world-arg", f"expected KEY=VALUE, got {pair!r}")
        out[key] = value
    return out


def _builtin(name: str, task: str | None, seed: int) -> Any:
    if not task:
        raise InputError("--task", f"the {name} world needs a task file (e.g. trees/collect_cup.yaml)")
    from vap_bt import taskfile
    from vap_bt.app import runner  # the executive's own wiring, so serve and run agree

    loaded = taskfile.load(task)
    return runner.make_world(loaded, runner.RunConfig.from_task(loaded, world=name, seed=seed))


def _resolve(spec: str) -> Any:
    module_name, _, attr = spec.partition(":")
    try:
        module = importlib.import_module(module_name)
    except ImportError as exc:
        raise InputError("--world", f"cannot import {module_name!r}: {exc}") from None
    factory = getattr(module, attr, None)
    if not callable(factory):
        raise InputError("--world", f"{module_name} has no callable {attr!r}")
    return factory
