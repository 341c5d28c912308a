"""Running episodes: wiring a task to a world, skills, robot interfaces, a VLM and the executive.

This is the one place where the rooms meet. The executive only sees protocols; the runner picks
their implementations from a :class:`RunConfig` — which world, which VLM, in-process skills or
Zenoh — runs an episode, and scores it against the world's oracle for the report: whether the
goal really holds, which situations the world injected, and how well each scene graph the robot
built matched the world at the moment it was built. The oracle stays here and in the world; the
executive is handed robot interfaces, skills and a VLM, never the world.

A :class:`Session` keeps what can be reused between episodes of one task (the world, the grounded
task and the planner's cache), which is what makes symbolic campaigns fast.

A Ctrl-C may come at any moment — while the world starts, during the survey, mid-plan — and what
was known by then is still worth a report: :class:`EpisodeInterrupted` carries one with every key
a finished report has, filled with what happened so far (nothing yet, before the episode began),
``interrupted`` true and the ``phase`` it stopped in (``starting``, or the executive's phase).
"""

from __future__ import annotations

import time
import typing
from dataclasses import asdict, dataclass, field, replace
from typing import Any, Callable

from vap_bt import plugins
from vap_bt.bt.executive import EpisodeOutcome, Executive, ExecutiveSettings, Survey
from vap_bt.bt.record import Situation
from vap_bt.domain.atoms import Atom
from vap_bt.domain.planner import Planner
from vap_bt.errors import InputError, TransportError
from vap_bt.perception.backends import BACKENDS as HTTP_BACKENDS, make_backend
from vap_bt.perception.backends.base import HttpVLM, StopWhenSilent
from vap_bt.perception.goal_parsing import GoalParse, GoalParser
from vap_bt.perception.protocol import Protocol
from vap_bt.perception.profile import PerceptionProfile, resolve
from vap_bt.perception.verification import VoteSettings
from vap_bt.perception.vlm import MeteredVLM, Paraphraser
from vap_bt.report import diagnosis_summary, verification_counts, versions
from vap_bt.scene.graph import SceneGraph
from vap_bt.settings import RunConfig, Vlm
from vap_bt.sim.detector import DetectorModel
from vap_bt.sim.disturbances import DisturbanceModel
from vap_bt.sim.graph_score import score_graph
from vap_bt.sim.situation_truth import Raised, situation_truths
from vap_bt.sim.situations import SituationModel
from vap_bt.skill import Skill, performed_by_world
from vap_bt.strategy import Strategy
from vap_bt.taskfile import Task
from vap_bt.world import World


class EpisodeInterrupted(KeyboardInterrupt):
    """Ctrl-C at any moment of a session; carries the report of the episode up to that moment."""

    def __init__(self, report: dict) -> None:
        super().__init__("interrupted")
        self.report = report


#: how often the tree is ticked while a goal is in flight on a skill server
TICK_PERIOD_S = 0.002
#: the phase of an episode before its executive runs: the world, skills and transport coming up
STARTING = "starting"


def make_detector(cfg: RunConfig) -> DetectorModel:
    """The symbolic world's detector, with the run's miss rate and relation noise where it sets them."""
    return DetectorModel(**{k: v for k in DETECTOR_SETTINGS if (v := getattr(cfg, k)) is not None})


#: the run settings that, left None, are the symbolic detector model's own
DETECTOR_SETTINGS = ("miss_rate", "relation_noise")


def resolved(cfg: RunConfig) -> RunConfig:
    """``cfg`` with what it leaves to the detector model filled in from it, so that a report states
    the values the run used."""
    model = make_detector(cfg)
    return replace(cfg, **{k: getattr(model, k) for k in DETECTOR_SETTINGS})


def make_world(task: Task, cfg: RunConfig) -> World:
    """The world ``cfg.world`` names for ``task``, seeded by ``cfg.seed``, with the configured situation
    injection and disturbances (and, for pybullet, the sensor model: ``exact`` or noisy ``real``); a
    ValueError for a world or sensor model it does not know."""
    situations = SituationModel(enabled=cfg.injection, seed=cfg.seed)
    disturbances = DisturbanceModel(cfg.disturbance) if cfg.disturbance > 0 else None
    if cfg.world == "symbolic":
        from vap_bt.sim.symbolic import SymbolicWorld

        return SymbolicWorld(task.planning, situations, seed=cfg.seed, detector=make_detector(cfg),
                             disturbances=disturbances)
    if cfg.world == "pybullet":
        from vap_bt.sim.pybullet_world import PybulletWorld

        from vap_bt.sim.depth_noise import DepthNoiseModel
        from vap_bt.sim.localization import LocalizationModel

        if cfg.sensors not in ("exact", "real"):
            raise ValueError(f"unknown sensors {cfg.sensors!r} (exact, real)")
        exact = cfg.sensors == "exact"
        return PybulletWorld(task, seed=cfg.seed, injection=cfg.injection, disturbance_model=disturbances,
                             depth_noise=DepthNoiseModel.exact() if exact else DepthNoiseModel(),
                             localization=LocalizationModel.perfect() if exact else LocalizationModel())
    raise ValueError(f"unknown world {cfg.world!r} (symbolic, pybullet)")


def make_skills(task: Task, world: World) -> dict[str, Skill]:
    """The installed skill plugins, plus — in the symbolic world only — a world-performed skill
    for each domain action no plugin implements (the symbolic world knows every action)."""
    skills = plugins.instantiate(world)
    if world.name == "symbolic":
        for name in task.planning.knowledge.schemas:
            if name not in skills:
                skills[name] = performed_by_world(name, world)
    return skills


def make_camera(robot) -> Any:
    """The camera service and body the executive perceives through: on a robot with drivers,
    the skills' own (:class:`skills.views.ViewService`, sharing their kit, so that a look and a
    skill never move the robot at once); a world without drivers (the symbolic one) is its own."""
    from vap_bt.robot.drivers import has_drivers

    if not has_drivers(robot):
        return robot
    from skills.kit import kit_for  # the motion modules: only a robot with drivers needs them
    from skills.views import ViewService

    return ViewService(kit_for(robot))


VLMS = typing.get_args(Vlm)  # sim, sim-http and each HTTP backend (tests/test_settings.py checks they match)


def sim_vlm(task: Task, world: World, cfg: RunConfig):
    """The world-side simulated VLM over ``world``'s capture records (here, or in ``vap-bt sim``)."""
    from vap_bt.sim.sim_vlm import SimVLM

    rooms = frozenset(o for o, t in task.planning.objects.items() if t == "room")
    return SimVLM(world.captures.get, cfg.vlm_noise, seed=cfg.seed, rooms=rooms)


def make_endpoint(task: Task, world: World, cfg: RunConfig):
    """For ``--vlm sim-http``: the simulated VLM served on the world's side as a local
    OpenAI-compatible endpoint (:mod:`vap_bt.sim.vlm_endpoint`), started; else None. A symbolic
    world's frames then carry a picture of their id, since the endpoint is shown only images."""
    if cfg.vlm != "sim-http":
        return None
    from vap_bt.sim.vlm_endpoint import SimVLMEndpoint

    show_pictures(world)
    return SimVLMEndpoint(sim_vlm(task, world, cfg), world.captures, latency_s=cfg.vlm_latency).start()


def show_pictures(world: World) -> None:
    """Have a world without pixels (the symbolic one) give each frame a picture, a card of its id,
    for a model that is shown only pictures: the simulated VLM behind its endpoint (it reads the
    card back), or a real model asked for the VLM-planner's next action (it reads the prompt's
    facts; the card stands for the frame a real camera would attach)."""
    if hasattr(world, "frame_cards"):
        world.frame_cards = True


def make_vlm(task: Task, world: World, cfg: RunConfig, endpoint=None):
    """The VLM the executive asks: ``sim``, the world-side simulated one reading the world's
    capture records (served beside the camera), or a real backend over HTTP — ``openai`` (any
    OpenAI-compatible server) or ``gemini`` — at ``cfg.vlm_url`` with ``cfg.vlm_model``, its key
    from ``OPENAI_API_KEY`` / ``GEMINI_API_KEY``. A real backend is the executive's own client: it
    is shown the frames' pixels (a frame without any, as in the symbolic world, is an abstention
    without a request) and is never served from the world's side. ``sim-http`` is the ``openai``
    client talking to the simulated VLM's ``endpoint`` (:func:`make_endpoint`)."""
    if cfg.vlm == "sim":
        return sim_vlm(task, world, cfg)
    top_logprobs = 5 if cfg.vlm_logprobs else 0
    if cfg.vlm == "sim-http":
        return make_backend("openai", endpoint.url, endpoint.model, api_key="", top_logprobs=top_logprobs)
    if cfg.vlm in HTTP_BACKENDS:
        return make_backend(cfg.vlm, cfg.vlm_url, cfg.vlm_model, top_logprobs=top_logprobs)
    raise InputError("--vlm", f"unknown VLM backend {cfg.vlm!r} ({', '.join(VLMS)})")


def reached(vlm, cfg: RunConfig):
    """``vlm``, a real backend, once a server has answered at its URL; else one line, exit 4."""
    why = vlm.unreachable()
    if why is not None:
        vlm.close()
        option = "--vlm-url" if cfg.vlm_url else f"--vlm {cfg.vlm} (its default URL)"
        raise TransportError(f"{option}: no VLM server answers at {vlm.url}: {why}; start it, or point --vlm-url at one")
    return vlm


@dataclass(frozen=True)
class GoalWords:
    """A goal in words to be parsed by the VLM, and the input it came from (named in errors)."""

    text: str
    source: str  # "--goal" or "instruction"
    where: str


def check_config(task: Task, cfg: RunConfig) -> GoalWords | None:
    """Say bad world, VLM and goal options in one line before anything starts; returns the goal words."""
    if cfg.verify == "vlm_planner" and cfg.vlm not in HTTP_BACKENDS:
        raise InputError("--verify", f"vlm_planner needs a real VLM backend ({', '.join(HTTP_BACKENDS)}): "
                                     "the simulated VLM cannot plan")
    if cfg.world == "pybullet" and task.spec.scene is None:  # a PDDL problem has no geometry to build
        raise InputError("--world", "the pybullet world builds a household from a task file's scene:; "
                                    "this task has a PDDL problem instead: run it --world symbolic")
    if cfg.sensors != "exact" and cfg.world != "pybullet":
        raise InputError("--sensors", "only the pybullet world has a depth camera and a localiser to model")
    if cfg.vlm in ("sim", "sim-http") and (cfg.vlm_url or cfg.vlm_model):
        raise InputError("--vlm-url" if cfg.vlm_url else "--vlm-model",
                         f"only for a real backend (--vlm openai|gemini); the {cfg.vlm} VLM has neither")
    if cfg.vlm in HTTP_BACKENDS and cfg.world == "symbolic" and cfg.verify not in ("none", "vlm_planner"):
        # every check would be an abstention without a request: the run would only ever be stuck
        # (the VLM-planner checks nothing, and its frames get a picture: show_pictures)
        raise InputError("--vlm", f"the {cfg.vlm} VLM answers from pictures and the symbolic world's frames "
                                  "have none: run it --world pybullet, or --verify none (it then only parses goals)")
    strategy = Strategy.parse(cfg.verify)
    if cfg.vlm == "sim-http" and (strategy.success or strategy.affordance):
        # the endpoint reads a prompt back to the atoms it asks about; an action-level prompt names
        # the action by its verb and two objects, and the atoms it implies depend on the state the
        # plan expects: read back, it would be a guess (vap_bt.sim.vlm_endpoint)
        raise InputError("--verify", f"{cfg.verify} asks action-level questions, which the sim-http endpoint "
                                     "cannot read back to the facts they imply: run it --vlm sim")
    if cfg.vlm_latency and cfg.vlm != "sim-http":
        raise InputError("--vlm-latency", "only for --vlm sim-http (the simulated VLM behind its endpoint)")
    return goal_words(task, cfg)


def goal_words(task: Task, cfg: RunConfig) -> GoalWords | None:
    """The goal in words an episode parses (ParseGoal, paper Alg. 1 line 2), or None when the
    task's PDDL goal runs. Words are parsed when

    * ``--goal WORDS`` is given (``cfg.goal``): they replace the task's goal;
    * the task states no goal (:attr:`~vap_bt.taskfile.Task.states_goal`) and has an ``instruction:``;
    * ``--parse-instruction`` (``cfg.parse_instruction``) asks for the instruction to be parsed
      although ``goal:`` atoms exist (they are then the report's reference, ``file_goal``).

    Otherwise — in particular offline, a task file with ``goal:`` and no ``--goal`` — the PDDL goal
    stands. The simulated VLM does not parse goals: asking for words with ``--vlm sim`` (the
    default) is bad input, said in one line before anything starts.
    """
    instruction = task.spec.instruction.strip()
    field = f"{task.path}: field instruction" if task.path else "instruction"
    if cfg.goal is not None:
        if not cfg.goal.strip():
            raise InputError("--goal", "empty: say what the robot should achieve")
        words = GoalWords(cfg.goal.strip(), "--goal", "--goal")
    elif cfg.parse_instruction or not task.states_goal:
        if not instruction:
            raise InputError(field, "no instruction: to parse (give instruction: words, or --goal)")
        words = GoalWords(instruction, "instruction", field)
    else:
        return None
    if cfg.vlm not in HTTP_BACKENDS:
        why = (f"the {cfg.vlm} VLM does not parse goals in words; run with --vlm openai|gemini")
        if words.source == "--goal":
            raise InputError("--goal", f"{why}, or leave --goal out and the task file's goal: atoms run")
        if cfg.parse_instruction:
            raise InputError("--parse-instruction", why)
        where = f"{task.path}: field goal" if task.path else "goal"
        raise InputError(where, f"no goal: atoms, and {why} (or give goal: atoms)")
    return words


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


def executive_settings(cfg: RunConfig, *, remote: bool) -> ExecutiveSettings:
    """The executive's settings, from the run's: ``remote`` when work takes time (a robot or a
    model in another process, or behind HTTP), which is then done on threads and polled."""
    protocol = Protocol.parse(cfg.protocol)
    if cfg.early_stop:
        protocol = replace(protocol, early_stop=True)
    return ExecutiveSettings(strategy=Strategy.parse(cfg.verify), budget=cfg.budget, max_steps=cfg.max_steps,
                             vote=VoteSettings(paraphrases=cfg.paraphrases, early_stop=protocol.early_stop),
                             max_replans=cfg.max_replans, max_seconds=cfg.max_seconds,
                             tick_period_s=TICK_PERIOD_S if remote else 0.0, unseen=cfg.unseen,
                             protocol=protocol, viewpoints=cfg.viewpoints, threads=remote,
                             second_look=cfg.second_look, claim_risk=cfg.claim_risk)


@dataclass
class Session:
    """Everything one task's episodes can share."""

    task: Task
    cfg: RunConfig
    progress: Callable[[str], None] = lambda m: None
    recorder: Any = None  # a vap_bt.viz.TreeRecorder (on_tree, note, scored), or None
    #: a TransportSettings: the world, skills and VLM run in other processes (``vap-bt run --connect``)
    remote: Any = None
    planner: Planner = field(init=False)
    world: World | None = field(init=False)  # None only until it comes up
    #: the last episode's outcome (belief, context, plans), beside its report
    last_outcome: EpisodeOutcome | None = field(init=False, default=None)

    def __post_init__(self) -> None:
        self.cfg = resolved(self.cfg)
        self.words = check_config(self.task, self.cfg)  # bad input is said before a world starts
        t0 = time.perf_counter()
        self._nothing_started()
        try:
            self._start()
        except KeyboardInterrupt:
            stop = self._interrupted(self.cfg, None, None, [], t0)
            self.close()
            raise stop from None

    def _nothing_started(self) -> None:
        """What a session holds before anything has come up: what close() and a report read."""
        self._world_side_vlm = self.cfg.vlm == "sim"  # a real backend is the executive's own client
        self.world, self.skills, self.endpoint, self.vlm = None, {}, None, None
        self._connected = self._embedded = self._goal_parser = None
        self._first_request = 0
        self.profile = self.task.profile
        self._truths: dict[int, dict] = {}
        self._raised: dict[int, Raised] = {}

    def _start(self) -> None:
        """The planner, the VLM, the world and the transport, in that order."""
        self.planner = Planner(self.task.planning, first_engine=self.cfg.planner, ground_eagerly=True)
        # a real backend is the executive's own client, built and reached before any world starts
        self.vlm = reached(make_vlm(self.task, None, self.cfg), self.cfg) if self.cfg.vlm in HTTP_BACKENDS else None
        if self.remote is not None:
            self._connect()
        else:
            self.world = make_world(self.task, self.cfg)
            self.skills = make_skills(self.task, self.world)
            self.endpoint = make_endpoint(self.task, self.world, self.cfg)  # sim-http: the sim VLM over HTTP
            if self.cfg.verify == "vlm_planner":  # the model is shown the frame each step
                show_pictures(self.world)
            if self.vlm is None:  # the simulated VLM, in process or behind its endpoint
                self.vlm = make_vlm(self.task, self.world, self.cfg, self.endpoint)
        self.profile = make_profile(self.task, self.vlm)
        if self.endpoint is not None:  # the served model reads questions in the words the executive asks
            self.endpoint.read_questions(self.profile, self.task.planning)
        if self.cfg.transport == "zenoh" and self._connected is None:
            from vap_bt.app.embedded import EmbeddedTransport

            self._embedded = EmbeddedTransport(self.world, self.skills,
                                               vlm=self.vlm if self._world_side_vlm else None, camera_for=make_camera)

    def _connect(self) -> None:
        """The world, skill servers and simulated VLM of other processes (:mod:`vap_bt.app.connected`);
        the world is only the runner's, to reset and score by."""
        from vap_bt.app.connected import ConnectedTransport

        if self.cfg.world != "pybullet" or self.cfg.transport != "zenoh" or self.cfg.vlm == "sim-http":
            raise InputError("--connect", "the parts `vap-bt sim` and `vap-bt serve --world remote` host are a "
                                          "pybullet world over Zenoh, asked through --vlm sim (or a real backend)")
        self._connected = ConnectedTransport(self.remote, self.task.name, world_side_vlm=self._world_side_vlm)
        self.cfg = replace(self.cfg, injection=bool(self._connected.world.info()["injection"]))  # the world's say
        self.world, self.skills, self.endpoint = self._connected.world, {}, None
        if self._world_side_vlm:
            self.vlm = self._connected.vlm_client

    def _executive(self, cfg: RunConfig, scores: list[dict]) -> tuple[Executive, MeteredVLM]:
        """A fresh world state for ``cfg.seed`` and an executive wired to it (see the module docstring)."""
        self.world.reset(cfg.seed)  # a world elsewhere reseeds its simulated VLM itself
        if self._world_side_vlm and self._connected is None:  # a real model has no seed: it answers at temperature 0
            self.vlm.reseed(cfg.seed)
        if self.endpoint is not None:
            self.endpoint.reset(cfg.seed)
        self._first_request = len(getattr(self.vlm, "requests", ()))
        skills, robot, vlm = self._transport()
        if isinstance(vlm, HttpVLM):  # a server that stops answering ends the episode, "transport down"
            vlm = StopWhenSilent(vlm)
        metered = MeteredVLM(vlm)
        self._goal_parser = None if self.words is None else GoalParser(
            metered, self.task.planning, self.words.text, self.words.where, self.words.source)
        remote = cfg.transport != "inproc" or not self._world_side_vlm  # work that takes time: threads
        settings = executive_settings(cfg, remote=remote)
        progress = self.progress
        if self.recorder is not None:  # progress lines go to the recording's log as well
            progress = lambda m: (self.progress(m), self.recorder.note(m))  # noqa: E731
        executive = Executive(self.task.planning, self.planner, skills, robot, robot, metered, settings, progress,
                              on_tree=self.recorder.on_tree if self.recorder is not None else None,
                              prior=self.task.prior, geometry=make_geometry(cfg),
                              on_survey=lambda survey, graph: scores.append(self._score(survey, graph)),
                              on_verification=self._score_verification, on_situation=self._note_situation,
                              goal_parser=self._goal_parser, profile=self.profile,
                              instruction=self.task.spec.instruction.strip())
        self._truths: dict[int, dict] = {}  # id(verification) -> the world's values (the runner's only)
        self._raised: dict[int, Raised] = {}  # id(situation) -> where it falls in the world's record
        if self.recorder is not None:  # the live view's 3-D scene shows the fused clouds beside the boxes
            self.recorder.clouds = lambda: fused_clouds(executive)
        return executive, metered

    def build_graph(self, seed: int | None = None) -> dict:
        """Only BuildSceneGraph: the initial survey of an episode, scored (for benchmarks)."""
        cfg = self.cfg if seed is None else replace(self.cfg, seed=seed)
        scores: list[dict] = []
        executive, metered = self._executive(cfg, scores)
        executive.perceive()
        return {**scores[0], "vlm_queries": metered.total}

    def episode(self, seed: int | None = None) -> dict:
        """Run one episode (``seed`` overrides the config's) and return its report. A part that goes away
        mid-episode ends it with a report that says so; a Ctrl-C raises :class:`EpisodeInterrupted`, which
        carries the report so far."""
        cfg = self.cfg if seed is None else replace(self.cfg, seed=seed)
        t0 = time.perf_counter()
        scores: list[dict] = []
        executive = metered = None
        try:
            executive, metered = self._executive(cfg, scores)
            outcome = self.last_outcome = executive.run()
        except KeyboardInterrupt:
            raise self._interrupted(cfg, executive, metered, scores, t0) from None
        except TransportError as exc:  # a part went away mid-episode: the tree is halted, the episode ends
            if executive is None or executive.outcome is None:
                raise  # it never came up: nothing ran
            outcome = self.last_outcome = executive.outcome
            outcome.reason = f"transport down: {exc}"
            self.progress(f"stopped: transport down ({exc})")
        wall = time.perf_counter() - t0
        rep = self._report(cfg, outcome, metered, scores, wall, executive.phase)
        if self.recorder is not None:  # the live view: each diagnosis with the truth beside it
            self.recorder.scored(outcome.situations, [s["diagnosis_truth"] for s in rep["situations"]])
        return rep

    def _interrupted(self, cfg: RunConfig, executive: Executive | None, metered: MeteredVLM | None,
                     scores: list[dict], t0: float) -> EpisodeInterrupted:
        """Ctrl-C: the report of the episode as far as it got, whatever it was doing (the executive,
        if it was running, has halted its tree on the way out)."""
        outcome = executive.so_far() if executive is not None else EpisodeOutcome.nothing_yet(
            SceneGraph.of_facts(self.task.prior))
        outcome.reason = "interrupted"
        if metered is None and self.vlm is not None:  # stopped before the episode asked anything
            metered = MeteredVLM(self.vlm)
        phase = executive.phase if executive is not None else STARTING
        rep = self._report(cfg, outcome, metered, scores, time.perf_counter() - t0, phase, interrupted=True)
        return EpisodeInterrupted(rep)

    def close(self) -> None:
        """Close whatever came up (all of it, or what had when a Ctrl-C stopped the start)."""
        if self._embedded is not None:
            self._embedded.close()
        if self._connected is not None:
            self._connected.close()
        if not self._world_side_vlm and self.vlm is not None:
            self.vlm.close()
        if self.endpoint is not None:
            self.endpoint.close()
        if self.world is not None:
            self.world.close()

    def _transport(self):
        if self._connected is not None:
            c = self._connected
            return c.client, c.robot, c.vlm_client if self._world_side_vlm else self.vlm
        if self._embedded is not None:
            e = self._embedded
            return e.client, e.robot, e.vlm_client if self._world_side_vlm else self.vlm
        if self.cfg.transport == "inproc":
            from vap_bt.app.inprocess import InProcessRobot, InProcessSkillClient

            return InProcessSkillClient(self.skills), InProcessRobot(make_camera(self.world)), self.vlm
        raise ValueError(f"unknown transport {self.cfg.transport!r}")

    def _score_verification(self, v) -> None:
        """The world's value of a check's atom when it settled (nothing happens between a check's
        last frame and its verdict, so the truth now is the truth the frame showed) and when its
        first view was captured (that capture's record, for the first view's accuracy), about the
        instances the robot looked at: its atom's objects resolved through the executive's own
        association in each view (:meth:`CaptureRecord.resolve`: which detection it took for which
        object), so that two bottles it named the other way round are scored as what it really
        saw; an atom about a false positive it took for an object holds of nothing. An
        action-level check (:class:`~vap_bt.bt.record.ActionCheck`) is scored as the conjunction
        of the atoms its question implies. Which settled values matched it is counted for the
        report by :func:`vap_bt.report.verification_counts`."""
        captures = getattr(self.world, "captures", None)  # a world in another process: names as names
        records = [(captures.get(r.view), r) for r in v.rounds] if captures is not None else []
        truth = all(self._true_now(a, records) for a in v.atoms)
        first, r0 = records[0] if records else (None, None)
        if first is not None:
            first_truth = all(_held_at(first, a, r0) for a in v.atoms)
        else:
            first_truth = truth
        self._truths[id(v)] = {"truth": truth, "first_truth": first_truth}

    def _true_now(self, atom: Atom, records: list) -> bool:
        """The world's value now of ``atom`` about the instances the latest view that identified
        its objects took them for (see :meth:`_score_verification`)."""
        resolved: Atom | None = atom
        for record, r in records:  # the latest view that identified them says
            if record is not None and r.identified:
                resolved = record.resolve_atom(atom, r.identified)
        return resolved is not None and self.world.oracle.holds(resolved)

    def _note_situation(self, s: Situation) -> None:
        """Where a situation falls in the world's record: how many of the world's events had
        happened when the executive took it up (for :meth:`_situations`)."""
        objects = frozenset((*(s.atom.args if s.atom else ()), *(s.action.args if s.action else ())))
        self._raised[id(s)] = Raised(objects, len(self.world.oracle.injected()))

    def _situations(self, situations: list[Situation]) -> list[dict]:
        """The report's ``situations``: each with the executive's diagnosis and, beside it, the
        truth the world's record gives (:mod:`vap_bt.sim.situation_truth`) and the indices in
        ``injected`` of the events it rests on."""
        events = self.world.oracle.injected() if self.world is not None else []
        raised = [self._raised.get(id(s), Raised(frozenset(), len(events))) for s in situations]
        return [{**s.to_json(), "diagnosis_truth": t.diagnosis, "truth_events": list(t.events)}
                for s, t in zip(situations, situation_truths(raised, events))]

    def _score(self, survey: Survey, graph: SceneGraph) -> dict:
        """Score a freshly built graph against the world now (the executive never sees this)."""
        perceived = set(survey.sweep.detected)
        site = self.world.site_map()
        detectable = {o for o, t in self.task.planning.objects.items() if t != "room"} - set(site.floors())
        told = {x for a in self.task.prior for x in a.args}  # what the task file names, it tells apart
        centroids = {n: o.centroid for n, o in graph.objects.items()}
        s = score_graph(self.world.oracle, self.task.planning, survey.facts, perceived, detectable, told, centroids)
        return {"reason": survey.reason, "build_s": round(survey.sweep.seconds, 4), "views": survey.sweep.frames, **s}

    def _sensors(self) -> dict:
        """The world's sensor models (printed next to the detector): the depth camera's noise and
        the localiser's error, the physics' step, and how many of the simulated VLM's truth
        readings came after their frame's world had moved on, where the world has them."""
        out = {}
        for key, attr in (("depth_noise", "depth_noise"), ("localization", "localization_model")):
            model = getattr(self.world, attr, None)
            if model is not None:
                out[key] = model.describe()
        physics = getattr(self.world, "physics", None)
        if physics:
            out["physics"] = physics
        captures = getattr(self.world, "captures", None)
        if captures is not None:  # truth a question read after its frame's world had moved on (captures.py)
            out["late_truth_readings"] = captures.late
        return out

    def _report(self, cfg: RunConfig, out: EpisodeOutcome, vlm: MeteredVLM | None, scores: list[dict],
                wall: float, phase: str, interrupted: bool = False) -> dict:
        """The episode's report (:mod:`vap_bt.report`); ``phase`` is the one it ended in. Only an
        episode interrupted while its world started may lack the world (and the VLM): what the
        world would say is then None or empty."""
        parse = self.goal_parse
        goal = self.task.planning.goal if parse is None or parse.goal is None else parse.goal  # the goal pursued
        ctx = out.context
        board = ctx.board  # what the episode's behaviours left
        world_name = self.world.name if self.world is not None else cfg.world
        detector = make_detector(cfg) if world_name == "symbolic" else getattr(self.world, "detector", None)
        verifications = [{**v.to_json(), **self._truths.get(id(v), {})} for v in board.verifications]
        action_checks = [{**c.to_json(), **self._truths.get(id(c), {})} for c in board.action_checks]
        situations = self._situations(out.situations)
        return {
            "success": out.success,
            "goal_satisfied": self._holds(goal),
            "reason": out.reason,
            "no_initial_plan": out.no_initial_plan or None,
            # what the goal's last check rested on: looked at, felt, or belief alone
            "goal_evidence": board.goal_evidence.to_json() if board.goal_evidence is not None else None,
            "interrupted": interrupted,
            "phase": phase,
            "seed": cfg.seed,
            "task": {"name": self.task.name, "file": str(self.task.path) if self.task.path else None,
                     "instruction": self.task.spec.instruction, "goal": [str(l) for l in goal],
                     "belief": sorted(map(str, self.task.prior)) if self.task.spec.scene is not None else "problem init"},
            "config": asdict(cfg),
            "world": {"name": world_name, "injection": self.world_situations(),
                      "disturbances": self.world_disturbances(),
                      "detector": detector.describe() if detector is not None else None,
                      **self._sensors()},
            "goal_parsing": self._goal_parsing_report(),
            "vlm": self._vlm_report(cfg, vlm),
            "perception": {"graph": {"initial": scores[0] if scores else None, "resurveys": scores[1:]},
                           "surveys": [s.to_json() for s in out.surveys], "profile": self.profile.to_json(),
                           "verifications": verification_counts(verifications),
                           "action_checks": verification_counts(action_checks)},
            "plans": [p.to_json() for p in out.plans],
            # --verify vlm_planner: each step's prompts, frames, replies, re-asks and what came of them
            "vlm_planner": {"max_steps": cfg.max_steps, "steps": [p.to_json() for p in out.proposals]}
            if cfg.verify == "vlm_planner" else None,
            "actions_executed": board.actions,
            "situations": situations,
            "diagnosis": diagnosis_summary(situations),
            "injected": [i.to_json() for i in (self.world.oracle.injected() if self.world is not None else [])],
            "replans": out.replans,
            "replan_ms": [round(s * 1000, 3) for s in out.replan_seconds],
            "surveys": len(out.surveys),
            "ticks": out.ticks,
            "vlm_queries": vlm.total if vlm is not None else 0,
            "verifications": verifications,
            # the action-level questions of the SuccessVQA/AffordanceVQA strategies (vap_bt.bt.action_check)
            "action_checks": action_checks,
            # which checks the trees had, or the VLM-planner baseline (vap_bt.strategy)
            "strategy": asdict(Strategy.parse(cfg.verify)),
            "protocol": {"name": cfg.protocol, **Protocol.parse(cfg.protocol).describe(), "viewpoints": cfg.viewpoints,
                         "claim_risk": cfg.claim_risk, "calibration": dict(ctx.calibration.source)},
            "unchecked": [u.to_json() for u in board.unchecked.values()],
            "belief_changes": [c.to_json() for c in out.graph.history],
            "wall_s": round(wall, 4),
            # actions' sent_s/done_s count from this time.perf_counter() (CLOCK_MONOTONIC on Linux:
            # comparable with the other processes' clocks on this machine)
            "clock_t0": round(ctx.t0, 6),
            # a run against parts elsewhere: where they were (None: stopped before it reached them)
            **({"processes": self._connected.describe() if self._connected is not None else None}
               if self.remote is not None else {}),
            "versions": versions(),
        }

    @property
    def goal_parse(self) -> GoalParse | None:
        """What goal parsing did in the last episode (None: the task's PDDL goal ran)."""
        return self._goal_parser.record if self._goal_parser is not None else None

    def _goal_parsing_report(self) -> dict | None:
        """The report's ``goal_parsing``: prompts, raw replies, re-ask, errors and the goal; beside
        them the task file's own goal atoms (if any) and whether the world satisfies those."""
        parse = self.goal_parse
        if parse is None:
            return None
        file_goal = self.task.planning.goal
        return {**parse.to_json(), "file_goal": [str(l) for l in file_goal] if file_goal else None,
                "file_goal_satisfied": self._holds(file_goal) if file_goal else None}

    def _vlm_report(self, cfg: RunConfig, vlm: MeteredVLM | None) -> dict:
        """The report's ``vlm``: the model, and what the episode asked of it (None: it never came up)."""
        if vlm is None:
            return {"backend": cfg.vlm, "queries": 0, "by_purpose": {}, "wall_s": 0.0, "query_s": 0.0}
        return {**vlm.describe(), "queries": vlm.total, "by_purpose": dict(vlm.counts),
                "wall_s": round(vlm.wall_s, 4), "query_s": round(vlm.seconds, 4),
                **({"served": self.endpoint.describe()} if self.endpoint is not None else {}),
                **self._requests()}

    def _requests(self) -> dict:
        """A real backend's record of every request this episode made (the sim VLM keeps none)."""
        if self._world_side_vlm:
            return {}
        return {"requests": [r.to_json() for r in self.vlm.requests[self._first_request:]]}

    def _holds(self, goal) -> bool | None:
        """The oracle's word on a goal, now (None: no world came up to ask)."""
        if self.world is None:
            return None
        return all(self.world.oracle.holds(l.atom) == l.positive for l in goal)

    def world_disturbances(self) -> list[dict]:
        """The disturbances the world scripted for this episode (applied or not: ``injected`` says)."""
        return [d.to_json() if hasattr(d, "to_json") else dict(d) for d in getattr(self.world, "disturbances", None) or ()]

    def world_situations(self) -> list[dict]:
        """The situations the world may inject, as the report lists them; empty for a world without a
        situation model (a remote one)."""
        model = getattr(self.world, "situations", None)
        return model.describe() if model is not None else []


def _held_at(record, atom: Atom, r) -> bool:
    """Whether ``atom``, about the instances round ``r`` took its objects for, held when
    ``record``'s frame was captured."""
    resolved = record.resolve_atom(atom, r.identified) if r.identified else atom
    return resolved is not None and record.holds(resolved)


def fused_clouds(executive: Executive) -> dict:
    """Each tracked object's fused cloud (map frame) as the executive's scene-graph builder holds
    it now; empty before the first survey and in a world without depth."""
    geometry = getattr(getattr(executive, "builder", None), "geometry", None)
    clouds = getattr(geometry, "clouds", None)
    return clouds() if clouds is not None else {}
