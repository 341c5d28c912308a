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
* ``edge`` — the egg at the cutting board's front corner (halve_egg), known only as "on the
  cutting board", the robot close in front: the frame aimed at the board's middle cuts the egg at
  its side: ``on(egg, cutting_board)``;
* ``drawer`` — the knife in the drawer pulled half open (halve_egg), seen from the front:
  ``inside(knife, drawer)``.

Each case is staged once (the world built for its task at world seed 0, things moved by hand as a
test does, the robot stood at its stand) and snapshotted with
``pybullet.saveState``; every run restores it, makes a fresh camera service (the skills'
:class:`~skills.views.ViewService` on a fresh kit), and ticks an
:class:`~vap_bt.bt.active_perception.ActivePerception` over a
:class:`~vap_bt.bt.verify_predicate.VerifyPredicate` — the executive's own check, asking the
world's simulated VLM (model fixed; its seed is the run's seed, so the same seed gives the same
first view's answers under every strategy). What the check starts from is belief placed where
the things are (the survey's job is not under test here; in the ``edge`` case, where the task
file's word places the egg): the tool reads the world's truth to stage, as a test does, and to
score; the check perceives. Per case and overall it reports the H2 measure (:mod:`vap_bt.viewpoint_measure`):
viewpoints per uncertain check (unresolved charged the budget K; greedy-all what it visited),
resolution rate and settled accuracy, and the paired difference VLM-guided minus each greedy
kind over the seeds (95 %: a t interval for viewpoints, Newcombe's for the rates).

    .venv/bin/python tools/bench/viewpoint_cases.py [--seeds 30] [--cases occluder,basket,...]
                                                    [--json docs/figures/viewpoint_cases_<commit>.json]

Progress goes to stderr; the markdown table to stdout. An unknown case or fewer than one seed is
one line on stderr and exit code 2.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

import vap_bt  # noqa: E402,F401  (first: it pins numpy's kernels, vap_bt/numerics.py, before pybullet loads numpy)

import numpy as np  # noqa: E402
import pybullet as pb  # noqa: E402
from py_trees.common import Status  # noqa: E402

from skills.kit import Kit  # noqa: E402
from skills.views import ViewService  # noqa: E402
from tools.bench.intervals import paired_difference, paired_t, wilson  # noqa: E402
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
from vap_bt.scene.builder import SUPPORT_MARGIN  # noqa: E402
from vap_bt.scene.identity import SEEN_RADIUS, Believed, Identifier, IdentifyingCamera  # noqa: E402
from vap_bt.settings import RunConfig  # noqa: E402
from vap_bt.sim.pybullet_world import PybulletWorld  # noqa: E402
from vap_bt.taskfile import load  # noqa: E402
from vap_bt.viewpoint_measure import uncertain_checks, viewpoint_measure  # noqa: E402

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
    #: how far from its point belief allows each to be (the identifier's radius; default a sighting's)
    radius: dict[str, float] = field(default_factory=dict)


# -- staging: the world's truth is read here, as a test stages a scene, never by the check -------

def stand(world: PybulletWorld, point, distance: float, bearing: float) -> None:
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


def believed_where_they_are(world: PybulletWorld, atom: Atom) -> Staged:
    """Belief puts each of the atom's things where it truly is (where a camera aims at it)."""
    return Staged({name: world.aim_at((name,)).point for name in atom.args})


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
        """Where belief puts ``names``: the middle of their staged points."""
        points = [self.staged.points[n] for n in names if n in self.staged.points]
        return Aim(tuple(names), tuple(map(float, np.mean(points, axis=0))) if points else None)

    def identify(self, frame):
        """Name the frame's detections as the executive would, against the staged belief."""
        state = self.world.state()
        belief = {n: Believed(p, self.staged.radius.get(n, SEEN_RADIUS)) for n, p in self.staged.points.items()
                  if self.world.site_map().piece(n) is None}
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
                               viewpoints=ViewpointStrategy(strategy), feels=lambda atom: False)
        node = ActivePerception(ctx, VerifyPredicate(ctx, self.atom, self.case.expected), "pre", None, 0)
        try:
            for _ in range(MAX_TICKS):
                node.tick_once()
                if node.status != Status.RUNNING:
                    break
            else:
                raise RuntimeError(f"{self.case.name}: the check did not end in {MAX_TICKS} ticks")
        finally:
            ctx.close()
        v = ctx.board.verifications[-1]
        return {**v.to_json(), "truth": self.truth}

    def close(self) -> None:
        """Let go of the world."""
        self.world.close()


# -- the five cases -------------------------------------------------------------------------------

#: the map frame's "toward the robot" for furniture against the back wall (every case's faces -y)
FRONT = -math.pi / 2


def occluder(world: PybulletWorld) -> Staged:
    """pick_plate as laid out: the bowl stands between the robot and the plate; the robot 1.4 m
    in front of the table."""
    stand(world, world.truth.center("plate"), 1.4, FRONT)
    return believed_where_they_are(world, Atom.parse("on(plate, dining_table)"))


def basket(world: PybulletWorld) -> Staged:
    """A log laid at the bottom of the basket (0.3 m deep), the robot 2.2 m off to the side of its
    front, where the camera looks at the rim more than over it."""
    b = world.scene.things["basket"].furniture
    move_item(world, "wood1", b.to_world((0.0, 0.0, 0.06)))
    stand(world, b.to_world((0.0, 0.0, 0.0)), 2.2, FRONT - 0.6)
    return believed_where_they_are(world, Atom.parse("inside(wood1, basket)"))


def far(world: PybulletWorld) -> Staged:
    """The cup on the coffee table seen from the far side of the living room, 3.5 m away."""
    stand(world, world.truth.center("cup"), 3.5, FRONT)
    return believed_where_they_are(world, Atom.parse("on(cup, coffee_table)"))


#: where the egg lies on the cutting board in the ``edge`` case (the board's frame: m to its side,
#: m toward its front) and how far in front of the board's middle the robot stands
EDGE_EGG, EDGE_STAND = (0.24, 0.12), 0.9


def edge(world: PybulletWorld) -> Staged:
    """The egg at the cutting board's front corner, known only as "on the cutting board" (the
    task file's word: belief aims at the board's middle and allows the egg anywhere on it, as
    the executive's belief of a thing never seen does); the robot close in front of the board,
    so that the frame aimed at the board's middle cuts the egg at its side."""
    board = world.scene.things["cutting_board"].furniture
    w, d, h = board.kind.size
    z = world.truth.center("egg")[2] - h
    move_item(world, "egg", board.to_world((EDGE_EGG[0], EDGE_EGG[1], h + z)))
    top = tuple(map(float, board.to_world((0.0, 0.0, h))))
    stand(world, top, EDGE_STAND, FRONT)
    return Staged({"egg": top, "cutting_board": top}, {"egg": math.hypot(w, d) / 2 + SUPPORT_MARGIN})


def drawer(world: PybulletWorld) -> Staged:
    """The drawer pulled half its travel, the knife riding in it; the robot 1.3 m in front."""
    t = world.scene.things["drawer"]
    h = t.hinge
    half = h.full / 2
    pb.resetJointState(h.body, h.joint, half, physicsClientId=world.cid)
    move_item(world, "knife", h.transform(half)[1](world.truth.center("knife")))
    stand(world, t.furniture.to_world((0.0, 0.0, 0.0)), 1.3, FRONT)
    return believed_where_they_are(world, Atom.parse("inside(knife, drawer)"))


CASES = {c.name: c for c in (
    Case("occluder", "pick_plate", "on(plate, dining_table)", True, occluder, "the plate behind the bowl"),
    Case("basket", "store_firewood", "inside(wood1, basket)", True, basket, "a log deep in the basket, from the side"),
    Case("far", "collect_cup", "on(cup, coffee_table)", True, far, "a small cup 3.5 m away"),
    Case("edge", "halve_egg", "on(egg, cutting_board)", True, edge, "the egg cut by the image's side"),
    Case("drawer", "halve_egg", "inside(knife, drawer)", True, drawer, "the knife in a half-open drawer"),
)}


# -- the bench: every case, strategy and seed; the measure and the paired differences -------------

#: what the bench keeps of each check (the measure's fields, and how many views it took)
KEPT = ("phase", "action", "predicate", "expected", "value", "outcome", "basis", "views", "viewpoints",
        "first_settled", "truth")


def run(names: list[str], seeds: range, progress: Progress) -> list[dict]:
    """One row per (case, seed, strategy): the check's verification, trimmed to :data:`KEPT`."""
    rows = []
    for name in names:
        bench = CaseBench(CASES[name])
        try:
            for seed in seeds:
                for strategy in STRATEGIES:
                    v = bench.check(strategy, seed)
                    rows.append({"case": name, "seed": seed, "strategy": strategy, **{k: v[k] for k in KEPT}})
                    progress.step()
        finally:
            bench.close()
    return rows


def report_of(rows: list[dict], strategy: str) -> dict:
    """The rows of one strategy as the part of an episode's report the H2 measure reads."""
    return {"config": {"viewpoints": strategy, "budget": BUDGET},
            "verifications": [r for r in rows if r["strategy"] == strategy]}


def paired(rows: list[dict], other: str) -> dict:
    """VLM-guided minus ``other`` over the seeds whose first view did not settle (the same first
    picture and answers under both: the pairs): viewpoints per check with a 95 % t interval,
    resolution with Newcombe's interval for paired rates, settled accuracy over the seeds both
    resolved, likewise."""
    def checks(strategy):
        mine = [r for r in rows if r["strategy"] == strategy]
        return {(r["case"], r["seed"]): c for r, c in zip([r for r in mine if r["first_settled"] is False],
                                                          uncertain_checks(report_of(rows, strategy)))}
    a, b = checks("vlm"), checks(other)
    keys = sorted(a.keys() & b.keys())
    d, lo, hi = paired_t([a[k].charged - b[k].charged for k in keys])
    res = _paired_rates([(a[k].resolved, b[k].resolved) for k in keys])
    both = [k for k in keys if a[k].correct is not None and b[k].correct is not None]
    acc = _paired_rates([(a[k].correct, b[k].correct) for k in both])
    return {"pairs": len(keys), "viewpoints": [d, lo, hi], "resolution": res, "accuracy_pairs": len(both),
            "accuracy": acc}


def _paired_rates(pairs: list[tuple[bool, bool]]) -> list[float]:
    """First rate minus second over paired outcomes, with Newcombe's 95 % interval."""
    both = sum(x and y for x, y in pairs)
    only_a, only_b = sum(x and not y for x, y in pairs), sum(y and not x for x, y in pairs)
    d, lo, hi = paired_difference(both, only_b, only_a, len(pairs) - both - only_a - only_b)
    return [d, lo, hi]


def figures(rows: list[dict]) -> dict:
    """Per strategy the H2 measure (no per-check list: the rows hold it) and the paired differences."""
    measures = {}
    for s in STRATEGIES:
        m = viewpoint_measure(report_of(rows, s))
        m["histogram"] = {str(k): n for k, n in sorted(_counts([c["charged"] for c in m.pop("checks")]).items())}
        m["resolution_95"] = list(wilson(m["resolved"], m["uncertain"])) if m["uncertain"] else None
        m["accuracy_95"] = list(wilson(m["correct"], m["scored"])) if m["scored"] else None
        measures[s] = m
    return {"checks": len({(r["case"], r["seed"]) for r in rows}), "strategies": measures,
            "vlm_minus": {o: paired(rows, o) for o in STRATEGIES if o != "vlm"}}


def _counts(values: list[int]) -> dict[int, int]:
    out: dict[int, int] = {}
    for v in values:
        out[v] = out.get(v, 0) + 1
    return out


def _num(x: float | None, fmt: str = "{:.2f}") -> str:
    return "–" if x is None or (isinstance(x, float) and math.isnan(x)) else fmt.format(x)


def _interval(t: list[float], fmt: str = "{:+.2f}") -> str:
    d, lo, hi = t
    return "–" if math.isnan(d) else f"{fmt.format(d)} [{fmt.format(lo)}, {fmt.format(hi)}]"


def markdown(result: dict) -> str:
    """The result as two markdown tables: the measure per case and strategy, and the paired
    differences VLM-guided minus each greedy kind."""
    out = ["| case | strategy | uncertain checks | viewpoints per check | resolved | settled accuracy |",
           "|---|---|---:|---:|---:|---:|"]
    sections = [*result["cases"].items(), ("overall", result["overall"])]
    for name, f in sections:
        for s, m in f["strategies"].items():
            out.append(f"| {name} | {s} | {m['uncertain']} of {f['checks']} | {_num(m['viewpoints_per_check'])} | "
                       f"{m['resolved']} ({_num(m['resolution_rate'], '{:.0%}')}) | "
                       f"{m['correct']}/{m['scored']} ({_num(m['settled_accuracy'], '{:.0%}')}) |")
    out += ["", "| case | VLM-guided minus | pairs | viewpoints per check (95 % t) | resolution rate (95 %) "
                "| settled accuracy, both settled (95 %) |", "|---|---|---:|---|---|---|"]
    for name, f in sections:
        for o, d in f["vlm_minus"].items():
            out.append(f"| {name} | {o} | {d['pairs']} | {_interval(d['viewpoints'])} | "
                       f"{_interval(d['resolution'], '{:+.0%}')} | "
                       f"{_interval(d['accuracy'], '{:+.0%}')} (n={d['accuracy_pairs']}) |")
    return "\n".join(out)


def main(argv: list[str] | None = None) -> int:
    """Run the bench; print the tables; write the JSON."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seeds", type=int, default=30, help="VLM seeds per case (default 30)")
    ap.add_argument("--cases", default=",".join(CASES), help=f"comma-separated, of {', '.join(CASES)}")
    ap.add_argument("--json", help="where to write the result (default: none)")
    args = ap.parse_args(argv)
    names = [n.strip() for n in args.cases.split(",") if n.strip()]
    unknown = [n for n in names if n not in CASES]
    if unknown or args.seeds < 1:
        print(f"--cases: unknown case {unknown[0]!r} (of {', '.join(CASES)})" if unknown
              else "--seeds: at least 1", file=sys.stderr)
        return 2
    t0 = time.time()
    rows = run(names, range(args.seeds), Progress(len(names) * args.seeds * len(STRATEGIES), "checks"))
    result = {"seeds": args.seeds, "budget": BUDGET, "wall_s": round(time.time() - t0, 1),
              "cases": {n: {"what": CASES[n].what, "task": CASES[n].task, "atom": CASES[n].atom,
                            "truth": next(r["truth"] for r in rows if r["case"] == n),
                            **figures([r for r in rows if r["case"] == n])} for n in names},
              "overall": figures(rows), "rows": rows}
    print(markdown(result))
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
