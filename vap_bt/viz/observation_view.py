"""One camera frame as rerun entities: where the camera was, and what it saw.

A :class:`~vap_bt.robot.frame.Frame` from a pixel world carries RGB, metric depth, the
detector's instance masks, pinhole intrinsics and the camera pose in the map frame (the
optical frame: x right, y down, z forward). Under ``world/camera`` it becomes

* a ``Transform3D`` (the pose) and a ``Pinhole`` (the intrinsics, RDF), so the 3-D view shows the
  frustum among the objects' boxes and lifts the depth image into a point cloud;
* ``world/camera/rgb`` (JPEG), ``world/camera/depth`` (millimetres, uint16) and ``world/camera/segmentation``
  (the instance masks), whose ids are shifted by one so that background (-1) is class 0 and each
  detection's class carries its name through an ``AnnotationContext``.

A symbolic frame has none of these, and yields nothing: the verification text still says
what was asked about it.
"""

from __future__ import annotations

import numpy as np
import rerun as rr

from vap_bt.robot.frame import Frame
from vap_bt.robot.state import quat_xyzw

CAMERA = "world/camera"
#: RGB is stored as JPEG (a tenth of the raw size; 0 stores raw pixels); depth as millimetres
JPEG_QUALITY = 90


def has_pixels(obs: Frame | None) -> bool:
    return obs is not None and any(x is not None for x in (obs.rgb, obs.depth, obs.masks))


def camera_entities(obs: Frame) -> list[tuple[str, object]]:
    """(entity path, archetype) pairs for ``obs``; empty when it has no pixels."""
    if not has_pixels(obs):
        return []
    out: list[tuple[str, object]] = []
    shape = next(x.shape for x in (obs.rgb, obs.depth, obs.masks) if x is not None)
    if obs.camera_pose is not None:
        T = np.asarray(obs.camera_pose, dtype=float)
        out.append((CAMERA, rr.Transform3D(translation=T[:3, 3], quaternion=rr.Quaternion(xyzw=quat_xyzw(T[:3, :3])))))
    if obs.intrinsics is not None:
        fx, fy, cx, cy = obs.intrinsics
        out.append((CAMERA, rr.Pinhole(focal_length=[fx, fy], principal_point=[cx, cy],
                                       resolution=[shape[1], shape[0]], camera_xyz=rr.ViewCoordinates.RDF)))
    if obs.rgb is not None:
        rgb = rr.Image(np.ascontiguousarray(obs.rgb, dtype=np.uint8))
        out.append((f"{CAMERA}/rgb", rgb.compress(jpeg_quality=JPEG_QUALITY) if JPEG_QUALITY else rgb))
    if obs.depth is not None:
        depth = np.nan_to_num(np.asarray(obs.depth, dtype=np.float32), nan=0.0, posinf=0.0, neginf=0.0)
        mm = np.clip(np.round(depth * 1000.0), 0, 65535).astype(np.uint16)
        out.append((f"{CAMERA}/depth", rr.DepthImage(mm, meter=1000.0)))
    if obs.masks is not None:
        seg = np.asarray(obs.masks)
        out.append((f"{CAMERA}/segmentation", rr.SegmentationImage((np.clip(seg, -1, 65534) + 1).astype(np.uint16))))
    return out


def segment_classes(obs: Frame) -> rr.AnnotationContext | None:
    """Names for the mask classes (mask id + 1; 0 is background): what the robot took each
    detection for, or its class in brackets where it took it for nothing it knows."""
    named = sorted((d.mask_id, d.name or f"({d.label})") for d in obs.detections if d.mask_id >= 0)
    if obs.masks is None or not named:
        return None
    return rr.AnnotationContext([(0, "background")] + [(i + 1, name) for i, name in named])
