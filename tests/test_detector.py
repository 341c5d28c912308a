"""The simulated detector (vap_bt.sim.detector): labels, not names; misses, false positives,
confusions and rough masks at the documented rates; the same picture, the same detections.

The statistical tests draw the detector many times over synthetic segmentations (one key per
draw, as a new picture would be) and check each rate against the model's own figure with a
binomial margin of four standard deviations: loose enough never to fail by chance, tight enough
to fail if the model's behaviour changed.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from vap_bt.robot.camera import Aim, Viewpoint
from vap_bt.robot.frame import detection_index
from vap_bt.robot.labels import class_of, label_of
from vap_bt.sim.detector import DetectorModel

from conftest import HOUSEHOLD_TASKS, TREES

W, H = 320, 240
MODEL = DetectorModel()


def squares(*sides: int) -> np.ndarray:
    """A segmentation with one square instance of each side (pixels), side by side."""
    img = np.full((H, W), -1, np.int32)
    x = 5
    for i, s in enumerate(sides):
        img[20:20 + s, x:x + s] = i
        x += s + 5
    return img


def rate_bounds(p: float, n: int) -> tuple[float, float]:
    sd = math.sqrt(max(p * (1 - p), 1e-4) / n)
    return p - 4 * sd, p + 4 * sd


def draw(model: DetectorModel, inst, names, labels, visible=None, n=600, classes=("cup",)):
    depth = np.full(inst.shape, 1.5, np.float32)
    pixels = [int((inst == i).sum()) for i in range(len(names))]
    return [model.detect(inst, names, pixels, visible or [1.0] * len(names), labels, depth, classes, f"test|{k}")
            for k in range(n)]


def test_misses_grow_as_things_shrink_in_the_image():
    inst = squares(10, 30, 80)  # 100, 900, 6400 px of a 320 x 240 image: small, medium, large in COCO's bins
    names = ["a", "b", "c"]
    n = 600
    runs = draw(MODEL.__class__(false_positives=0.0, confusion=0.0), inst, names, ["cup"] * 3, n=n)
    found = {name: sum(name in r.instances for r in runs) / n for name in names}
    for name, side in zip(names, (10, 30, 80)):
        lo, hi = rate_bounds(MODEL.recall(side * side, W * H), n)
        assert lo <= found[name] <= hi, (name, found[name], MODEL.recall(side * side, W * H))
    assert found["a"] < found["b"] < found["c"]
    assert MODEL.recall(90, W * H) == pytest.approx(MODEL.recall_small)  # below the small bin's centre
    assert MODEL.recall(8, W * H) >= 0.0 and MODEL.pixel_threshold(W, H) == 38


def test_misses_grow_as_things_hide():
    inst = squares(80, 80)
    n = 600
    runs = draw(MODEL.__class__(false_positives=0.0, confusion=0.0), inst, ["whole", "hidden"], ["cup"] * 2,
                visible=[1.0, 0.4], n=n)
    whole = sum("whole" in r.instances for r in runs) / n
    hidden = sum("hidden" in r.instances for r in runs) / n
    expect = MODEL.recall(6400, W * H, 0.4)
    assert expect == pytest.approx(MODEL.recall_large * 0.4 ** 1.5, rel=0.05)
    lo, hi = rate_bounds(expect, n)
    assert lo <= hidden <= hi and hidden < 0.5 * whole
    # a thing covering a tenth of the image is not hidden by the frame cutting it
    assert MODEL.recall(0.2 * W * H, W * H, 0.1) == pytest.approx(MODEL.recall_large)


def test_labels_are_confused_with_similar_classes_at_the_documented_rate():
    inst = squares(80)
    n = 3000
    runs = draw(MODEL.__class__(false_positives=0.0), inst, ["cup1"], ["cup"], n=n)
    found = [r.detections[0].label for r in runs if r.instances]
    other = sum(label != "cup" for label in found) / len(found)
    lo, hi = rate_bounds(MODEL.confusion, len(found))
    assert lo <= other <= hi, other
    assert set(found) == {"cup", "mug", "bottle"}  # cup's partners
    # a class without partners is never confused
    runs = draw(MODEL.__class__(false_positives=0.0), inst, ["knife"], ["knife"], n=300)
    assert {d.label for r in runs for d in r.detections} == {"knife"}


def test_false_positives_come_at_the_documented_rate_with_a_class_of_the_scene():
    inst = squares(60)
    n = 2000
    runs = draw(MODEL.__class__(recall_large=0.0, recall_medium=0.0, recall_small=0.0), inst, ["cup"], ["cup"], n=n,
                classes=("plate", "table"))
    counts = [sum(1 for x in r.instances if x == "") for r in runs]
    mean = sum(counts) / n
    sd = math.sqrt(MODEL.false_positives / n)
    assert MODEL.false_positives - 4 * sd <= mean <= MODEL.false_positives + 4 * sd, mean
    labels = {d.label for r in runs for d, x in zip(r.detections, r.instances) if x == ""}
    assert labels == {"plate", "table"}
    assert all(d.score < 0.8 and d.pixels >= MODEL.pixel_threshold(W, H) for r in runs
               for d, x in zip(r.detections, r.instances) if x == "")


def test_masks_are_not_the_renderers_exact_ones():
    inst = squares(40)
    truth = inst == 0
    runs = draw(MODEL.__class__(false_positives=0.0), inst, ["cup"], ["cup"], n=300)
    ious = [np.logical_and(r.masks == 0, truth).sum() / np.logical_or(r.masks == 0, truth).sum()
            for r in runs if r.instances]
    assert all(iou > 0.6 for iou in ious) and sum(iou < 1.0 for iou in ious) > 0.9 * len(ious)
    grown = [(r.masks == 0).sum() > truth.sum() for r in runs if r.instances]
    assert 0.2 < sum(grown) / len(grown) < 0.8  # dilated about as often as eroded


def test_the_same_picture_gives_the_same_detections():
    inst = squares(10, 30, 80)
    depth = np.full(inst.shape, 1.5, np.float32)
    args = (inst, ["a", "b", "c"], [100, 900, 6400], [1.0] * 3, ["cup"] * 3, depth, ("cup",))
    one, two = MODEL.detect(*args, "seed|picture"), MODEL.detect(*args, "seed|picture")
    assert one.detections == two.detections and np.array_equal(one.masks, two.masks)
    others = [MODEL.detect(*args, f"seed|picture {k}") for k in range(20)]
    assert any(o.instances != one.instances or not np.array_equal(o.masks, one.masks) for o in others)


# -- in the worlds: a detection carries a class, never an instance's name ------------------------------


def _no_names(frame, instances: set[str], classes: set[str]) -> None:
    for d in frame.detections:
        assert d.name == "", d
        assert d.label in classes and d.label not in instances - classes, d
        for a in d.relations:
            for x in a.args:
                assert x not in instances or x in classes, (a, d)  # never an item's own name
                k = detection_index(x)
                assert k is None or 0 <= k < len(frame.detections)


@pytest.mark.parametrize("name", HOUSEHOLD_TASKS)
def test_symbolic_frames_carry_classes_and_relations_name_no_item(name):
    from vap_bt.scene.builder import SceneGraphBuilder
    from vap_bt.sim.symbolic import SymbolicWorld
    from vap_bt.taskfile import load

    task = load(TREES / name).planning
    world = SymbolicWorld(task, seed=0)
    site = world.site_map()
    items = {o for o in task.objects if site.piece(o) is None and o not in site.static_names()}
    classes = {label_of(o, site) for o in task.objects}
    b = SceneGraphBuilder(task.knowledge, task.objects, site)
    seen = 0
    for room in site.rooms:
        for view in b.views(room.name):
            if world.goto_view(view):
                frame = world.capture(view.aim)
                seen += len(frame.detections)
                _no_names(frame, items, classes)
                record = world.captures.get(frame.frame_id)
                assert len(record.instances) == len(frame.detections)
                assert all(label_of(o, site) == d.label for o, d in zip(record.instances, frame.detections))
    assert seen


@pytest.mark.slow
def test_pybullet_frames_carry_classes_never_instance_names():
    from skill_runs import camera, pybullet

    from vap_bt.scene.builder import SceneGraphBuilder

    world = pybullet("retrieve_bottles")
    try:
        site = world.site_map()
        items = set(world.layout.items)
        classes = {label_of(o, site) for o in world.scene.things} | {class_of(o) for o in items}
        view = camera(world)
        b = SceneGraphBuilder(world.task.planning.knowledge, world.task.planning.objects, site)
        found = []
        for v in b.views("garden")[:3]:
            if view.goto_view(v):
                frame = view.capture(v.aim)
                _no_names(frame, items, classes)
                record = world.captures.get(frame.frame_id)
                assert record.marked and len(record.instances) == len(frame.detections)
                found += [x for x in record.instances if x]
        assert {"bottle1", "garden_bench"} & set(found)
        # the same picture again: the same detections
        again = view.capture()
        assert again.detections == view.capture().detections
    finally:
        world.close()
