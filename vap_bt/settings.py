"""The settings of a run and the arguments of every command, each declared once: its type,
default, help text, validation, and where it may be given.

An option of a run is at once a flag, a field of the runner's config, perhaps a key of a task
file's ``options:``, and a field of the executive's settings; here it is one field of a pydantic
dataclass: the annotation and ``Field`` say its type, default, help text (``description``) and
bounds; an :class:`Option` beside them says which commands take it on their command line, under
which flag, and whether a task file may state it. From these declarations derive

* each command's ``argparse`` arguments (:mod:`vap_bt.app.arguments` walks the fields: flag,
  choices, type check, default and help come from here),
* the task file's ``options:`` (:data:`TaskOptions`, the fields a task file may state, with the
  same types, defaults and bounds; read by :mod:`vap_bt.taskfile`),
* :class:`RunConfig` itself, the episode's settings the runner wires, resolved by
  :meth:`RunConfig.from_task` with the documented precedence: what the command line gave, over
  what the task file states, over the default,
* the executive's settings (:class:`vap_bt.bt.executive.ExecutiveSettings`, a small frozen
  dataclass of bt/, built from a RunConfig by the runner: bt/ reads only defaults from here).

Beside the run's settings, the other arguments commands take are declared the same way: what a
command runs and writes (:class:`TaskSource`, :class:`RunOutput`, :class:`TreeOutput`), how it
opens its Zenoh session (:class:`Zenoh`, read into a ``TransportSettings`` of the wire), what
``serve`` and ``sim`` host (:class:`Hosting`), and the rest (:class:`Commands`).

A new option is one field below (``tests/test_settings.py`` walks the fields and checks each
reaches its commands' parsers, the task file's model and the run's config).

``vap-bt --help`` reads this module, so it imports nothing heavy: pydantic, the standard
library and the table of verification strategies (:mod:`vap_bt.strategy`, standard library
only); defaults owned by heavier modules are read when a config is built, not at import.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Any, Iterator, Literal, Protocol

from pydantic import ConfigDict, Field, create_model
from pydantic.dataclasses import dataclass as settings_model
from pydantic.fields import FieldInfo

from vap_bt.strategy import NAMES as STRATEGY_NAMES


class StatedSettings(Protocol):
    """Where a run's settings are stated, besides the command line: a task file
    (:class:`vap_bt.taskfile.Task`: its ``options:`` and its other keys, ``spec``). A protocol, so
    that the settings, which the task file's model is made of, need not import it back."""

    options: Any
    spec: Any


#: replans an episode may make by default (the paper sets no bound; an episode needs one:
#: vap_bt.bt.repeats): Table II injects up to seven situations in one pybullet episode and each may
#: take two replans (the correction, then what it uncovers), and a check the camera cannot settle
#: takes one more each time; with 10, a third of the failures with injection were episodes still
#: recovering, and with 20, pb-3's full method (seeds 0-49) still lost 25 of its 88 failures to the
#: bound, most with a dozen Table II events (docs/RESULTS.md, stop 52); the loops that do not
#: recover are stopped by vap_bt.bt.repeats, not by this bound
MAX_REPLANS = 40
#: steps the VLM-planner may take (it has no plan whose length could bound it; the household's
#: longest plans are about a dozen actions)
MAX_STEPS = 30
#: the accepted chance of claiming a goal atom that does not hold, per atom (vap_bt.perception.evidence)
CLAIM_RISK = 0.05

#: where ``vap-bt serve`` listens, and clients connect, unless told otherwise
DEFAULT_ENDPOINT = "tcp/127.0.0.1:7448"
#: where ``vap-bt sim`` (the episode's Zenoh router) listens, and its parts connect, by default
SIM_ENDPOINT = "tcp/127.0.0.1:7447"
#: how long a session waits for the configured peers to answer (vap_bt.transport.config.open_session)
PEER_TIMEOUT_S = 5.0
#: how long a camera request may take (rendering included): ``--camera-timeout``
CAMERA_TIMEOUT_S = 30.0
#: how long the executive waits for a vanished skill server's robot to be served again (a
#: ``vap-bt serve`` restarted by hand or by a supervisor is up in a few seconds) before it gives
#: up: ``--rejoin-timeout``
REJOIN_TIMEOUT_S = 30.0
#: how long a ``vap-bt parts`` snapshot waits for the liveliness query's answers
SNAPSHOT_TIMEOUT_S = 2.0

World = Literal["symbolic", "pybullet"]
#: the verification strategies (:mod:`vap_bt.strategy` declares them)
Verify = Literal[STRATEGY_NAMES]
#: sim (world-side, offline) | sim-http | the HTTP backends of vap_bt.perception.backends
Vlm = Literal["sim", "sim-http", "openai", "gemini"]
Engine = Literal["fast-downward", "search"]

#: a task file states the setting under ``options:``
OPTIONS = "options"
#: a task file states the setting as a key of its own (``world:``, checked against ``scene:``)
TOP_LEVEL = "top level"


@dataclass(frozen=True)
class Option:
    """Where a setting may be given besides code: the flag (``--max-replans``; a name without a
    dash is a positional argument; None: no command line), the commands that take it, and whether
    a task file may state it (``in_task``: :data:`OPTIONS` or :data:`TOP_LEVEL`).

    A boolean flag given sets the opposite of the field's default (``--no-injection`` sets
    ``injection`` False). On the command line a setting a task file may state defaults to None
    (not given), so the task file's word stands unless the flag is given; any other takes the
    field's default, or ``cli_default`` where the command's default differs from the library's."""

    flag: str | None = None
    commands: tuple[str, ...] = ("run",)
    in_task: str | None = None
    metavar: str | None = None
    short: str | None = None
    #: what a bad value is said not to be: ``'0.7' is not <expects>`` (default: pydantic's words)
    expects: str | None = None
    cli_default: Any = None
    nargs: str | None = None
    #: the titled group of ``--help`` it is listed in (None: the command's own options)
    group: str | None = None
    #: a name shared by flags of which one at most may be given (``--once``, ``--watch``)
    exclusive: str | None = None
    #: the help text where a command words it otherwise than ``description`` (command -> text)
    help_for: tuple[tuple[str, str], ...] = ()

    def help(self, command: str, description: str | None) -> str | None:
        """The option's help text in ``command``: its own words for that command (``help_for``), else the
        field's ``description``."""
        return dict(self.help_for).get(command, description)


def option_of(info: FieldInfo) -> Option | None:
    """The :class:`Option` declared beside a field (None: settable in code only)."""
    return next((m for m in info.metadata if isinstance(m, Option)), None)


def settings_fields(model: type) -> Iterator[tuple[str, FieldInfo, Option | None]]:
    """``(name, field, option)`` for each field of a settings model, in declaration order."""
    for name, info in model.__pydantic_fields__.items():
        yield name, info, option_of(info)


RUN_TREE = ("run", "export", "tree")
RUN_SIM = ("run", "sim")
#: the commands that open a Zenoh session
ZENOH = ("run", "serve", "sim", "parts")


@settings_model(config=ConfigDict(extra="forbid"))
class RunConfig:
    """An episode's settings: which world, VLM, protocol and transport the runner wires, and the
    executive's bounds. Built by :meth:`from_task` (command line over task file over default)."""

    verify: Annotated[Verify, Option("--verify", RUN_TREE, in_task=OPTIONS)] = Field(
        "both", description="the verification strategy: which checks the tree has — preconditions and effects, one of "
                            "them, or none (the closed-world baseline), or a baseline of the paper's comparison "
                            "(success_vqa, affordance_vqa, suc_aff, ok_robot), or vlm_planner (no planner and no checks: a "
                            "real VLM names each next action; docs/perception.md); default the task file's "
                            "options.verify, else both")
    world: Annotated[World, Option("--world", in_task=TOP_LEVEL)] = Field(
        "symbolic", description="the world to run in (default: the task file's world:; the household's task "
                                "files say pybullet)")
    seed: Annotated[int, Option("--seed")] = Field(
        0, description="the episode's seed: the world's, the simulated VLM's and the injection's draws (default 0)")
    budget: Annotated[int, Option("--budget", in_task=OPTIONS)] = Field(
        3, ge=0, description="viewpoint budget K")
    vlm: Annotated[Vlm, Option("--vlm")] = Field(
        "sim", description="sim (default, offline): the world-side simulated VLM; sim-http: the same model behind a "
                           "local OpenAI-compatible endpoint, asked through the openai client; openai: any "
                           "OpenAI-compatible server (key from OPENAI_API_KEY); gemini: Gemini's REST API (key from "
                           "GEMINI_API_KEY)")
    vlm_latency: Annotated[float, Option("--vlm-latency", metavar="SECONDS", expects="a number of seconds >= 0")] = Field(
        0.0, ge=0.0, description="sim-http: seconds the endpoint adds to every answer (a model's inference time)")
    vlm_logprobs: Annotated[bool, Option("--no-logprobs")] = Field(
        True, description="HTTP backends: do not ask for token log-probabilities (the lean protocol then votes)")
    vlm_url: Annotated[str | None, Option("--vlm-url")] = Field(
        None, description="API root of the openai/gemini backend, e.g. http://127.0.0.1:8000/v1")
    vlm_model: Annotated[str | None, Option("--vlm-model")] = Field(
        None, description="model name for the openai/gemini backend (openai: the served model)")
    vlm_noise: Annotated[float, Option("--vlm-noise", RUN_SIM)] = Field(
        1.0, description="scale of the simulated VLM's imperfections: 1 the calibrated model (default), 0 an ideal "
                         "reader of the picture")
    goal: Annotated[str | None, Option("--goal", metavar="WORDS")] = Field(
        None, description="the goal in words, parsed by the VLM after the survey (needs --vlm openai|gemini); "
                          "without it the task file's goal: atoms run")
    parse_instruction: Annotated[bool, Option("--parse-instruction")] = Field(
        False, description="parse the task file's instruction: with the VLM even though it has goal: atoms "
                           "(those are then the report's reference)")
    injection: Annotated[bool, Option("--no-injection", RUN_SIM, in_task=OPTIONS)] = Field(
        True, description="turn Table II situation injection off")
    #: pybullet: the depth camera and the localiser — exact (the renderer's depth, the true base
    #: pose) or real (D435i-like depth, an AMCL-like error; vap_bt/sim/depth_noise.py, localization.py)
    sensors: Annotated[Literal["exact", "real"], Option("--sensors")] = Field(
        "exact", description="pybullet: the wrist depth camera and the base's localiser exact (default), or real: "
                             "D435i-like depth and an AMCL-like pose error (docs/world.md)")
    early_stop: Annotated[bool, Option("--early-stop")] = Field(
        False, description="stop a vote once it is decided")
    protocol: Annotated[Literal["paper", "lean"], Option("--protocol")] = Field(
        "paper", description="how checks ask: the paper's Alg. 2 (default), or lean (early stop, questions in "
                             "flight at once, no re-asking what nothing changed, three agreeing answers or one "
                             "confident logprob answer where they confirm the plan, the detector's word on whether "
                             "a view shows enough; a surprise always gets the paper's full vote)")
    viewpoints: Annotated[Literal["vlm", "greedy", "greedy-all"], Option("--viewpoints")] = Field(
        "vlm", description="where to look from next: the VLM's suggestion (default), a fixed round stopping at the "
                           "first view that decides (greedy), or every reachable viewpoint of the round before "
                           "the views are weighed (greedy-all: the paper's H2 baseline)")
    second_look: Annotated[bool, Option("--one-look")] = Field(
        True, description="believe the first settled view of a surprise or a goal, as the paper's Alg. 2 does "
                          "(default: a second view from a new picture first)")
    claim_risk: Annotated[float, Option("--claim-risk", metavar="P", expects="a probability between 0 and 0.5")] = Field(
        CLAIM_RISK, gt=0.0, lt=0.5,
        description="the accepted chance of claiming a goal atom that does not hold: views are weighed by the "
                    "VLM's calibration until the odds reach (1 - P)/P (default 0.05; docs/perception.md, "
                    "'Looking again')")
    max_replans: Annotated[int, Option("--max-replans", in_task=OPTIONS)] = Field(
        MAX_REPLANS, ge=0, description=f"replans an episode may make (default {MAX_REPLANS})")
    max_steps: Annotated[int, Option("--max-steps", in_task=OPTIONS)] = Field(
        MAX_STEPS, ge=1, description=f"--verify vlm_planner: actions the VLM may name before the episode ends "
                                     f"without its 'done' (default {MAX_STEPS})")
    planner: Annotated[Engine, Option("--planner")] = Field(
        "fast-downward", description="engine of the first plan")
    transport: Annotated[Literal["inproc", "zenoh"], Option("--transport", cli_default="zenoh")] = Field(
        "inproc", description="zenoh (default): skill servers in this command, reached over a loopback Zenoh "
                              "link; inproc: skills called directly (fast campaigns)")
    # -- a task file's, or code's, only -------------------------------------------------------------
    paraphrases: Annotated[int, Option(commands=(), in_task=OPTIONS)] = Field(
        5, ge=1, le=5, description="N paraphrases asked per predicate")
    max_seconds: Annotated[float, Option(commands=(), in_task=OPTIONS)] = Field(
        900.0, gt=0, description="the episode's budget of wall-clock time")
    unseen: Literal["look", "go_on", "stop"] = Field(
        "look", description="what an unsettled precondition does (vap_bt.bt.context.UnseenPolicy)")
    disturbance: float = Field(
        0.0, ge=0, le=1, description="the probability of a scripted disturbance per episode (a person moves a "
                                     "thing, pushes a leaf shut or half shut: vap_bt.sim.disturbances); 0: none")
    # the symbolic world's detector: None leaves a value to its model (vap_bt.sim.detector), which the
    # runner fills in before the run, so the report states what was used
    miss_rate: float | None = Field(
        None, ge=0, le=1, description="the symbolic world's detector: the chance an object in view is missed "
                                      "(default: the detector model's)")
    relation_noise: float | None = Field(
        None, ge=0, description="the symbolic world's relation reports, 0: exact where shown (default: the "
                                "detector model's)")

    @classmethod
    def from_task(cls, task: StatedSettings, **given: Any) -> "RunConfig":
        """The settings of a run of ``task``: each one ``given`` (None: not given, as an argparse
        flag left out), else what the task file states (its ``options:``, its ``world:``), else the
        default."""
        return cls(**cls.chosen(task, **given))

    @classmethod
    def chosen(cls, task: StatedSettings, **given: Any) -> dict[str, Any]:
        """The settings :meth:`from_task` builds a config of, before the defaults fill in the rest
        (a command that reads only a few of them need not build the whole config)."""
        stated = {name: _stated(task, name, option.in_task) for name, _, option in settings_fields(cls)
                  if option is not None and option.in_task}
        return {**stated, **{k: v for k, v in given.items() if v is not None}}

    @classmethod
    def given(cls, args: Any, command: str) -> dict[str, Any]:
        """What ``command``'s parsed arguments say of the settings (None where a flag was not given)."""
        return {name: getattr(args, name) for name, _, option in settings_fields(cls)
                if option is not None and command in option.commands}


def default(name: str) -> Any:
    """A run setting's default (for the executive's own settings, whose defaults are the run's)."""
    return RunConfig.__pydantic_fields__[name].get_default(call_default_factory=True)


def _stated(task: StatedSettings, name: str, where: str) -> Any:
    return getattr(task.options if where == OPTIONS else task.spec, name)


def task_file_field(name: str) -> Any:
    """A setting's declaration for the task file model to state as a key of its own (``world:``)."""
    return RunConfig.__pydantic_fields__[name]


def task_options(model: type) -> type:
    """The model of a task file's ``options:``: every setting of ``model`` declared
    ``in_task=OPTIONS``, with its type, default, bounds and description; anything else there is an error."""
    fields = {name: (info.annotation, info) for name, info, option in settings_fields(model)
              if option is not None and option.in_task == OPTIONS}
    return create_model("Options", __config__=ConfigDict(extra="forbid"),
                        __doc__=f"What a task file's options: may say (declared on {model.__qualname__}).", **fields)


#: a task file's ``options:``
TaskOptions = task_options(RunConfig)



# -- what a command reads and writes, besides the run's settings -----------------------------------------


@settings_model
class TaskSource:
    """What ``run``, ``export`` and ``tree`` run or compile: a task file, or a PDDL domain and problem."""

    task: Annotated[str | None, Option("task", RUN_TREE, nargs="?")] = Field(
        None, description="task file (trees/*.yaml)")
    domain: Annotated[str | None, Option("--domain", RUN_TREE)] = Field(
        None, description="a PDDL domain file, instead of a task file (with --problem)")
    problem: Annotated[str | None, Option("--problem", RUN_TREE)] = Field(
        None, description="a PDDL problem file, instead of a task file (with --domain)")


@settings_model
class RunOutput:
    """What ``vap-bt run`` writes besides its progress: the report, the live view, the summary."""

    report: Annotated[str | None, Option("--report")] = Field(None, description="write the full JSON report here")
    rerun: Annotated[list[str] | None, Option("--rerun", metavar="MODE", nargs="+")] = Field(
        None, description="live view in rerun: 'spawn' (a local viewer), 'serve [PORT]' (gRPC on 127.0.0.1, "
                          "default 9876), or 'save FILE.rrd'")
    json: Annotated[bool, Option("--json")] = Field(
        False, description="print only the JSON summary on stdout, for scripts (the table goes to stderr)")
    full: Annotated[bool, Option("--full")] = Field(
        False, description="with --json: the full report, not the summary (implies --json)")
    quiet: Annotated[bool, Option("--quiet", short="-q")] = Field(
        False, description="no progress lines on stderr (nor the table, with --json)")


@settings_model
class TreeOutput:
    """What ``vap-bt tree`` and ``vap-bt export`` print, and where."""

    format: Annotated[Literal["ascii", "dot", "xml"], Option("--format", ("tree",))] = Field(
        "ascii", description="ascii (default) and dot: py_trees' own display; xml: the BehaviorTree.CPP v4 export")
    output: Annotated[str | None, Option("--output", ("export", "tree"), short="-o", help_for=(
        ("export", "write the XML here instead of stdout"),))] = Field(
        None, description="write the tree here instead of stdout")


@settings_model
class Zenoh:
    """How a command's Zenoh session is opened (:class:`vap_bt.transport.config.TransportSettings`,
    built from these by :func:`~vap_bt.transport.config.settings_from_args` or ``part_settings``)."""

    listen: Annotated[list[str], Option("--listen", ZENOH, metavar="ENDPOINT", group="zenoh transport", help_for=(
        ("run", "with --connect: also listen here, as a Zenoh peer; repeatable"),
        ("serve", f"endpoint to listen on, e.g. {DEFAULT_ENDPOINT}; repeatable (default: {DEFAULT_ENDPOINT} when "
                  "nothing else is given)"),
        ("sim", f"endpoint to listen on, e.g. {SIM_ENDPOINT}; repeatable (default: {SIM_ENDPOINT} when nothing "
                "else is given)")))] = Field(
        default_factory=list, description=f"endpoint to listen on, e.g. {DEFAULT_ENDPOINT}; repeatable")
    connect: Annotated[list[str], Option("--connect", ZENOH, metavar="ENDPOINT", group="zenoh transport", help_for=(
        ("run", f"run against parts already running: the router of `vap-bt sim` (e.g. {SIM_ENDPOINT}) and the "
                "skill servers of `vap-bt serve --world remote`; repeatable"),
        ("parts", f"where to look: the router of `vap-bt sim` (default {SIM_ENDPOINT}), or any peer of the "
                  "network; repeatable")))] = Field(
        default_factory=list, description="endpoint of a peer or router to connect to; repeatable")
    zenoh_config: Annotated[str | None, Option("--zenoh-config", ZENOH, metavar="FILE", group="zenoh transport")] = Field(
        None, description="a zenoh JSON5 config used as is (router, TLS, user/password)")
    peer_timeout: Annotated[float, Option("--peer-timeout", ZENOH, metavar="S", group="zenoh transport")] = Field(
        PEER_TIMEOUT_S, description=f"seconds to wait for configured peers (default {PEER_TIMEOUT_S:g})")
    # the executive's own waits on the parts it reaches (vap-bt run --connect)
    camera_timeout: Annotated[float, Option("--camera-timeout", metavar="S", group="zenoh transport",
                                            expects="a number of seconds above 0")] = Field(
        CAMERA_TIMEOUT_S, gt=0, allow_inf_nan=False,
        description=f"seconds a camera or world-side VLM request may take (default {CAMERA_TIMEOUT_S:g})")
    rejoin_timeout: Annotated[float, Option("--rejoin-timeout", metavar="S", group="zenoh transport",
                                            expects="a number of seconds above 0")] = Field(
        REJOIN_TIMEOUT_S, gt=0, allow_inf_nan=False,
        description="seconds to wait for a vanished skill server's robot to be served again before the episode "
                    f"ends 'transport down' (default {REJOIN_TIMEOUT_S:g})")


@settings_model
class Hosting:
    """What ``vap-bt serve`` and ``vap-bt sim`` host: the world they build, and (serve) which skills."""

    household: Annotated[str | None, Option("household", ("sim",), metavar="task")] = Field(
        None, description="task file whose household to build (trees/*.yaml)")
    robot: Annotated[list[str], Option("--robot", ("serve",), metavar="ROBOT")] = Field(
        default_factory=list, description="robot whose skills to host (ur5e, base, ...); repeatable; default: every "
                                          "robot with a skill plugin")
    world: Annotated[str, Option("--world", ("serve",))] = Field(
        "symbolic", description="symbolic, pybullet, remote (the world of a running `vap-bt sim`, reached at "
                                f"--connect, default {SIM_ENDPOINT}), or package.module:factory (default symbolic)")
    task: Annotated[str | None, Option("--task", ("serve",))] = Field(
        None, description="task file the symbolic/pybullet world is built from")
    seed: Annotated[int, Option("--seed", ("serve", "sim"))] = Field(
        0, description="the world's first seed (a run resets it to its own)")
    world_arg: Annotated[list[str], Option("--world-arg", ("serve",), metavar="KEY=VALUE")] = Field(
        default_factory=list, description="keyword argument for a package.module:factory world; repeatable")
    name: Annotated[str | None, Option("--name", ("serve",))] = Field(
        None, description="server name in the liveliness token (one robot only)")
    exclude_skill: Annotated[list[str], Option("--exclude-skill", ("serve",), metavar="ENTRY_POINT")] = Field(
        default_factory=list, description="ignore this skill plugin (by entry-point name); repeatable")


@settings_model(kw_only=True)
class Commands:
    """The other commands' arguments: ``plan``, ``skills``, ``parts``, ``launch``, and ``vap-bt``'s own."""

    verbose: Annotated[bool, Option("--verbose", ("vap-bt",), short="-v")] = Field(False, description="debug logging")
    domain: Annotated[str, Option("domain", ("plan",))] = Field(description="the PDDL domain file")
    problem: Annotated[str, Option("problem", ("plan",))] = Field(description="the PDDL problem file")
    engine: Annotated[Engine, Option("--engine", ("plan",))] = Field(
        "fast-downward", description="Fast Downward through unified-planning (default), or the in-process greedy "
                                     "search")
    once: Annotated[bool, Option("--once", ("parts",), exclusive="mode")] = Field(
        False, description="one snapshot, then exit (the default)")
    watch: Annotated[bool, Option("--watch", ("parts",), exclusive="mode")] = Field(
        False, description="list what is there, then one line per part or goal that comes (+) or goes (-), until "
                           "Ctrl-C")
    timeout: Annotated[float, Option("--timeout", ("parts",), metavar="S")] = Field(
        SNAPSHOT_TIMEOUT_S, description=f"seconds a snapshot waits for answers (default {SNAPSHOT_TIMEOUT_S:g})")
    json: Annotated[bool, Option("--json", ("skills", "parts"), help_for=(
        ("parts", "the snapshot as JSON ({'parts': [...], 'goals': [...]})"),))] = Field(
        False, description="machine-readable listing")
    file: Annotated[str, Option("file", ("launch",))] = Field(description="the launch file (YAML; the schema is below)")
    endpoint: Annotated[str | None, Option("--endpoint", ("launch",), metavar="ENDPOINT")] = Field(
        None, description="where the parts meet, instead of the file's endpoint: (a part's own endpoint: still "
                          f"holds; default {SIM_ENDPOINT})")
