"""The skill contract: how the executive asks for an action and how a plugin performs it.

A *skill* is a class that performs one PDDL action on a :class:`~vap_bt.world.World`. It names
the action it implements, the robot whose server hosts it, and the resource it occupies (two
goals for one resource are never in flight together). Skills are found through the entry-point
group ``vap_bt.skills``; the built-in ones in ``skills/`` are registered the same way.

The executive side sees goals the ROS way — send, feedback, result, cancel — through a
:class:`SkillClient`. One client runs goals in-process (fast campaigns), the other over Zenoh
(:mod:`vap_bt.transport`); behaviours cannot tell them apart. Skills never import py_trees.
"""

from __future__ import annotations

import enum
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from typing import Any, ClassVar, Protocol

from vap_bt.outcome import Outcome
from vap_bt.world import GoalContext, World

ENTRY_POINT_GROUP = "vap_bt.skills"


class GoalState(enum.Enum):
    """A goal's state, as ROS actions name them: pending and active until it ends (:attr:`terminal`)."""

    PENDING = "pending"  # sent, not yet accepted
    ACTIVE = "active"  # accepted and running
    SUCCEEDED = "succeeded"
    ABORTED = "aborted"  # the skill ran and failed, or its server vanished
    CANCELED = "canceled"
    REJECTED = "rejected"  # unknown action, busy resource, bad arguments

    @property
    def terminal(self) -> bool:
        """Whether the goal has ended (succeeded, aborted, canceled or rejected) and will not change
        again."""
        return self not in (GoalState.PENDING, GoalState.ACTIVE)


@dataclass
class SkillResult:
    """How a goal ended: ``success``, a message for people and the skill's own ``data`` (JSON-able)."""

    success: bool
    message: str = ""
    data: dict[str, Any] = field(default_factory=dict)

    @classmethod
    def of(cls, outcome: Outcome, call: str) -> "SkillResult":
        """The result of a motion or a world's action that ended as ``outcome`` (``call`` is the
        message when it gives none); the thing it did not see and the precondition it found
        false, if it names them, in ``data``."""
        data = {k: v for k, v in (("missing", outcome.missing), ("unmet", outcome.unmet)) if v}
        return cls(outcome.completed, outcome.message or call, data)

    @property
    def missing(self) -> str | None:
        """The thing the skill looked for where belief put it and did not see
        (:attr:`~vap_bt.outcome.Outcome.missing`), when its data names one."""
        return self._named("missing")

    @property
    def unmet(self) -> str | None:
        """The precondition the skill found false where it looked
        (:attr:`~vap_bt.outcome.Outcome.unmet`), when its data names one."""
        return self._named("unmet")

    def _named(self, key: str) -> str | None:
        name = self.data.get(key) if isinstance(self.data, dict) else None
        return name if isinstance(name, str) else None


@dataclass(frozen=True)
class Hint:
    """What the executive believes about one object of a goal, sent with the goal: where its
    scene graph places it (``position``, map frame) and what it rests on or in. A skill looks
    there and measures for itself; a hint is never a measurement the skill may skip."""

    name: str
    position: tuple[float, float, float] | None = None
    on: str | None = None
    inside: str | None = None
    #: m: how far from ``position`` belief allows the object to be (a measured centroid: a few
    #: cm; believed on a table: anywhere on its top); the skill names the object in its own
    #: frames within it (:mod:`vap_bt.scene.identity`)
    radius: float | None = None

    def to_json(self) -> dict:
        return {"name": self.name, "position": self.position, "on": self.on, "inside": self.inside,
                "radius": self.radius}

    @classmethod
    def from_json(cls, d: dict) -> "Hint":
        p = d.get("position")
        r = d.get("radius")
        return cls(d["name"], None if p is None else tuple(map(float, p)), d.get("on"), d.get("inside"),
                   None if r is None else float(r))


@dataclass
class Feedback:
    """A running goal's progress (0..1) and what it is doing now."""

    progress: float  # 0..1
    text: str = ""


class Skill(ABC):
    """Base class of every skill plugin.

    Subclasses set ``action`` (the PDDL action name), ``robot`` (which server hosts it) and
    ``resource`` (what it occupies while running), and implement :meth:`execute`, which runs on
    a worker thread and should call ``ctx.feedback`` now and then and return early once
    ``ctx.cancelled()`` is true.
    """

    action: ClassVar[str]
    robot: ClassVar[str] = "ur5e"
    resource: ClassVar[str] = "arm"

    def __init__(self, world: World) -> None:
        self.world = world

    @classmethod
    def binds(cls, world: Any) -> bool:
        """Whether this skill can act on ``world`` (a motion skill needs the robot's drivers)."""
        return True

    @abstractmethod
    def execute(self, args: tuple[str, ...], ctx: GoalContext) -> SkillResult:
        """Perform the action on ``args`` and say how it ended. Runs on a worker thread, blocks until
        done, reports through ``ctx.feedback`` and returns early (unsuccessful) once ``ctx.cancelled()``
        is true."""


class WorldActionSkill(Skill):
    """Perform ``self.action`` by asking the world (:meth:`~vap_bt.world.World.perform`).

    A world that knows every action — the symbolic one, over ground facts — needs no motion: this
    skill reports that it started, hands the action over and turns the world's
    :class:`~vap_bt.world.Outcome` into a :class:`SkillResult`. It stands in for a plugin
    whose world lacks what the plugin needs (:meth:`Skill.binds`), under the plugin's own action,
    robot and resource (:func:`vap_bt.plugins.instantiate`), and for the domain actions no plugin
    implements (:func:`vap_bt.app.runner.make_skills`). A world with drivers (the pybullet one)
    performs nothing: its actions are the skills' motions.
    """

    def execute(self, args: tuple[str, ...], ctx: GoalContext) -> SkillResult:
        call = f"{self.action}({', '.join(args)})"
        if ctx.cancelled():  # cancelled while queued: do not start moving
            return SkillResult(False, f"{call} cancelled before it started")
        ctx.feedback(0.0, f"{call} started")
        outcome = self.world.perform(self.action, tuple(args), ctx)
        ctx.feedback(1.0, f"{call} {'completed' if outcome.completed else 'failed'}")
        return SkillResult.of(outcome, call)


def performed_by_world(action: str, world: Any, robot: str = "sim", resource: str = "arm") -> Skill:
    """A :class:`WorldActionSkill` for ``action`` on ``world``."""
    cls = type(f"Performed_{action}", (WorldActionSkill,), {"action": action, "robot": robot, "resource": resource})
    return cls(world)


class GoalHandle:
    """A goal in flight, as the executive sees it: its state, its latest feedback, its result,
    and a way to cancel it (ROS actions' goal handle).

    The one base of every transport's handle: the in-process client's goals have ended before
    their handle exists (:class:`vap_bt.app.inprocess` builds it finished), a Zenoh goal's state
    is filled in by its status and liveliness callbacks (:class:`vap_bt.transport.client.
    ZenohGoalHandle` also reads its accept/reject reply when asked, and sends cancels)."""

    def __init__(self, goal_id: str, state: GoalState = GoalState.PENDING, result: SkillResult | None = None,
                 feedback: Feedback | None = None) -> None:
        self.goal_id = goal_id
        self._state = state
        self._result = result
        self._feedback = feedback

    def state(self) -> GoalState:
        return self._state

    def feedback(self) -> Feedback | None:
        return self._feedback

    def result(self) -> SkillResult | None:
        return self._result

    def cancel(self) -> None:
        """Ask the goal to stop; a goal that has already ended has nothing to cancel."""


class SkillClient(Protocol):
    """Starts goals on whatever hosts the skills (in-process or over Zenoh)."""

    def send_goal(self, action: str, args: tuple[str, ...], hints: tuple[Hint, ...] = ()) -> GoalHandle:
        """Start ``action(args)`` with the executive's ``hints``; returns at once with the goal's handle
        (a rejected goal's handle says so)."""

    def close(self) -> None: ...
