"""PointCloudGeometry: the builder's view of fused RGB-D geometry (open3d underneath).

It ties the three geometric modules together for :class:`~vap_bt.scene.builder.SceneGraphBuilder`:
every frame with depth is integrated into per-object :class:`~vap_bt.scene.tracks.Tracks` (depth
+ mask → cleaned cloud in the map frame → fused per object, a moved object replacing its old
geometry), and the relations among all tracked objects are computed by
:func:`~vap_bt.scene.relations.scene_relations` — once per change, since every relation of one
object depends on the others' boxes.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import DomainKnowledge
from vap_bt.domain.roles import Roles
from vap_bt.robot.frame import Frame
from vap_bt.robot.site_map import SiteMap
from vap_bt.scene.relations import Signatures, scene_relations
from vap_bt.scene.tracks import Tracks

if TYPE_CHECKING:
    import numpy as np


class PointCloudGeometry:
    """Fused tracks of one scene and the geometric relations among them."""

    def __init__(self, knowledge: DomainKnowledge, objects: dict[str, str], site_map: SiteMap,
                 roles: Roles | None = None) -> None:
        self.sig = Signatures(knowledge, objects, roles or Roles())
        self.site_map = site_map
        self.tracks = Tracks(static=site_map.static_names())
        self._relations: dict[frozenset[str], frozenset[Atom]] = {}

    def integrate(self, frame: Frame) -> list[str]:
        names = self.tracks.integrate(frame)
        if names:
            self._relations.clear()
        return names

    def forget(self, names) -> None:
        for n in names:
            if self.tracks.forget(n) is not None:
                self._relations.clear()

    def relations(self, name: str, held=()) -> set[Atom]:
        """Every geometric atom about ``name`` (its support, room, what it blocks or is blocked
        by, whether it is reachable); ``held``: items in the hand, which are in no place."""
        key = frozenset(held)
        atoms = self._relations.get(key)
        if atoms is None:
            atoms = self._relations[key] = scene_relations(self.tracks, self.site_map, self.sig, held=key)
        return {a for a in atoms if name in a.args and (a.args[0] == name or a.predicate == self.sig.roles.blocking)}

    def centroid(self, name: str) -> tuple[float, float, float] | None:
        t = self.tracks.get(name)
        return None if t is None else t.centroid

    def box(self, name: str) -> tuple[float, ...] | None:
        t = self.tracks.get(name)
        return None if t is None else t.box

    def clouds(self) -> dict[str, "np.ndarray"]:
        """Each tracked object's fused cloud, (N, 3) points in the map frame (for the live view)."""
        return {t.name: t.points for t in self.tracks}

    def missing(self, frame: Frame, min_pixels: int = 0) -> list[str]:
        """Tracked objects the frame should have shown and did not (see :meth:`Tracks.missing`)."""
        return self.tracks.missing(frame, min_pixels=min_pixels)
