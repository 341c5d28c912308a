"""Skill plugins: finding the classes that perform PDDL actions, wherever they are installed.

A skill plugin is a :class:`~vap_bt.skill.Skill` subclass in any installed distribution,
registered under the entry-point group ``vap_bt.skills``::

    [project.entry-points."vap_bt.skills"]
    grasp = "my_package.grasp:Grasp"

The built-in skills (:mod:`skills`) are registered exactly the same way, so there is one path
for everybody. :func:`discover_skills` reads the registry without importing anything twice and
never raises for a broken plugin: a plugin that fails to import, or is not a concrete Skill
subclass, yields one warning naming the entry point and is skipped, so a bad third-party package
cannot take the executive down with it.

**One action, one skill.** The PDDL action name is the routing key (the client sends ``grasp`` to
whichever robot hosts ``grasp``), so two plugins binding the same action are a configuration
error, raised by :func:`skill_table` naming both entry points and their distributions. There is
no silent precedence: uninstall one of the two, or pass an explicit selection (``exclude``).
"""

from __future__ import annotations

import inspect
import logging
from dataclasses import dataclass
from importlib import metadata
from typing import Iterable

from vap_bt.errors import EXIT_BAD_INPUT, VapBtError
from vap_bt.skill import ENTRY_POINT_GROUP, Skill, performed_by_world
from vap_bt.world import World

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class SkillEntry:
    """One loadable skill plugin, as the registry and its class describe it."""

    name: str  # entry-point name
    action: str  # PDDL action the class performs
    robot: str  # robot whose skill server hosts it
    resource: str  # what it occupies while running
    cls: type[Skill]
    distribution: str  # distribution that declared the entry point ("?" when unknown)
    version: str
    module: str  # "package.module:Class", the entry point's value

    @property
    def origin(self) -> str:
        """Human-readable provenance, for listings and error messages."""
        return f"{self.name} = {self.module} ({self.distribution} {self.version})"


@dataclass(frozen=True)
class PluginProblem:
    """An entry point that could not be turned into a skill, and why."""

    name: str
    module: str
    distribution: str
    reason: str

    def __str__(self) -> str:
        return (
            f"skill plugin {self.name!r} ({self.module}, from {self.distribution}) "
            f"skipped: {self.reason}"
        )


@dataclass(frozen=True)
class Discovery:
    """Everything found under the group: usable entries and the ones that were skipped."""

    entries: tuple[SkillEntry, ...]
    problems: tuple[PluginProblem, ...]


class SkillConflictError(VapBtError):
    """Two plugins bind the same PDDL action; the message names both (exit code 2)."""

    exit_code = EXIT_BAD_INPUT


def discover(group: str = ENTRY_POINT_GROUP) -> Discovery:
    """Load every entry point of ``group``; never raises for a broken plugin."""
    entries: list[SkillEntry] = []
    problems: list[PluginProblem] = []
    seen: set[tuple[str, str, str]] = set()
    for ep in sorted(metadata.entry_points(group=group), key=lambda e: (e.name, e.value)):
        dist, version = _provenance(ep)
        key = (dist, ep.name, ep.value)
        if key in seen:  # the same distribution visible twice on sys.path
            continue
        seen.add(key)
        try:
            cls = ep.load()
        except Exception as exc:  # a plugin's import error is its problem, not ours
            problems.append(PluginProblem(ep.name, ep.value, dist, _describe(exc)))
            continue
        reason = _why_not_a_skill(cls)
        if reason:
            problems.append(PluginProblem(ep.name, ep.value, dist, reason))
            continue
        entries.append(
            SkillEntry(ep.name, cls.action, cls.robot, cls.resource, cls, dist, version, ep.value)
        )
    return Discovery(tuple(entries), tuple(problems))


def discover_skills(group: str = ENTRY_POINT_GROUP) -> list[SkillEntry]:
    """The usable skill plugins; each broken one is logged once as a warning and skipped."""
    found = discover(group)
    for problem in found.problems:
        log.warning("%s", problem)
    return list(found.entries)


def skill_table(
    entries: Iterable[SkillEntry], exclude: Iterable[str] = ()
) -> dict[str, SkillEntry]:
    """Map each action to its one entry; ``exclude`` drops entry points by name first.

    Raises :class:`SkillConflictError` when two remaining entries bind the same action.
    """
    dropped = set(exclude)
    table: dict[str, SkillEntry] = {}
    for entry in entries:
        if entry.name in dropped:
            continue
        other = table.get(entry.action)
        if other is not None:
            raise SkillConflictError(
                f"two skill plugins bind action {entry.action!r}: {other.origin} and "
                f"{entry.origin}; uninstall one or exclude one by entry-point name"
            )
        table[entry.action] = entry
    return table


def routes(entries: Iterable[SkillEntry]) -> dict[str, str]:
    """Which robot hosts which action: the client's routing table."""
    return {action: e.robot for action, e in skill_table(entries).items()}


def instantiate(
    world: World,
    robot: str | None = None,
    entries: Iterable[SkillEntry] | None = None,
) -> dict[str, Skill]:
    """One skill object per action, bound to ``world``; only ``robot``'s when given.

    A plugin that cannot act on ``world`` (:meth:`~vap_bt.skill.Skill.binds`: a motion skill and a
    world without drivers, such as the symbolic one) is stood in for by the world performing the
    action itself, when the world can (:class:`~vap_bt.skill.WorldActionSkill`); otherwise it is
    left out with a warning. Conflicts are checked over all entries, not just ``robot``'s,
    because routing is global.
    """
    table = skill_table(discover_skills() if entries is None else entries)
    out: dict[str, Skill] = {}
    for action, entry in table.items():
        if robot is not None and entry.robot != robot:
            continue
        if entry.cls.binds(world):
            out[action] = entry.cls(world)
        elif callable(getattr(world, "perform", None)):
            out[action] = performed_by_world(action, world, entry.robot, entry.resource)
        else:
            log.warning("skill plugin %s cannot act on this world and the world cannot perform %r: left out",
                        entry.origin, action)
    return out


def _provenance(ep: metadata.EntryPoint) -> tuple[str, str]:
    dist = getattr(ep, "dist", None)
    if dist is None:
        return "?", "?"
    return dist.metadata["Name"] or "?", dist.version or "?"


def _describe(exc: BaseException) -> str:
    return f"{type(exc).__name__}: {exc}".rstrip(": ")


def _why_not_a_skill(obj: object) -> str | None:
    """None when ``obj`` is a usable Skill class, otherwise a short reason."""
    if not (inspect.isclass(obj) and issubclass(obj, Skill)):
        return f"{obj!r} is not a subclass of vap_bt.skill.Skill"
    if inspect.isabstract(obj):
        return f"{obj.__qualname__} is abstract (implement execute)"
    for attr in ("action", "robot", "resource"):
        value = getattr(obj, attr, None)
        if not isinstance(value, str) or not value:
            return f"{obj.__qualname__}.{attr} must be a non-empty string"
    return None
