"""The pybullet household is built from each task's layout, and its truth matches the layout."""

from pathlib import Path

import numpy as np
import pytest

from vap_bt.domain.atoms import Atom
from vap_bt.scene.layout import layout_facts
from vap_bt.sim.pb_catalog import load_catalog
from vap_bt.sim.pybullet_world import PybulletWorld
from vap_bt.taskfile import load

TREES = sorted(Path(__file__).resolve().parents[1].joinpath("trees").glob("*.yaml"))
CHECKED = ("on", "inside", "closed", "open", "hand_empty", "reachable", "blocking", "robot_in", "in_room")


def test_catalog_resolves_names():
    cat = load_catalog()
    assert cat.furniture_kind("kitchen_sink", "sink").name == "sink"
    assert cat.furniture_kind("garden_bench", "surface").name == "bench"
    assert cat.furniture_kind("mystery_box", "container").name == "cabinet"
    assert cat.item_kind("wood2", "item").name == "wood"
    assert cat.item_kind("gizmo", "item").name == "item"


@pytest.mark.parametrize("path", TREES, ids=lambda p: p.stem)
def test_initial_truth_matches_layout(path):
    task = load(path)
    world = PybulletWorld(task, seed=0, injection=False, image_size=(160, 120))
    try:
        snap = world.survey()
        expected = {a for a in layout_facts(task.spec.scene) if a.predicate in CHECKED}
        assert expected <= snap.facts, sorted(map(str, expected - snap.facts))
        for a in expected:
            assert world.holds(a)
        names = {o.name for o in snap.objects}
        assert set(task.spec.scene.items) <= names and set(task.spec.scene.furniture) <= names
    finally:
        world.close()


def test_observation_images_and_visibility():
    world = PybulletWorld(load(TREES[0].parent / "pick_plate.yaml"), injection=False)
    try:
        obs = world.observe(("mug",))
        h, w = obs.rgb.shape[:2]
        assert obs.rgb.dtype == np.uint8 and obs.depth.shape == (h, w) and obs.segmentation.shape == (h, w)
        assert 0.1 < float(obs.depth.min()) and float(obs.depth.max()) <= 5.0
        seen = {obs.segment_names[i] for i in np.unique(obs.segmentation) if i >= 0}
        assert {"mug", "bowl", "dining_table"} <= seen
        assert obs.visibility["mug"] > 0.3
        assert Atom("on", ("mug", "dining_table")) in obs.relations
        assert world.holds(Atom("inview", ("mug",)))
        assert obs.intrinsics is not None and len(obs.camera_pose) == 7
    finally:
        world.close()
