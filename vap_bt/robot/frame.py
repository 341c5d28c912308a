"""Frames: one RGB-D capture of the wrist camera with what the object detector found in it.

A :class:`Frame` is what a real camera driver plus an instance-segmentation model return:
colour, metric depth, an instance mask image, the intrinsics and the camera's pose in the map
frame at capture time, and one :class:`Detection` per instance. A world without pixels (the
symbolic one) returns frames without images; its detections then carry the location relations
its relation detector reports (``Detection.relations``), each wrong at a documented rate, so
the same scene-graph builder consumes both.

A world's detection carries a class label (``label``: "bottle", "cabinet", "door"; the rule is
:mod:`vap_bt.robot.labels`), never which instance it is: its ``name`` is empty. Which known object
a detection is — bottle1 or bottle2, or none (a false positive) — is the robot's to work out:
:mod:`vap_bt.scene.identity` fills ``name`` in on a copy of the frame, from the map, belief and
the gripper (its association, name -> the detection's index in :attr:`Frame.detections`, is
:meth:`Frame.identified`). Every frame the executive or a skill reasons about has been
through it; :meth:`Frame.detection`, :meth:`Frame.detected` and :meth:`Frame.mask` read those
names. A detection never says anything about an object's state; that is for geometry and the
VLM to establish.

In worlds without pixels the relation reports name things only as a robot could: ``""`` is the
detected thing itself, ``"#k"`` the frame's k-th detection, and the site map's things (rooms,
floors, furniture, doors) by their map names (:func:`reference`, :func:`detection_index`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from vap_bt.domain.atoms import Atom


#: how a relation report names the detected thing itself
SELF = ""


def reference(index: int) -> str:
    """How a relation report names the frame's ``index``-th detection (``"#2"``)."""
    return f"#{index}"


def detection_index(arg: str) -> int | None:
    """The detection a relation argument refers to (``"#2"`` -> 2), or None (a map name, or the
    thing itself)."""
    if arg.startswith("#") and arg[1:].isdigit():
        return int(arg[1:])
    return None


@dataclass(frozen=True)
class Detection:
    """One object instance found in a frame: its class, its mask, and — once the robot has
    re-identified it — which known object it is (``name``; empty as a world reports it, and
    for a detection the robot could not assign)."""

    label: str  # class label, e.g. "cup", "cabinet", "door"
    pixels: int = 0  # area of the instance mask (0 in frames without images)
    mask_id: int = -1  # value of this instance in :attr:`Frame.masks`
    score: float = 1.0  # the detector's confidence
    #: worlds without geometry only: location atoms (on, inside, in_room, holding, blocking) about
    #: this instance as that world's relation detector reports them (possibly wrong), naming
    #: things as the module docstring says
    relations: tuple[Atom, ...] = ()
    #: which known object this is, filled in by re-identification (:mod:`vap_bt.scene.identity`)
    name: str = ""


@dataclass
class Frame:
    """One capture. Arrays are ``None`` in worlds without pixels."""

    frame_id: str
    stamp: float  # seconds of the world's clock at capture
    detections: tuple[Detection, ...] = ()
    rgb: np.ndarray | None = None  # (H, W, 3) uint8
    depth: np.ndarray | None = None  # (H, W) float32, metres along the optical axis; 0 = no return
    masks: np.ndarray | None = None  # (H, W) int32 instance mask ids, -1 background
    intrinsics: tuple[float, float, float, float] | None = None  # fx, fy, cx, cy (pixels)
    camera_pose: np.ndarray | None = None  # (4, 4) map <- optical frame (z forward, x right, y down)
    #: where the camera stood, in a world without camera poses: a name the same while the robot
    #: has not moved (the robot knows whether it moved); with a pose, the pose says it
    stand: str | None = None
    #: what the camera was aimed at (for records and people; never used to interpret the frame)
    aim: tuple[str, ...] = ()
    extra: dict = field(default_factory=dict)

    def detection(self, name: str) -> Detection | None:
        """The detection identified as ``name`` (None: none was, or the frame is unidentified)."""
        if not name:
            return None
        return next((d for d in self.detections if d.name == name), None)

    def detected(self) -> frozenset[str]:
        """The names of the identified detections."""
        return frozenset(d.name for d in self.detections if d.name)

    def identified(self) -> dict[str, int]:
        """Re-identification's association: object name -> index of its detection (for a frame
        known by id only, :func:`marked_frame`, the association it was sent with)."""
        if not self.detections and "identified" in self.extra:
            return dict(self.extra["identified"])
        return {d.name: k for k, d in enumerate(self.detections) if d.name}

    def mask(self, name: str) -> np.ndarray | None:
        """Boolean mask of one detected instance, or None (not detected, or no images)."""
        d = self.detection(name)
        if d is None or self.masks is None or d.mask_id < 0:
            return None
        return self.masks == d.mask_id


def at_edge(mask: np.ndarray) -> bool:
    """Whether a detection's mask reaches the image's border: the frame cut the thing off, and
    shows part of it."""
    return bool(mask[0].any() or mask[-1].any() or mask[:, 0].any() or mask[:, -1].any())


def marked_frame(frame_id: str, identified: dict[str, int]) -> Frame:
    """A frame known by its id only — its pixels stay with the world that took it — with the
    executive's association of names to its detections: what a world-side VLM is handed when a
    question crosses the transport."""
    return Frame(frame_id, 0.0, extra={"identified": dict(identified)})
