"""Running episodes: wiring a task to a world, skills, a camera, a VLM and the executive.

This is the one place where the rooms meet. The executive only sees protocols; the runner picks
their implementations from a :class:`RunConfig` — which world, which VLM, in-process skills or
Zenoh — runs an episode, asks the world for the truth afterwards and assembles the report.
A :class:`Session` keeps what can be reused between episodes of one task (the world, the grounded
task and the planner's cache), which is what makes symbolic campaigns fast.
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field
from typing import Any, Callable

from vap_bt import plugins
from vap_bt.bt.context import VerifyMode
from vap_bt.bt.executive import EpisodeOutcome, Executive, ExecutiveSettings
from vap_bt.domain.planner import Planner
from vap_bt.perception.verification import VoteSettings
from vap_bt.perception.vlm import MeteredVLM
from vap_bt.report import versions
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
    vlm: str = "symbolic"
    vlm_error: float = 0.05
    transport: str = "inproc"
    planner: str = "fast-downward"

    @classmethod
    def from_task(cls, task: Task, **overrides) -> "RunConfig":
        o = task.options
        base = cls(world=task.spec.world, verify=o.verify, budget=o.budget, paraphrases=o.paraphrases,
                   max_replans=o.max_replans, max_ticks=o.max_ticks, injection=o.injection)
        return cls(**{**asdict(base), **{k: v for k, v in overrides.items() if v is not None}})


def make_world(task: Task, cfg: RunConfig) -> World:
    situations = SituationModel(enabled=cfg.injection, seed=cfg.seed)
    if cfg.world == "symbolic":
        from vap_bt.sim.symbolic import SymbolicWorld

        return SymbolicWorld(task.planning, situations, seed=cfg.seed)
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
    if cfg.vlm == "symbolic":
        from vap_bt.sim.symbolic_vlm import SymbolicVLM

        rooms = frozenset(o for o, t in task.planning.objects.items() if t == "room")
        return SymbolicVLM(world.holds, cfg.vlm_error, seed=cfg.seed, rooms=rooms)
    raise ValueError(f"unknown VLM backend {cfg.vlm!r} (symbolic)")


@dataclass
class Session:
    """Everything one task's episodes can share."""

    task: Task
    cfg: RunConfig
    progress: Callable[[str], None] = lambda m: None
    recorder: Any = None  # a vap_bt.viz.TreeRecorder (on_tree + note), or None
    planner: Planner = field(init=False)
    world: World = field(init=False)

    def __post_init__(self) -> None:
        self.planner = Planner(self.task.planning, first_engine=self.cfg.planner, ground_eagerly=True)
        self.world = make_world(self.task, self.cfg)
        self.skills = make_skills(self.task, self.world)
        self._embedded = None
        if self.cfg.transport == "zenoh":
            from vap_bt.transport.embedded import EmbeddedTransport

            self._embedded = EmbeddedTransport(self.world, self.skills)
        # the simulated VLM reads the truth through the same lock the skill servers hold
        self.vlm = make_vlm(self.task, self._embedded.locked if self._embedded else self.world, self.cfg)

    def episode(self, seed: int | None = None) -> dict:
        cfg = self.cfg if seed is None else RunConfig(**{**asdict(self.cfg), "seed": seed})
        self.world.reset(cfg.seed)
        self.vlm.reseed(cfg.seed)
        metered = MeteredVLM(self.vlm)
        skills, camera = self._transport()
        settings = ExecutiveSettings(mode=VerifyMode.parse(cfg.verify), budget=cfg.budget,
                                     vote=VoteSettings(paraphrases=cfg.paraphrases, early_stop=cfg.early_stop),
                                     max_replans=cfg.max_replans, max_ticks=cfg.max_ticks,
                                     tick_period_s=0.0 if cfg.transport == "inproc" else TICK_PERIOD_S)
        t0 = time.perf_counter()
        vlm = metered if settings.mode.pre or settings.mode.eff else None
        progress = self.progress
        if self.recorder is not None:  # progress lines go to the recording's log as well
            progress = lambda m: (self.progress(m), self.recorder.note(m))  # noqa: E731
        executive = Executive(self.task.planning, self.planner, skills, camera, vlm, settings, progress,
                              on_tree=self.recorder.on_tree if self.recorder is not None else None)
        try:
            outcome = executive.run()
        except KeyboardInterrupt:
            if executive.outcome is None:
                raise
            outcome = executive.outcome  # what happened until the interruption is still worth keeping
            outcome.reason = "interrupted"
            rep = self._report(cfg, outcome, metered, time.perf_counter() - t0)
            raise EpisodeInterrupted(rep) from None
        wall = time.perf_counter() - t0
        return self._report(cfg, outcome, metered, wall)

    def close(self) -> None:
        if self._embedded is not None:
            self._embedded.close()
        self.world.close()

    def _transport(self):
        if self._embedded is not None:
            return self._embedded.client, self._embedded.camera
        if self.cfg.transport == "inproc":
            from vap_bt.transport.inprocess import InProcessCamera, InProcessSkillClient

            return InProcessSkillClient(self.skills), InProcessCamera(self.world)
        raise ValueError(f"unknown transport {self.cfg.transport!r}")

    def _report(self, cfg: RunConfig, out: EpisodeOutcome, vlm: MeteredVLM, wall: float) -> dict:
        goal = self.task.planning.goal
        satisfied = all(self.world.holds(l.atom) == l.positive for l in goal)
        ctx = out.context
        return {
            "success": out.success,
            "goal_satisfied": satisfied,
            "reason": out.reason,
            "seed": cfg.seed,
            "task": {"name": self.task.name, "file": str(self.task.path) if self.task.path else None,
                     "instruction": self.task.spec.instruction, "goal": [str(l) for l in goal]},
            "config": asdict(cfg),
            "world": {"name": self.world.name, "injection": self.world_situations()},
            "vlm": {**vlm.describe(), "queries": vlm.total, "by_purpose": dict(vlm.counts)},
            "plans": [p.to_json() for p in out.plans],
            "actions_executed": ctx.actions,
            "situations": [s.to_json() for s in out.situations],
            "injected": [{"action": i.action, "args": list(i.args), "kind": i.kind, "step": i.step}
                         for i in self.world.injected()],
            "replans": out.replans,
            "replan_ms": [round(s * 1000, 3) for s in out.replan_seconds],
            "surveys": out.surveys,
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
