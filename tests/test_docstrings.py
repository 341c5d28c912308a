"""Every public class and function of the package says what it is, checked on the code.

A public class (vap_bt/, skills/, robots/) has a docstring, and so does every public module-level
function. A public method has one too, unless

* it overrides a method of one of its base classes that is the project's, py_trees' or the
  standard library's (the base's docstring says what it does: ``update``, ``initialise``,
  ``terminate``, ``execute``, an executor's ``submit``), or
  implements a method of one of the project's Protocols — a class implements a Protocol when it
  has every method the Protocol declares, as a type checker sees it (a ``capture`` of a camera);
* or its name says it all (:data:`SELF_EXPLANATORY`).

Methods of private classes (``_Drawing``) are not public, and a lambda that is a dataclass field's
default is not a method. The modules are imported, not parsed, so that a base class from another
module (or from py_trees) is found where Python finds it.
"""

from __future__ import annotations

import functools
import importlib
import inspect
import pkgutil
import sys
from pathlib import Path
from types import ModuleType
from typing import Any, Callable

from conftest import ROOT

PACKAGES = ("vap_bt", "skills", "robots")
#: the folders and modules checked: the whole package
ROOMS = PACKAGES
#: files inside ROOMS that are not checked (none: every module is documented)
EXCLUDED: tuple[str, ...] = ()
#: method names that say all there is to say: serialisation, closing, a goal's or a device's plain
#: accessors, a thing's name, a tree's root, a chain's number of joints, a predicate's number of
#: arguments. Keep it short: any other method either has a docstring or is an override.
SELF_EXPLANATORY = frozenset({"to_json", "from_json", "from_dict", "close", "state", "result", "feedback",
                              "name", "root", "dof", "arity"})
#: the packages whose base classes' (and Protocols') docstrings an override shares; the standard
#: library's are as good (an :class:`~concurrent.futures.Executor`'s ``submit``)
BASE_PACKAGES = PACKAGES + ("py_trees",) + tuple(sorted(sys.stdlib_module_names))


def _rel(module: ModuleType) -> str:
    return Path(module.__file__).relative_to(ROOT).as_posix()


def _in_rooms(rel: str) -> bool:
    return rel not in EXCLUDED and any(rel == room or rel.startswith(room + "/") for room in ROOMS)


@functools.lru_cache(maxsize=1)
def _modules() -> tuple[ModuleType, ...]:
    """Every module of the package but the ``__main__`` entry points (they run when imported)."""
    out = []
    for name in PACKAGES:
        package = importlib.import_module(name)
        out.append(package)
        out += [importlib.import_module(m.name) for m in pkgutil.walk_packages(package.__path__, name + ".")
                if not m.name.endswith("__main__")]
    return tuple(out)


def _own(module: ModuleType, kind: Callable[[Any], bool]) -> list[tuple[str, Any]]:
    """The public classes or functions ``module`` defines, not those it imports; a decorated
    function (functools.wraps keeps name, module and docstring) counts as the one it wraps."""
    return [(name, obj) for name, obj in vars(module).items()
            if not name.startswith("_") and kind(inspect.unwrap(obj))
            and getattr(obj, "__module__", None) == module.__name__]


def _function(member: Any) -> Callable | None:
    """The function behind a class attribute (a method, static or class method, property), or None."""
    if isinstance(member, (staticmethod, classmethod)):
        return member.__func__
    if isinstance(member, property):
        return member.fget
    if isinstance(member, functools.cached_property):
        return member.func
    # a lambda in a class body is a dataclass field's default (``progress: Callable = lambda m: None``),
    # not a method: the field's ``#:`` comment says what it is, and a lambda cannot have a docstring
    return member if inspect.isfunction(member) and member.__name__ != "<lambda>" else None


def _methods(cls: type) -> list[str]:
    return [n for n, m in vars(cls).items() if not n.startswith("_") and _function(m) is not None]


def _is_protocol(cls: type) -> bool:
    return bool(getattr(cls, "_is_protocol", False))


@functools.lru_cache(maxsize=1)
def _protocols() -> tuple[frozenset[str], ...]:
    """The method names of each of the project's Protocols that declares any."""
    return tuple(frozenset(_methods(cls)) for module in _modules() for _, cls in _own(module, inspect.isclass)
                 if _is_protocol(cls) and _methods(cls))


def _inherited(cls: type, name: str) -> bool:
    """Whether method ``name`` of ``cls`` overrides a project or py_trees base's, or implements a
    method of a project Protocol that ``cls`` implements (a Protocol's own methods implement none)."""
    if any(base.__module__.split(".")[0] in BASE_PACKAGES and name in vars(base) for base in cls.__mro__[1:]):
        return True
    return not _is_protocol(cls) and any(
        name in protocol and all(hasattr(cls, n) for n in protocol) for protocol in _protocols())


def _documented(obj: Any) -> bool:
    """A docstring of its own: a dataclass or NamedTuple without one gets its signature instead."""
    doc = obj.__doc__ or ""
    return bool(doc.strip()) and not (inspect.isclass(obj) and doc.startswith(obj.__name__ + "("))


def undocumented() -> list[str]:
    """Every public class, function and method in ROOMS that needs a docstring and has none."""
    missing = []
    for module in _modules():
        where = _rel(module)
        if not _in_rooms(where):
            continue
        missing += [f"{where}: def {name}" for name, fn in _own(module, inspect.isfunction) if not _documented(fn)]
        for name, cls in _own(module, inspect.isclass):
            if not _documented(cls):
                missing.append(f"{where}: class {name}")
            missing += [f"{where}: def {name}.{attr}" for attr in _methods(cls)
                        if not _documented(_function(vars(cls)[attr])) and attr not in SELF_EXPLANATORY
                        and not _inherited(cls, attr)]
    return missing


def test_every_room_is_checked():
    """A room that names nothing (a typo, a moved module) would check nothing, silently."""
    checked = [_rel(m) for m in _modules() if _in_rooms(_rel(m))]
    empty = [room for room in ROOMS if not any(rel == room or rel.startswith(room + "/") for rel in checked)]
    assert not empty, f"ROOMS that match no module: {empty}"


def test_public_classes_and_functions_have_docstrings():
    missing = undocumented()
    assert not missing, f"{len(missing)} without a docstring:\n" + "\n".join(missing)
