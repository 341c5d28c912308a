"""H2 on structural cases: one check from one pybullet state, under each viewpoint strategy.

Paper H2 says VLM-guided viewpoint selection resolves what a first view could not with fewer
viewpoints than greedy perception. Whole episodes mix that with everything else an episode
does; here each case is one *picture problem* built once in the pybullet household, and one
verification check is run from that identical state under each strategy (``vlm``, ``greedy``,
``greedy-all``: :mod:`vap_bt.perception.viewpoints`) with the same seeds of the simulated VLM:

* ``occluder`` — the plate behind the bowl on the dining table (pick_plate), seen over the bowl:
  ``on(plate, dining_table)``;
* ``basket`` — a log deep in the basket (store_firewood), seen from the side at the basket's
  height: ``inside(wood1, basket)``;
* ``far`` — the cup on the coffee table (collect_cup) seen from across the room:
  ``on(cup, coffee_table)``;
* ``edge`` — the egg on the cutting board (halve_egg) where belief puts it a hand's breadth off,
  so that the frame aimed at the belief cuts it at the image's edge: ``on(egg, cutting_board)``;
* ``drawer`` — the knife in the drawer pulled half open (halve_egg), seen from the front:
  ``inside(knife, drawer)``.

Each case is staged once (the world built for its task at world seed 0, things moved by hand as a
test does, the robot stood at its stand and the camera aimed) and snapshotted with
``pybullet.saveState``; every run restores it, makes a fresh camera service (the skills'
:class:`~skills.views.ViewService` on a fresh kit), and ticks an
:class:`~vap_bt.bt.active_perception.ActivePerception` over a
:class:`~vap_bt.bt.verify_predicate.VerifyPredicate` — the executive's own check, asking the
world's simulated VLM (model fixed; its seed is the run's seed, so the same seed gives the same
first view's answers under every strategy). What the check starts from is belief placed where
the things are (the survey's job is not under test here; the ``edge`` case's belief is off on
purpose): the tool reads the world's truth to stage, as a test does, and to score; the check
perceives. Per case and overall it reports the H2 measure (:mod:`vap_bt.viewpoint_measure`):
viewpoints per uncertain check (unresolved charged the budget K; greedy-all what it visited),
resolution rate and settled accuracy, and the paired difference VLM-guided minus each greedy
kind over the seeds with a 95 % t interval.

    .venv/bin/python tools/bench/viewpoint_cases.py [--seeds 30] [--cases occluder,basket,...]
                                                    [--json docs/figures/viewpoint_cases.json]

Progress goes to stderr; the markdown table to stdout.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np
import pybullet as pb
from py_trees.common import Status

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from skills.kit import Kit  # noqa: E402
from skills.views import ViewService  # noqa: E402
from tools.progress import Progress  # noqa: E402
from vap_bt.app.runner import make_world, sim_vlm  # noqa: E402
from vap_bt.bt.active_perception import ActivePerception  # noqa: E402
from vap_bt.bt.context import ExecutionContext  # noqa: E402
from vap_bt.bt.verify_predicate import VerifyPredicate  # noqa: E402
from vap_bt.domain.atoms import Atom  # noqa: E402
from vap_bt.perception.viewpoints import STRATEGIES, ViewpointStrategy  # noqa: E402
from vap_bt.robot.camera import Aim  # noqa: E402
from vap_bt.robot.labels import label_of  # noqa: E402
from vap_bt.scene.graph import SceneGraph  # noqa: E402
from vap_bt.scene.identity import Believed, Identifier, IdentifyingCamera  # noqa: E402
from vap_bt.settings import RunConfig  # noqa: E402
from vap_bt.sim.pybullet_world import PybulletWorld  # noqa: E402
from vap_bt.taskfile import load  # noqa: E402
from vap_bt.viewpoint_measure import summary, UncertainCheck  # noqa: E402

TREES = ROOT / "trees"
#: the viewpoint budget K of every run (the executive's default)
BUDGET = 3
#: ticks a check may take before the bench calls it stuck (a move is one tick in flight)
MAX_TICKS = 400


@dataclass(frozen=True)
class Case:
    """One picture problem: the task whose household it is in, the atom checked (and the value the
    plan expects of it), and how to stage it (move things, stand the robot, aim)."""

    name: str
    task: str
    atom: str
    expected: bool
    stage: Callable[[PybulletWorld], "Staged"]
    what: str


@dataclass(frozen=True)
class Staged:
    """A staged case: where belief puts each of the atom's objects (the aims of the check's
    captures and moves, and the identifier's belief)."""

    points: dict[str, tuple[float, float, float]]


# -- staging: the world's truth is read here, as a test stages a scene, never by the check -------

def stand(world: PybulletWorld, point, distance: float, bearing: float, arm=None) -> None:
    """Stand the robot ``distance`` m from ``point`` (x, y) in the direction ``bearing`` (rad, map
    frame) from it, facing it."""
    x, y = point[0] + distance * math.cos(bearing), point[1] + distance * math.sin(bearing)
    q = np.asarray(world.robot.q(), float).copy()
    q[:3] = (x, y, bearing + math.pi)
    world.robot.reset(q)
    world.localization.reset(world.robot.base_pose)


def move_item(world: PybulletWorld, name: str, position) -> None:
    """Put item ``name`` at ``position`` (its base), at rest."""
    body = world.scene.things[name].body
    _, orn = pb.getBasePositionAndOrientation(body, physicsClientId=world.cid)
    pb.resetBasePositionAndOrientation(body, tuple(map(float, position)), orn, physicsClientId=world.cid)
    pb.resetBaseVelocity(body, (0, 0, 0), (0, 0, 0), physicsClientId=world.cid)


def settle(world: PybulletWorld, steps: int = 60) -> None:
    """Let what was moved come to rest."""
    for _ in range(steps):
        world.step()


def believed_where_they_are(world: PybulletWorld, atom: Atom, off=(0.0, 0.0, 0.0)) -> Staged:
    """Belief puts each of the atom's things where it truly is (the item ``off`` by so much)."""
    points = {}
    for k, name in enumerate(atom.args):
        p = np.asarray(world.aim_at((name,)).point, float) + (np.asarray(off) if k == 0 else 0.0)
        points[name] = tuple(map(float, p))
    return Staged(points)


# -- one check from the snapshot -------------------------------------------------------------------

class CaseBench:
    """One case's world, staged once and snapshotted; :meth:`check` runs one verification from
    the snapshot under a strategy and a VLM seed."""

    def __init__(self, case: Case) -> None:
        self.case = case
        self.task = load(TREES / f"{case.task}.yaml")
        self.cfg = RunConfig.from_task(self.task, world="pybullet", seed=0, injection=False)
        self.world = make_world(self.task, self.cfg)
        self.atom = Atom.parse(case.atom)
        self.staged = case.stage(self.world)
        settle(self.world)
        site = self.world.site_map()
        objects = self.task.planning.objects
        self.identifier = Identifier({n: label_of(n, site) for n in objects}, site, roles=self.task.profile.roles)
        self.undetectable = frozenset(n for n, t in objects.items() if t == "room") | frozenset(site.floors())
        self.truth = self.world.oracle.holds(self.atom)
        self.snapshot = pb.saveState(physicsClientId=self.world.cid)
        # what pybullet's snapshot does not hold: the motors' set-points and the clock
        self.body_q, self.opening, self.ticks = self.world.robot.q(), self.world.robot.opening, self.world.ticks

    def aim(self, graph: SceneGraph, names: tuple[str, ...]) -> Aim:
        """Where belief puts ``names`` (their mean; the map's things where the map has them)."""
        points = [self.staged.points[n] for n in names if n in self.staged.points]
        return Aim(tuple(names), tuple(map(float, np.mean(points, axis=0))) if points else None)

    def identify(self, frame):
        """Name the frame's detections as the executive would, against the staged belief."""
        state = self.world.state()
        belief = {n: Believed(p) for n, p in self.staged.points.items() if self.world.site_map().piece(n) is None}
        return self.identifier.identify(frame, belief, None, tuple(state.tcp_pose[:3]), state.room)

    def check(self, strategy: str, seed: int) -> dict:
        """One check of the case's atom from the snapshot: the verification as the report writes
        it, with the world's truth beside it."""
        pb.restoreState(self.snapshot, physicsClientId=self.world.cid)
        self.world.robot.reset(self.body_q, self.opening)
        self.world.localization.reset(self.world.robot.base_pose)
        self.world.ticks = self.ticks
        camera = IdentifyingCamera(ViewService(Kit(self.world)), self.identify)
        cfg = RunConfig.from_task(self.task, world="pybullet", seed=seed, injection=False)
        ctx = ExecutionContext(graph=SceneGraph.of_facts(set(), roles=self.task.profile.roles),
                               vlm=sim_vlm(self.task, self.world, cfg), camera=camera, skills=None, budget=BUDGET,
                               aim=self.aim, undetectable=self.undetectable, profile=self.task.profile,
                               viewpoints=ViewpointStrategy(strategy))
        node = ActivePerception(ctx, VerifyPredicate(ctx, self.atom, self.case.expected), "pre", None, 0)
        for _ in range(MAX_TICKS):
            node.tick_once()
            if node.status != Status.RUNNING:
                break
        else:
            raise RuntimeError(f"{self.case.name}: the check did not end in {MAX_TICKS} ticks")
        v = ctx.board.verifications[-1]
        return {**v.to_json(), "truth": self.truth}

    def close(self) -> None:
        """Let go of the world."""
        self.world.close()
