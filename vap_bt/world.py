"""The World contract: what a world (simulated or real) offers the rest of the system.

A world owns the truth. The executive never touches it directly: it sends goals to skills (which
act on a world) and asks for observations (which a world renders). Only two places may read the
truth itself, and both say so: the run's report (``goal_satisfied``, injected situations) and the
simulated VLM, whose answers are modelled on what the camera actually shows.

Worlds implement :class:`World`; :mod:`vap_bt.sim.symbolic` is the fast one over ground facts,
:mod:`vap_bt.sim` also holds the pybullet household. Everything here is plain data so that it can
cross a process boundary (see :mod:`vap_bt.transport`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np

from vap_bt.domain.atoms import Atom

#: Directions the viewpoint prompt offers (paper appendix, "Viewpoint Selection Prompt").
VIEW_DIRECTIONS: tuple[str, ...] = ("left", "right", "front", "behind", "above", "closer")


@dataclass(frozen=True)
class ObjectInfo:
    """One object as perception reports it: the scene graph's node."""

    name: str
    label: str
    room: str | None = None
    centroid: tuple[float, float, float] | None = None
    #: axis-aligned box as (xmin, ymin, zmin, xmax, ymax, zmax), metres, world frame
    box: tuple[float, float, float, float, float, float] | None = None


@dataclass
class SceneSnapshot:
    """What the robot believes at the start: objects and the ground facts that hold among them."""

    objects: list[ObjectInfo]
    facts: set[Atom]


@dataclass
class Observation:
    """One camera view. Images are optional so that the symbolic world can answer too.

    ``visibility`` maps object names to the fraction of the object that the view shows (0 when out
    of view or fully occluded); a pixel world derives it from the segmentation mask.

    ``relations`` are the spatial facts (``on``, ``inside``, ``in_room``, ``holding``) about the
    objects in view, as the scene-graph builder derives them from geometry (paper Sec. IV-A:
    centroid above a support surface, box inside a container's volume). They re-locate objects
    after a situation; truth values of other predicates are for the VLM to judge.
    """

    view_index: int
    targets: tuple[str, ...]
    visibility: dict[str, float]
    rgb: np.ndarray | None = None  # (H, W, 3) uint8
    depth: np.ndarray | None = None  # (H, W) float32, metres
    segmentation: np.ndarray | None = None  # (H, W) int32 object ids, -1 background
    segment_names: dict[int, str] = field(default_factory=dict)
    relations: frozenset[Atom] = frozenset()
    intrinsics: tuple[float, float, float, float] | None = None  # fx, fy, cx, cy
    camera_pose: tuple[float, ...] | None = None  # x, y, z, qx, qy, qz, qw (world frame)
    stamp: float = 0.0


@dataclass(frozen=True)
class InjectedSituation:
    """A situation the world caused on purpose (Table II) or by script, for the report."""

    action: str
    args: tuple[str, ...]
    kind: str  # e.g. "grasp_fails_object_unchanged", "held_object_drops"
    step: int


@dataclass
class ActionOutcome:
    """What the world did with an action. ``completed`` is the motion's own view: a grasp that
    closed on nothing still *completed*; that it failed is for perception to find out."""

    completed: bool
    message: str = ""


class GoalContext(Protocol):
    """Handed to a running skill: report progress, notice cancellation."""

    def feedback(self, progress: float, text: str = "") -> None: ...

    def cancelled(self) -> bool: ...


@runtime_checkable
class World(Protocol):
    """A place where actions happen and cameras look."""

    name: str

    def reset(self, seed: int) -> None:
        """Restore the task's initial state; every random draw after this follows ``seed``."""

    def survey(self) -> SceneSnapshot:
        """Explore and build a scene graph of the current state: every object with the facts an
        RGB-D survey and geometric reasoning establish (the paper's BuildSceneGraph). Called at
        the start, and again when an object has been lost track of."""

    def perform(self, action: str, args: tuple[str, ...], ctx: GoalContext) -> ActionOutcome:
        """Carry out one domain action, with this world's situation injection."""

    def observe(self, targets: tuple[str, ...]) -> Observation:
        """Render the current view, aimed at ``targets`` (object names)."""

    def move_view(self, target: str, direction: str) -> bool:
        """Move the viewpoint relative to ``target``; False when that view cannot be reached."""

    def holds(self, atom: Atom) -> bool:
        """Ground truth of one atom (reports and the simulated VLM only)."""

    def injected(self) -> list[InjectedSituation]:
        """Situations injected since the last reset, in order."""

    def close(self) -> None: ...
