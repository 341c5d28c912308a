"""unified-planning's engines, imported without paying for ConfigSpace at start-up.

Every command that reads PDDL needs ``unified_planning.engines``: the environment behind the PDDL
reader builds the engine factory, and Fast Downward, the plan validator and the quantifiers remover
are engines. That package's base class module does ``from ConfigSpace import ConfigurationSpace``,
and ConfigSpace imports ``scipy.stats``, whose distributions rewrite their docstrings at import:
0.8 s on an idle machine and 2 s on a busy one, which was half of ``vap-bt tree`` or ``vap-bt plan``.
unified-planning uses the name for one thing only — ``Engine.get_configuration_space()``, the
hyperparameter space of an engine tuner, returns an empty ``ConfigurationSpace()`` — and vap_bt
never tunes an engine.

:func:`load` imports the engines while ``sys.modules`` holds a stand-in ``ConfigSpace`` whose
``ConfigurationSpace`` builds the real one when called, and removes the stand-in as soon as the
import is done: ``get_configuration_space()`` still returns a real ``ConfigurationSpace`` (ConfigSpace
is imported then), and anyone importing ConfigSpace later gets the real package. When ConfigSpace
or the engines are already imported (a test, a tool that used ``unified_planning.shortcuts``),
:func:`load` changes nothing. Call it before the first use of anything that imports the engines:
the PDDL reader's environment, a compiler, a planner or the validator.
"""

from __future__ import annotations

import importlib
import sys
import threading
import types

_ENGINES = "unified_planning.engines"
_CONFIG_SPACE = "ConfigSpace"
_lock = threading.Lock()


def load() -> types.ModuleType:
    """``unified_planning.engines``, imported (once) with ConfigSpace left for when it is used."""
    with _lock:
        if _ENGINES in sys.modules or _CONFIG_SPACE in sys.modules:
            return importlib.import_module(_ENGINES)
        stand_in = types.ModuleType(_CONFIG_SPACE, "ConfigSpace, imported when a ConfigurationSpace is built")
        stand_in.ConfigurationSpace = configuration_space
        sys.modules[_CONFIG_SPACE] = stand_in
        try:
            return importlib.import_module(_ENGINES)
        finally:
            if sys.modules.get(_CONFIG_SPACE) is stand_in:
                del sys.modules[_CONFIG_SPACE]


def configuration_space(*args, **kwargs):
    """A real ``ConfigSpace.ConfigurationSpace``, ConfigSpace imported on this first call."""
    from ConfigSpace import ConfigurationSpace

    return ConfigurationSpace(*args, **kwargs)


__all__ = ["load", "configuration_space"]
