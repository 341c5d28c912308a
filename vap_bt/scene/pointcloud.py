"""From one RGB-D frame to one clean point cloud per detected instance, in the map frame.

A detection's mask selects its pixels of the depth image; open3d back-projects them through the
pinhole intrinsics and the camera's pose (``create_from_depth_image`` with the extrinsic
``inverse(camera_pose)``: open3d's camera frame is the optical frame, x right, y down, z forward).
Pixels without a return (depth 0) or beyond the sensor's useful range are dropped. Only the
mask's bounding box is back-projected (the principal point shifted accordingly), so a small
object costs a small crop, not the whole image; a large mask is sampled every few pixels.

The raw cloud is then cleaned in three steps, each for a failure of real masks and real depth:

1. **voxel downsampling** — pixels on a near surface are far denser than needed and a surface
   seen at a grazing angle is uneven; one point per voxel makes later steps fast and makes a
   fused cloud's density independent of how often a part was seen. A big object (furniture)
   gets coarser voxels, so that no cloud exceeds ``max_points``: outlier removal and DBSCAN
   cost about a microsecond a point, and a box needs no more;
2. **statistical outlier removal** — "flying pixels" at depth edges and mask pixels that bled
   onto the background lie far from their neighbours;
3. **DBSCAN** — a mask that spills over onto another surface (the table behind a cup's rim)
   yields a separate cluster (the neighbourhood is three times the cloud's point spacing, so it
   suits a near cup and a far, thinned table alike). The rule: keep the largest cluster, and any
   other cluster at least ``keep_share`` of its size. A thin occluder can cut one surface into two
   comparable halves, both real; spill and stray returns are small next to the object itself.
   DBSCAN's noise label (-1) is dropped.

All parameters are in :class:`CloudParams`, each with its reason.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import open3d as o3d

from vap_bt.robot.frame import Detection, Frame


@dataclass(frozen=True)
class CloudParams:
    """How depth becomes a cleaned instance cloud (metres unless stated)."""

    #: returns beyond this are dropped: a RealSense D435's depth error grows with the square of
    #: the range and is several cm past 4 m; the household's rooms are 4.4 m deep
    max_range: float = 4.0
    #: voxel edge: a third of the smallest item's diameter (a 2.8 cm stick is still 3 voxels
    #: across); at the camera's 307 px focal length a pixel covers 1 cm at 3 m
    voxel: float = 0.01
    #: statistical outlier removal: the neighbourhood (the ring of voxels around a point on a
    #: surface and a few beyond; more would span much of a 60-point cup) and how many standard
    #: deviations of the mean neighbour distance a point may be off (open3d's tutorial value)
    outlier_neighbors: int = 12
    outlier_std: float = 2.0
    #: most points of one cloud (a view's or a fused object's): bounds the cost of the cleaning
    #: steps (about a microsecond a point each); a 1.1 x 0.7 m table top at 600 points is still
    #: sampled every 3.5 cm, and a box needs no more
    max_points: int = 600
    #: most pixels back-projected per instance (sampled with a stride above it): about three
    #: times ``max_points``, so the voxels still average a few pixels each, while a table filling
    #: half the image costs a fraction of a millisecond to back-project and voxelize
    max_pixels: int = 2000
    #: DBSCAN neighbourhood in point spacings (:func:`spacing`): three, so a surface stays one
    #: cluster however sparsely it is sampled, while a gap of a few spacings (3 cm at the
    #: finest) splits it
    cluster_eps_spacings: float = 3.0
    #: neighbours for a DBSCAN core point; 4 keeps a thin edge such as a stick in one piece
    cluster_min_points: int = 4
    #: clusters at least this share of the largest are kept (see the module docstring)
    keep_share: float = 0.5
    #: fewer points than this after cleaning: the view says nothing reliable about the object
    min_points: int = 8


def _crop(mask: np.ndarray) -> tuple[slice, slice] | None:
    """Rows and columns of the mask's bounding box, or None for an empty mask."""
    rows = np.flatnonzero(mask.any(axis=1))
    if rows.size == 0:
        return None
    cols = np.flatnonzero(mask.any(axis=0))
    return slice(int(rows[0]), int(rows[-1]) + 1), slice(int(cols[0]), int(cols[-1]) + 1)


def backproject(depth: np.ndarray, mask: np.ndarray, intrinsics: tuple[float, float, float, float],
                camera_pose: np.ndarray, max_range: float, max_pixels: int | None = None) -> o3d.geometry.PointCloud:
    """Points (map frame) of the pixels in ``mask`` with a depth in (0, ``max_range``]; with
    ``max_pixels``, a mask larger than that is sampled every ``stride`` pixels in both axes."""
    import open3d as o3d  # on first use: a run without depth never pays its 2 s

    box = _crop(mask)
    if box is None:
        return o3d.geometry.PointCloud()
    rows, cols = box
    inside = mask[rows, cols]
    crop = np.where(inside, depth[rows, cols], 0.0).astype(np.float32)
    stride = 1 if max_pixels is None else max(1, math.ceil(math.sqrt(np.count_nonzero(inside) / max_pixels)))
    fx, fy, cx, cy = intrinsics
    h, w = crop.shape
    camera = o3d.camera.PinholeCameraIntrinsic(w, h, fx, fy, cx - cols.start, cy - rows.start)
    extrinsic = np.linalg.inv(np.asarray(camera_pose, dtype=np.float64))  # optical <- map
    return o3d.geometry.PointCloud.create_from_depth_image(
        o3d.geometry.Image(np.ascontiguousarray(crop)), camera, extrinsic,
        depth_scale=1.0, depth_trunc=max_range, stride=stride, project_valid_depth_only=True)


def downsample(cloud: o3d.geometry.PointCloud, params: CloudParams) -> o3d.geometry.PointCloud:
    """Voxel-downsample at ``params.voxel``, coarser while that leaves more than ``max_points``.

    Coarser voxels thin a big object evenly and keep its thin parts (a table's legs), which a
    random subset would break into specks. Points on a surface go with the inverse square of the
    voxel once it is coarser than their spacing; until then (a far surface sampled sparsely) the
    count barely drops, so the voxel grows by at least a quarter a pass. Each pass works on the
    previous pass's few thousand points, a fraction of a millisecond. A voxel averages its
    points, so a support seen only edge-on has its top lowered by up to half a voxel (1.5 cm on
    a table thinned to ``max_points``), which the ``on`` thresholds allow for."""
    voxel = params.voxel
    cloud = cloud.voxel_down_sample(voxel)
    for _ in range(12):  # 1.25 ** 12: from 1 cm to 15 cm, beyond any household object's need
        n = len(cloud.points)
        if n <= params.max_points:
            break
        voxel *= max(math.sqrt(n / params.max_points) * 1.05, 1.25)
        cloud = cloud.voxel_down_sample(voxel)
    return cloud


def spacing(cloud: o3d.geometry.PointCloud, params: CloudParams) -> float:
    """The cloud's typical point spacing: the median nearest-neighbour distance, at least a voxel
    (a far or subsampled surface is sparser than the voxel)."""
    return max(params.voxel, float(np.median(np.asarray(cloud.compute_nearest_neighbor_distance()))))


def keep_clusters(cloud: o3d.geometry.PointCloud, params: CloudParams) -> o3d.geometry.PointCloud:
    """The largest DBSCAN cluster and those at least ``keep_share`` of it; noise dropped."""
    import open3d as o3d  # on first use: a run without depth never pays its 2 s

    eps = params.cluster_eps_spacings * spacing(cloud, params)
    labels = np.asarray(cloud.cluster_dbscan(eps, params.cluster_min_points))
    sizes = np.bincount(labels[labels >= 0])
    if sizes.size == 0:
        return o3d.geometry.PointCloud()
    kept = np.flatnonzero(sizes >= params.keep_share * sizes.max())
    return cloud.select_by_index(np.flatnonzero(np.isin(labels, kept)).tolist())


def clean(cloud: o3d.geometry.PointCloud, params: CloudParams) -> o3d.geometry.PointCloud:
    """Voxel downsampling, statistical outlier removal, then DBSCAN (see the module docstring)."""
    import open3d as o3d  # on first use: a run without depth never pays its 2 s

    cloud = downsample(cloud, params)
    if len(cloud.points) > params.outlier_neighbors:  # too few points have no statistics
        cloud, _ = cloud.remove_statistical_outlier(params.outlier_neighbors, params.outlier_std)
    if len(cloud.points) < params.min_points:
        return o3d.geometry.PointCloud()
    cloud = keep_clusters(cloud, params)
    return cloud if len(cloud.points) >= params.min_points else o3d.geometry.PointCloud()


def instance_cloud(frame: Frame, detection: Detection, params: CloudParams = CloudParams()) -> o3d.geometry.PointCloud | None:
    """The cleaned cloud of one detection; None when the frame has no images or the detection no
    mask, or too little of it survives cleaning."""
    if frame.depth is None or frame.masks is None or frame.intrinsics is None or frame.camera_pose is None:
        return None
    if detection.mask_id < 0:
        return None
    raw = backproject(frame.depth, frame.masks == detection.mask_id, frame.intrinsics, frame.camera_pose,
                      params.max_range, params.max_pixels)
    cloud = clean(raw, params)
    return cloud if len(cloud.points) else None


def frame_clouds(frame: Frame, params: CloudParams = CloudParams()) -> dict[str, o3d.geometry.PointCloud]:
    """Cleaned clouds of every identified detection in ``frame`` that yields one, by the name
    re-identification gave it (an unnamed detection is no known object's)."""
    out: dict[str, o3d.geometry.PointCloud] = {}
    for d in frame.detections:
        if not d.name:
            continue
        cloud = instance_cloud(frame, d, params)
        if cloud is not None:
            out[d.name] = cloud
    return out
