"""The World contract: what a world (simulated or real) offers, and what it keeps to itself.

A world owns the truth. The executive never touches it: it sends goals to skills (which act on a
world) and perceives through the world's robot interfaces — the camera service (frames with
detections, viewpoints), proprioception and the site map (:mod:`vap_bt.robot`). A simulated
world also holds an :class:`~vap_bt.sim.oracle.Oracle` for the runner's report and for its own
simulated sensors and VLM; nothing on the executive's side is ever given it.

Worlds implement :class:`World`; :mod:`vap_bt.sim.symbolic` is the fast one over ground facts,
:mod:`vap_bt.sim.pybullet_world` the pybullet household. Everything here is plain data so that it
can cross a process boundary (see :mod:`vap_bt.transport`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal, Protocol, runtime_checkable

from vap_bt.outcome import Outcome
from vap_bt.robot.camera import Aim, Viewpoint
from vap_bt.robot.frame import Frame
from vap_bt.robot.site_map import SiteMap
from vap_bt.robot.state import RobotState


@dataclass(frozen=True)
class InjectedSituation:
    """An entry of the world's record, for the report: a situation the world caused on purpose
    (``source`` "table2"), a person's doing it scripted ("disturbance"), or an action of the
    robot that failed by physics alone ("natural", :mod:`vap_bt.sim.natural_failures`)."""

    action: str
    args: tuple[str, ...]
    kind: str  # e.g. "grasp_fails_object_unchanged", "object_moved_by_person"
    step: int
    #: the things it changed (what fell, what a person moved, the leaf pushed), where the world says
    affected: tuple[str, ...] = ()
    source: Literal["table2", "disturbance", "natural"] = "table2"

    def to_json(self) -> dict:
        """The report's (and the oracle service's) form of the entry."""
        return {"action": self.action, "args": list(self.args), "kind": self.kind, "step": self.step,
                "affected": list(self.affected), "source": self.source}

    @classmethod
    def from_json(cls, row: dict) -> "InjectedSituation":
        """The entry :meth:`to_json` wrote."""
        return cls(row["action"], tuple(row["args"]), row["kind"], int(row["step"]), tuple(row["affected"]), row["source"])


class GoalContext(Protocol):
    """Handed to a running skill: report progress, notice cancellation, read the goal's hints
    (:class:`vap_bt.skill.Hint` by object name: where the executive believes things are)."""

    hints: dict

    def feedback(self, progress: float, text: str = "") -> None:
        """Report progress (0..1) and what the skill is doing now (call it now and then, not every cycle)."""

    def cancelled(self) -> bool:
        """Whether the goal has been asked to stop: a skill checks it between steps (a driver, every
        control cycle) and returns early."""


@runtime_checkable
class World(Protocol):
    """A place where actions happen and a robot perceives."""

    name: str
    #: the truth: for the runner's report and the world's own simulated sensors and VLM only
    oracle: Any

    def reset(self, seed: int) -> None:
        """Restore the task's initial state; every random draw after this follows ``seed``."""

    def perform(self, action: str, args: tuple[str, ...], ctx: GoalContext) -> Outcome:
        """Carry out one domain action, with this world's situation injection. Only a world
        without drivers has it (the symbolic one); a world with drivers (the pybullet one) performs
        nothing: skills move its robot (:mod:`vap_bt.robot.drivers`)."""

    # the robot interfaces (vap_bt.robot.camera.Camera and Body)
    def capture(self, aim: Aim | None = None) -> Frame:
        """Aim at ``aim`` (None: as the camera is) and take one frame
        (:meth:`vap_bt.robot.camera.Camera.capture`)."""

    # without drivers, the world is its own camera service; with them, the skills' is
    # (skills.views.ViewService: it drives and aims, and the world only renders)
    def goto_view(self, view: Viewpoint) -> bool:
        """Drive and aim to ``view``; False when it cannot be reached from here."""

    def move_view(self, aim: Aim, direction: str) -> bool:
        """Move the viewpoint ``direction`` (one of ``VIEW_DIRECTIONS``) relative to ``aim``; False when
        it cannot."""

    def state(self) -> RobotState: ...

    def site_map(self) -> SiteMap:
        """The map the robot is given before it looks: rooms, doors, furniture (no items, nothing that
        changes)."""

    def close(self) -> None: ...
