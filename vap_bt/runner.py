"""Running episodes: wiring a task to a world, skills, robot interfaces, a VLM and the executive.

This is the one place where the rooms meet. The executive only sees protocols; the runner picks
their implementations from a :class:`RunConfig` — which world, which VLM, in-process skills or
Zenoh — runs an episode, and scores it against the world's oracle for the report: whether the
goal really holds, which situations the world injected, and how well each scene graph the robot
built matched the world at the moment it was built. The oracle stays here and in the world; the
executive is handed robot interfaces, skills and a VLM, never the world.

A :class:`Session` keeps what can be reused between episodes of one task (the world, the grounded
task and the planner's cache), which is what makes symbolic campaigns fast.
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field
from typing import Any, Callable

from vap_bt import plugins
from vap_bt.bt.context import VerifyMode
from vap_bt.bt.executive import EpisodeOutcome, Executive, ExecutiveSettings, Survey
from vap_bt.domain.planner import Planner
from vap_bt.perception.profile import PerceptionProfile, resolve
from vap_bt.perception.verification import VoteSettings
from vap_bt.perception.vlm import MeteredVLM, Paraphraser
from vap_bt.report import versions
from vap_bt.scene.graph import SceneGraph
from vap_bt.sim.detector import DetectorModel
from vap_bt.sim.graph_score import score_graph
from vap_bt.sim.situations import SituationModel
from vap_bt.skill import Skill
from vap_bt.taskfile import Task
from vap_bt.world import World


class EpisodeInterrupted(KeyboardInterrupt):
    """Ctrl-C during an episode; carries the report of the episode up to that moment."""

    def __init__(self, report: dict) -> None:
        super().__init__("interrupted")
        self.report = report


#: how often the tree is ticked while a goal is in flight on a skill server
TICK_PERIOD_S = 0.002
_DETECTOR = DetectorModel()


@dataclass
class RunConfig:
    world: str = "symbolic"
    seed: int = 0
    verify: str = "both"
    budget: int = 3
    paraphrases: int = 5
    early_stop: bool = False
    max_replans: int = 10
    max_ticks: int = 2000
    injection: bool = True
    vlm: str = "sim"
    vlm_error: float = 0.05
    miss_rate: float = _DETECTOR.miss_rate  # symbolic detector
    relation_error: float = _DETECTOR.relation_error  # symbolic relation detector
    transport: str = "inproc"
    planner: str = "fast-downward"

    @classmethod
    def from_task(cls, task: Task, **overrides) -> "RunConfig":
        o = task.options
        base = cls(world=task.spec.world, verify=o.verify, budget=o.budget, paraphrases=o.paraphrases,
                   max_replans=o.max_replans, max_ticks=o.max_ticks, injection=o.injection)
        return cls(**{**asdict(base), **{k: v for k, v in overrides.items() if v is not None}})

    def detector(self) -> DetectorModel:
        return DetectorModel(miss_rate=self.miss_rate, relation_error=self.relation_error)


def make_world(task: Task, cfg: RunConfig) -> World:
    situations = SituationModel(enabled=cfg.injection, seed=cfg.seed)
    if cfg.world == "symbolic":
        from vap_bt.sim.symbolic import SymbolicWorld

        return SymbolicWorld(task.planning, situations, seed=cfg.seed, detector=cfg.detector())
    if cfg.world == "pybullet":
        from vap_bt.sim.pybullet_world import PybulletWorld

        return PybulletWorld(task, seed=cfg.seed, injection=cfg.injection)
    raise ValueError(f"unknown world {cfg.world!r} (symbolic, pybullet)")


def make_skills(task: Task, world: World) -> dict[str, Skill]:
    """The installed skill plugins, plus — in the symbolic world only — a world-performed skill
    for each domain action no plugin implements (the symbolic world knows every action)."""
    skills = plugins.instantiate(world)
    if world.name == "symbolic":
        from skills.base import WorldActionSkill

        for name in task.planning.knowledge.schemas:
            if name not in skills:
                cls = type(f"Symbolic_{name}", (WorldActionSkill,), {"action": name, "robot": "sim"})
                skills[name] = cls(world)
    return skills


def make_vlm(task: Task, world: World, cfg: RunConfig):
    """The world-side simulated VLM, reading the world's capture records."""
    if cfg.vlm == "sim":
        from vap_bt.sim.sim_vlm import SimVLM

        rooms = frozenset(o for o, t in task.planning.objects.items() if t == "room")
        return SimVLM(world.captures.get, cfg.vlm_error, seed=cfg.seed, rooms=rooms)
    raise ValueError(f"unknown VLM backend {cfg.vlm!r} (sim)")


def make_profile(task: Task, vlm) -> PerceptionProfile:
    """The task's perception profile; a VLM that writes paraphrases writes the missing ones."""
    if isinstance(vlm, Paraphraser):
        return resolve(task.planning.knowledge, task.perception_file, paraphraser=vlm)
    return task.profile


def make_geometry(cfg: RunConfig):
    """The executive's point-cloud fusion (a factory the builder calls), for worlds whose frames
    carry depth; the symbolic world's frames have none."""
    if cfg.world == "symbolic":
        return None
    from vap_bt.scene.geometry import PointCloudGeometry

    return PointCloudGeometry


@dataclass
class Session:
    """Everything one task's episodes can share."""

    task: Task
    cfg: RunConfig
    progress: Callable[[str], None] = lambda m: None
    recorder: Any = None  # a vap_bt.viz.TreeRecorder (on_tree + note), or None
    planner: Planner = field(init=False)
    world: World = field(init=False)
    #: the last episode's outcome (belief, context, plans), beside its report
    last_outcome: EpisodeOutcome | None = field(init=False, default=None)

    def __post_init__(self) -> None:
        self.planner = Planner(self.task.planning, first_engine=self.cfg.planner, ground_eagerly=True)
        self.world = make_world(self.task, self.cfg)
        self.skills = make_skills(self.task, self.world)
        self.vlm = make_vlm(self.task, self.world, self.cfg)
        self.profile = make_profile(self.task, self.vlm)
        self._embedded = None
        if self.cfg.transport == "zenoh":
            from vap_bt.transport.embedded import EmbeddedTransport

            self._embedded = EmbeddedTransport(self.world, self.skills, vlm=self.vlm)

    def _executive(self, cfg: RunConfig, scores: list[dict]) -> tuple[Executive, MeteredVLM]:
        """A fresh world state for ``cfg.seed`` and an executive wired to it (see the module docstring)."""
        self.world.reset(cfg.seed)
        self.vlm.reseed(cfg.seed)
        skills, robot, vlm = self._transport()
        metered = MeteredVLM(vlm)
        settings = ExecutiveSettings(mode=VerifyMode.parse(cfg.verify), budget=cfg.budget,
                                     vote=VoteSettings(paraphrases=cfg.paraphrases, early_stop=cfg.early_stop),
                                     max_replans=cfg.max_replans, max_ticks=cfg.max_ticks,
                                     tick_period_s=0.0 if cfg.transport == "inproc" else TICK_PERIOD_S)
        progress = self.progress
        if self.recorder is not None:  # progress lines go to the recording's log as well
            progress = lambda m: (self.progress(m), self.recorder.note(m))  # noqa: E731
        executive = Executive(self.task.planning, self.planner, skills, robot, robot, metered, settings, progress,
                              on_tree=self.recorder.on_tree if self.recorder is not None else None,
                              prior=self.task.prior, geometry=make_geometry(cfg),
                              on_survey=lambda survey, graph: scores.append(self._score(survey, graph)),
                              profile=self.profile)
        return executive, metered

    def build_graph(self, seed: int | None = None) -> dict:
        """Only BuildSceneGraph: the initial survey of an episode, scored (for benchmarks)."""
        cfg = self.cfg if seed is None else RunConfig(**{**asdict(self.cfg), "seed": seed})
        scores: list[dict] = []
        executive, metered = self._executive(cfg, scores)
        executive.perceive()
        return {**scores[0], "vlm_queries": metered.total}

    def episode(self, seed: int | None = None) -> dict:
        cfg = self.cfg if seed is None else RunConfig(**{**asdict(self.cfg), "seed": seed})
        t0 = time.perf_counter()
        scores: list[dict] = []
        executive, metered = self._executive(cfg, scores)
        try:
            outcome = self.last_outcome = executive.run()
        except KeyboardInterrupt:
            if executive.outcome is None:
                raise
            outcome = executive.outcome  # what happened until the interruption is still worth keeping
            outcome.reason = "interrupted"
            rep = self._report(cfg, outcome, metered, scores, time.perf_counter() - t0)
            raise EpisodeInterrupted(rep) from None
        wall = time.perf_counter() - t0
        return self._report(cfg, outcome, metered, scores, wall)

    def close(self) -> None:
        if self._embedded is not None:
            self._embedded.close()
        self.world.close()

    def _transport(self):
        if self._embedded is not None:
            return self._embedded.client, self._embedded.robot, self._embedded.vlm_client
        if self.cfg.transport == "inproc":
            from vap_bt.transport.inprocess import InProcessRobot, InProcessSkillClient

            return InProcessSkillClient(self.skills), InProcessRobot(self.world), self.vlm
        raise ValueError(f"unknown transport {self.cfg.transport!r}")

    def _score(self, survey: Survey, graph: SceneGraph) -> dict:
        """Score a freshly built graph against the world now (the executive never sees this)."""
        perceived = set(survey.sweep.detected)
        site = self.world.site_map()
        detectable = {o for o, t in self.task.planning.objects.items() if t != "room"} - set(site.floors())
        s = score_graph(self.world.oracle, self.task.planning, survey.facts, perceived, detectable)
        return {"reason": survey.reason, "build_s": round(survey.sweep.seconds, 4), "views": survey.sweep.frames, **s}

    def _report(self, cfg: RunConfig, out: EpisodeOutcome, vlm: MeteredVLM, scores: list[dict],
                wall: float) -> dict:
        goal = self.task.planning.goal
        oracle = self.world.oracle
        satisfied = all(oracle.holds(l.atom) == l.positive for l in goal)
        ctx = out.context
        detector = cfg.detector() if self.world.name == "symbolic" else getattr(self.world, "detector", None)
        return {
            "success": out.success,
            "goal_satisfied": satisfied,
            "reason": out.reason,
            "seed": cfg.seed,
            "task": {"name": self.task.name, "file": str(self.task.path) if self.task.path else None,
                     "instruction": self.task.spec.instruction, "goal": [str(l) for l in goal],
                     "belief": sorted(map(str, self.task.prior)) if self.task.spec.scene is not None else "problem init"},
            "config": asdict(cfg),
            "world": {"name": self.world.name, "injection": self.world_situations(),
                      "detector": detector.describe() if detector is not None else None},
            "vlm": {**vlm.describe(), "queries": vlm.total, "by_purpose": dict(vlm.counts)},
            "perception": {"graph": {"initial": scores[0] if scores else None, "resurveys": scores[1:]},
                           "surveys": [s.to_json() for s in out.surveys], "profile": self.profile.to_json()},
            "plans": [p.to_json() for p in out.plans],
            "actions_executed": ctx.actions,
            "situations": [s.to_json() for s in out.situations],
            "injected": [{"action": i.action, "args": list(i.args), "kind": i.kind, "step": i.step}
                         for i in oracle.injected()],
            "replans": out.replans,
            "replan_ms": [round(s * 1000, 3) for s in out.replan_seconds],
            "surveys": len(out.surveys),
            "ticks": out.ticks,
            "vlm_queries": vlm.total,
            "verifications": [v.to_json() for v in ctx.verifications],
            "unchecked": [u.to_json() for u in ctx.unchecked.values()],
            "belief_changes": [c.to_json() for c in out.graph.history],
            "wall_s": round(wall, 4),
            "versions": versions(),
        }

    def world_situations(self) -> list[dict]:
        model = getattr(self.world, "situations", None)
        return model.describe() if model is not None else []
