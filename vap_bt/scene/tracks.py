"""Object tracks: one object's geometry fused across the views that saw it.

A single view shows one side of an object, so its cloud's centroid is pulled towards the camera
and its box is too shallow. An :class:`ObjectTrack` accumulates every view of an object (the
name re-identification gave the detection, :mod:`vap_bt.scene.identity`, is the track's identity): the new view's cleaned cloud is merged with the
old and voxel-downsampled again, which keeps the density even however often a side was seen.

Merging is right only while the object stays put. Things the site map places (furniture, doors)
stay put by definition: their views always merge, however different the part they show (a view
of one table leg from across the room is the same table). When a view puts any other object
evidently elsewhere, the object has moved (a person carried it off, it fell), and the old geometry
describes a place the object no longer is: the new view replaces it. "Evidently elsewhere" takes
two tests (:class:`FusionParams`):

* the centroid shifted further than a partial view can explain: half the object's box diagonal
  (a view of one side has its centroid at most that far from the whole's), and at least
  ``moved_min`` so that noise on a small item is not taken for a move;
* and neither cloud lies mostly within the other's box: a close view of a table's corner after
  a view of the whole table (or the whole after the corner) shifts the centroid a lot, yet is the
  same table seen partly.

:class:`Tracks` holds the tracks of a scene and integrates whole frames into them. It also says
which tracked objects a frame should have shown but did not (:meth:`Tracks.missing`): the camera
looked where the object was, nothing stood in front, and the detector found nothing — the object
is not where belief puts it, and someone has to go and look.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:  # open3d (2 s to import) is needed only for the type names here
    import open3d as o3d

from vap_bt.robot.frame import Frame
from vap_bt.scene.pointcloud import CloudParams, downsample, frame_clouds

Box = tuple[float, float, float, float, float, float]  # xmin, ymin, zmin, xmax, ymax, zmax (m, map frame)


@dataclass(frozen=True)
class FusionParams:
    """When a new view is merged into a track and when it replaces the track's geometry."""

    #: smallest centroid shift taken for a move: above a view's noise and partial-view bias on a
    #: 6 cm cup (about 2 cm each), below the 10 cm a person's move of an object amounts to at least
    moved_min: float = 0.05
    #: a shift beyond this share of the track's box diagonal is a move (see the module docstring)
    moved_share: float = 0.5
    #: a cloud with at least this share of its points within the other's box (grown by
    #: ``contained_margin``) is the same object seen partly: a majority, so stray points do not
    #: decide
    contained_share: float = 0.5
    #: a voxel: how far a box's faces move with noise between views of an unmoved object
    contained_margin: float = 0.01
    #: a track's box reaches up to this quantile's complement of its points' heights, not to the
    #: highest: a stereo camera's mixed pixels at an object's outline return a depth between it and
    #: what stands in front, so the background surface's points there come forward, towards a
    #: camera that looks down — up. The highest of a fused table's few hundred points lay 3-7 cm
    #: above its top beside a cup (pick_plate and cut_lemon with noisy depth), its 98th percentile
    #: within 7 mm. Only the top is trimmed: the bottom of a table's thin legs is a few points too,
    #: and true
    box_trim: float = 0.02


def cloud_box(cloud: o3d.geometry.PointCloud, top_trim: float = 0.0) -> Box:
    """Axis-aligned bounding box of a non-empty cloud; with ``top_trim``, its top at that share
    of the points below the highest (see :attr:`FusionParams.box_trim`)."""
    bb = cloud.get_axis_aligned_bounding_box()
    lo, hi = np.array(bb.min_bound, float), np.array(bb.max_bound, float)
    if top_trim > 0.0:
        hi[2] = float(np.quantile(np.asarray(cloud.points)[:, 2], 1.0 - top_trim))
    return (*map(float, lo), *map(float, hi))  # type: ignore[return-value]


def box_diagonal(box: Box) -> float:
    """The length of a box's diagonal (metres)."""
    return float(np.linalg.norm(np.subtract(box[3:], box[:3])))


@dataclass
class ObjectTrack:
    """One object's fused cloud (map frame), with its centroid and box, and how it was seen."""

    name: str
    label: str
    cloud: o3d.geometry.PointCloud
    centroid: tuple[float, float, float]
    box: Box
    views: int = 1  # views fused since the geometry was last replaced
    last_frame: str = ""
    #: frame in which a view last replaced the geometry because the object had moved
    moved_in: str | None = None

    @classmethod
    def start(cls, name: str, label: str, cloud: o3d.geometry.PointCloud, frame_id: str,
              params: FusionParams = FusionParams()) -> "ObjectTrack":
        """A new track: ``cloud``, the object's first view, seen in ``frame_id``."""
        return cls(name, label, cloud, _centroid(cloud), cloud_box(cloud, params.box_trim), 1, frame_id)

    @property
    def points(self) -> np.ndarray:
        """(N, 3) float64 points, map frame."""
        return np.asarray(self.cloud.points)

    def moved(self, view: o3d.geometry.PointCloud, params: FusionParams) -> bool:
        """Does ``view`` put the object somewhere else than this track?"""
        shift = float(np.linalg.norm(np.subtract(_centroid(view), self.centroid)))
        if shift <= max(params.moved_min, params.moved_share * box_diagonal(self.box)):
            return False
        new = np.asarray(view.points)
        return max(_share_within(new, self.box, params.contained_margin),
                   _share_within(self.points, cloud_box(view, params.box_trim), params.contained_margin)) < params.contained_share

    def fuse(self, view: o3d.geometry.PointCloud, frame_id: str, cloud_params: CloudParams,
             params: FusionParams, static: bool = False) -> None:
        """Merge ``view`` (a cleaned cloud) into the track, or replace the geometry if it moved
        (never for a ``static`` thing: one the map places)."""
        if not static and self.moved(view, params):
            merged, self.views, self.moved_in = view, 1, frame_id
        else:
            merged = downsample(self.cloud + view, cloud_params)
            self.views += 1
        self.cloud, self.centroid, self.box = merged, _centroid(merged), cloud_box(merged, params.box_trim)
        self.last_frame = frame_id


def in_plain_view(track: ObjectTrack, frame: Frame, min_pixels: int = 0, max_range: float = math.inf) -> bool:
    """Would ``frame`` show the object if it were where its track puts it?

    Its centroid must project into the image within ``max_range``, the depth there must not
    be nearer than the object's own near side (else something stands in front of it), and it
    must look big enough to be detected (``min_pixels``: its box's circumscribed disc, projected).
    A pixel without a depth return is no evidence either way."""
    if frame.depth is None or frame.intrinsics is None or frame.camera_pose is None:
        return False
    fx, fy, cx, cy = frame.intrinsics
    x, y, z = (np.linalg.inv(frame.camera_pose) @ np.array([*track.centroid, 1.0]))[:3]
    h, w = frame.depth.shape
    if not 0.0 < z <= max_range:
        return False
    u, v = int(round(fx * x / z + cx)), int(round(fy * y / z + cy))
    if not (0 <= u < w and 0 <= v < h):
        return False
    radius = box_diagonal(track.box) / 2
    seen = float(frame.depth[v, u])
    return seen > 0.0 and seen >= z - radius and math.pi * (fx * radius / z) ** 2 >= min_pixels


def _share_within(points: np.ndarray, box: Box, grow: float) -> float:
    """Share of ``points`` inside ``box`` grown by ``grow`` on every side."""
    lo, hi = np.asarray(box[:3]) - grow, np.asarray(box[3:]) + grow
    return float(np.mean(np.all((points >= lo) & (points <= hi), axis=1)))


def _centroid(cloud: o3d.geometry.PointCloud) -> tuple[float, float, float]:
    c = cloud.get_center()
    return (float(c[0]), float(c[1]), float(c[2]))


@dataclass
class Tracks:
    """The object tracks of one scene, by instance name."""

    cloud_params: CloudParams = field(default_factory=CloudParams)
    fusion: FusionParams = field(default_factory=FusionParams)
    #: names of things that never move (the site map's furniture and doors)
    static: frozenset[str] = frozenset()
    _tracks: dict[str, ObjectTrack] = field(default_factory=dict, repr=False)

    def integrate(self, frame: Frame) -> list[str]:
        """Fuse every detection of ``frame`` that has a mask and enough depth into its track;
        returns the names of the tracks started or updated, in detection order."""
        labels = {d.name: d.label for d in frame.detections if d.name}
        clouds = frame_clouds(frame, self.cloud_params)
        for name, cloud in clouds.items():
            self.add_view(name, labels[name], cloud, frame.frame_id)
        return list(clouds)

    def add_view(self, name: str, label: str, cloud: o3d.geometry.PointCloud, frame_id: str) -> ObjectTrack:
        """Fuse one cleaned cloud of ``name`` into its track (started if new)."""
        track = self._tracks.get(name)
        if track is None:
            track = self._tracks[name] = ObjectTrack.start(name, label, cloud, frame_id, self.fusion)
        else:
            track.fuse(cloud, frame_id, self.cloud_params, self.fusion, static=name in self.static)
        return track

    def missing(self, frame: Frame, min_pixels: int = 0) -> list[str]:
        """Tracks that ``frame`` should have shown (see :func:`in_plain_view`) but did not detect:
        evidence that the object is no longer where its track puts it."""
        detected = frame.detected()
        return [t.name for t in self._tracks.values()
                if t.name not in detected and in_plain_view(t, frame, min_pixels, self.cloud_params.max_range)]

    def forget(self, name: str) -> ObjectTrack | None:
        """Drop a track (the object is gone, or is being re-surveyed from scratch)."""
        return self._tracks.pop(name, None)

    def get(self, name: str) -> ObjectTrack | None:
        """``name``'s track, or None when nothing of it is tracked."""
        return self._tracks.get(name)

    def __getitem__(self, name: str) -> ObjectTrack:
        return self._tracks[name]

    def __contains__(self, name: object) -> bool:
        return name in self._tracks

    def __iter__(self) -> Iterator[ObjectTrack]:
        return iter(list(self._tracks.values()))

    def __len__(self) -> int:
        return len(self._tracks)

    def names(self) -> list[str]:
        """The names of the objects tracked, in the order their tracks were started."""
        return list(self._tracks)
