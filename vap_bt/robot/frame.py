"""Frames: one RGB-D capture of the wrist camera with what the object detector found in it.

A :class:`Frame` is what a real camera driver plus an instance-segmentation model return:
colour, metric depth, an instance mask image, the intrinsics and the camera's pose in the map
frame at capture time, and one :class:`Detection` per instance. A world without pixels (the
symbolic one) returns frames without images; its detections then carry the location relations
its relation detector reports (``Detection.relations``), each wrong at a documented rate, so
the same scene-graph builder consumes both.

A detection names its instance (``name``): the detector's track identity, which here is the
object's name, standing for detection plus re-identification. It never says anything about an
object's state; that is for geometry and the VLM to establish.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from vap_bt.domain.atoms import Atom


@dataclass(frozen=True)
class Detection:
    """One object instance found in a frame."""

    name: str  # instance identity (track id); the object's name in this project's worlds
    label: str  # class label, e.g. "cup", "cabinet"
    pixels: int = 0  # area of the instance mask (0 in frames without images)
    mask_id: int = -1  # value of this instance in :attr:`Frame.masks`
    score: float = 1.0
    #: worlds without geometry only: location atoms (on, inside, in_room, holding) about this
    #: instance as that world's relation detector reports them (possibly wrong)
    relations: tuple[Atom, ...] = ()


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
    #: what the camera was aimed at (for records and people; never used to interpret the frame)
    aim: tuple[str, ...] = ()
    extra: dict = field(default_factory=dict)

    def detection(self, name: str) -> Detection | None:
        return next((d for d in self.detections if d.name == name), None)

    def detected(self) -> frozenset[str]:
        return frozenset(d.name for d in self.detections)

    def mask(self, name: str) -> np.ndarray | None:
        """Boolean mask of one detected instance, or None (not detected, or no images)."""
        d = self.detection(name)
        if d is None or self.masks is None or d.mask_id < 0:
            return None
        return self.masks == d.mask_id
