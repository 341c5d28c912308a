"""Task files: the YAML a user writes to say what the robot should do, and where.

A task file names a domain, describes the scene (a :class:`~vap_bt.scene.layout.Layout`, or a
PDDL problem file for domains other than the household), states the goal — as PDDL atoms, with
the natural-language instruction beside it — and sets the run's options. Paths are relative to
the task file. Every mistake is reported once, with the file and the field or line at fault::

    name: boil_water
    instruction: Boil some water in a cup.
    domain: ../domains/household.pddl
    goal: ["filled(cup)", "heated(cup)"]
    scene: {rooms: [...], doors: {...}, robot: {...}, furniture: {...}, items: {...}}
    belief: ["inside(cup, cabinet)"]
    world: pybullet        # the world a run uses (symbolic, the default, or pybullet); --world overrides
    options: {verify: both, budget: 3, max_replans: 40}
    perception: my_household.perception.yaml   # optional; default: the one beside the domain

A task with an ``instruction:`` and no ``goal:`` has its goal parsed from the words by a real VLM
after the robot's survey (:mod:`vap_bt.perception.goal_parsing`; see :func:`vap_bt.app.runner.goal_words`
for when words are parsed); offline, with the simulated VLM, such a task cannot run.

Two parts say different things to different readers. ``scene:`` is the world a simulator builds:
the executive never reads it. ``belief:`` is what the user tells the robot about things it may
not be able to see (the cup is in the closed cabinet); it may be wrong, perception overrides it
and verification catches what neither saw. A ``problem:`` file's initial state is, likewise, the
user's account of the situation: the executive takes it as its prior belief.

``world:`` is the world ``vap-bt run`` uses unless ``--world`` says otherwise: ``symbolic`` (the
default) or ``pybullet``, the headless household built from ``scene:`` (so a ``problem:`` file
cannot name it). The household's task files in ``trees/`` name pybullet; campaigns, benchmarks
and most tests ask for the symbolic world explicitly, since they run episodes by the thousand.

``perception:`` names the domain's perception profile (which predicates the camera is asked,
with which questions; :mod:`vap_bt.perception.profile`) when it is not the one beside the domain
file. It is read and checked against the domain when the task is loaded.
"""

from __future__ import annotations

import re
from pathlib import Path

from pydantic import BaseModel, ConfigDict, Field, ValidationInfo, field_validator, model_validator

from vap_bt.domain.atoms import Atom, AtomSyntaxError, Literal as Lit
from vap_bt.domain.task import PlanningTask
from vap_bt.errors import InputError
from vap_bt.perception.profile import file_roles, locate as locate_profile, resolve as resolve_profile
from vap_bt.scene.layout import Layout, layout_facts
from vap_bt.settings import TaskOptions, World, task_file_field
from vap_bt.yaml_file import read_model

#: what ``options:`` may say: the run's settings a task file may state, declared once with their
#: flags (:mod:`vap_bt.settings`); a flag given on the command line overrides the file's word
Options = TaskOptions


class TaskFile(BaseModel):
    """A task file as written (the module docstring shows one), with its fields' types and the rules
    between them; :func:`load` reads one."""

    model_config = ConfigDict(extra="forbid")
    name: str
    instruction: str = ""
    paper_task: str | None = None
    domain: str
    problem: str | None = None
    scene: Layout | None = None
    goal: list[str] | None = None
    belief: list[str] = Field(default_factory=list, description="what the user tells the robot (a prior)")
    world: World = task_file_field("world")  # the world `vap-bt run` uses unless --world says otherwise
    options: Options = Field(default_factory=Options)
    perception: str | None = Field(None, description="the domain's perception profile (default: beside the domain)")

    @field_validator("world")
    @classmethod
    def _pybullet_needs_a_scene(cls, world: str, info: ValidationInfo) -> str:
        if world == "pybullet" and info.data.get("scene") is None:  # scene: comes first, so it is read
            raise ValueError("the pybullet world builds the household from scene:; a problem: file runs "
                             "in world: symbolic")
        return world

    @model_validator(mode="after")
    def _scene_or_problem(self) -> "TaskFile":
        if (self.scene is None) == (self.problem is None):
            raise ValueError("give exactly one of scene: (a household layout) or problem: (a PDDL file)")
        if self.scene is not None and not self.goal and not self.instruction.strip():
            raise ValueError("a task with a scene needs goal: [atoms], or an instruction: for a VLM to parse")
        return self


class Task:
    """A loaded task: the file's contents plus the planning task they define.

    ``planning.init`` is the scenario's true initial state (for worlds to build, never for the
    executive); ``prior`` is what the executive is told. ``profile`` is the domain's perception
    profile as read from ``perception_file`` (None: no file, defaults throughout), with template
    paraphrases where it has none; a runner whose VLM writes paraphrases resolves it again."""

    def __init__(self, spec: TaskFile, planning: PlanningTask, path: Path | None,
                 prior: frozenset | None = None, perception_file: Path | None = None) -> None:
        self.spec, self.planning, self.path = spec, planning, path
        self.prior = planning.init if prior is None else prior
        self.perception_file = perception_file
        self.profile = resolve_profile(planning.knowledge, perception_file)

    @property
    def name(self) -> str:
        return self.spec.name

    @property
    def states_goal(self) -> bool:
        """Whether the task gives its goal in PDDL: a problem file always does (``(:goal (and))``,
        already true, included), a scene only with ``goal:`` atoms."""
        return self.spec.problem is not None or bool(self.spec.goal)

    @property
    def options(self) -> Options:
        """The options the task file states (unstated ones at their defaults)."""
        return self.spec.options


def load(path: str | Path) -> Task:
    """The task the file at ``path`` describes, read, checked and resolved (its paths relative to it);
    every mistake is one :class:`InputError` naming the file and the field at fault."""
    path = Path(path)
    spec = read_model(path, TaskFile, "task file", "name:, domain:, goal:, ...")
    return from_spec(spec, base=path.parent, where=path)


def from_spec(spec: TaskFile, base: Path, where: Path | str) -> Task:
    """The task of a task file already parsed: the domain, the perception profile and the problem file read
    relative to ``base``, the scene expanded into facts, and the goal checked against them; ``where`` names
    the file in errors."""
    from vap_bt.domain.pddl import load_task, parse_strings

    domain_path = _existing(base, spec.domain, where, "domain")
    perception = _perception_file(spec, base, domain_path, where)
    if spec.problem is not None:
        planning = load_task(domain_path, _existing(base, spec.problem, where, "problem"))
        if spec.goal:
            planning = planning.with_state(planning.init, _goal(spec.goal, planning, where))
        return Task(spec, planning, Path(where), perception_file=perception)
    objects = spec.scene.objects()
    facts = layout_facts(spec.scene, file_roles(perception))  # in the predicates the profile names
    goal_atoms = [_parse(g, where) for g in spec.goal or ()]  # none: the instruction is parsed
    for lit in goal_atoms:  # unknown names are the goal's fault, said before PDDL ever sees them
        unknown = [a for a in lit.atom.args if a not in objects]
        if unknown:
            raise InputError(f"{where}: field goal", f"unknown object {unknown[0]!r} in {lit.atom} "
                             f"(the scene has {', '.join(sorted(objects))})")
    # the goal is checked against the domain here, not by the PDDL parser, which would blame the
    # scene for an unknown predicate, a wrong arity or type in goal: (and in its own words)
    text = problem_text(spec.name, objects, facts, [])
    planning = parse_strings(domain_path, text, where=f"{where}: field scene")
    for a in goal_atoms:
        why = planning.check_atom(a.atom)
        if why:
            raise InputError(f"{where}: field goal", why)
    planning = planning.with_state(planning.init, goal_atoms)
    prior = []
    for text_atom in spec.belief:
        lit = _parse(text_atom, where, field="belief")
        why = planning.check_atom(lit.atom)
        if why or not lit.positive:
            raise InputError(f"{where}: field belief", why or f"state what holds, not what does not: {text_atom!r}")
        prior.append(lit.atom)
    return Task(spec, planning, Path(where), frozenset(prior), perception_file=perception)


def _existing(base: Path, name: str, where, field: str) -> Path:
    """The PDDL file a field names; a missing one is the task file's mistake, said as such."""
    path = (base / name).resolve()
    if not path.is_file():
        raise InputError(f"{where}: field {field}", f"no such PDDL file: {path}")
    return path


def _perception_file(spec: TaskFile, base: Path, domain_path: Path, where) -> Path | None:
    """The task's ``perception:`` file, else the profile beside the domain, else None (defaults)."""
    if spec.perception is not None:
        path = (base / spec.perception).resolve()
        if not path.is_file():
            raise InputError(f"{where}: field perception", f"no such perception profile: {path}")
        return path
    beside = locate_profile(domain_path)
    return beside if beside.is_file() else None


def _parse(text: str, where, field: str = "goal") -> Lit:
    neg = text.strip().startswith("not ")
    try:
        atom = Atom.parse(text.strip()[4:] if neg else text)
    except AtomSyntaxError as exc:
        raise InputError(f"{where}: field {field}", str(exc)) from None
    return Lit(atom, not neg)


def _goal(goal: list[str], planning: PlanningTask, where) -> tuple[Lit, ...]:
    out = []
    for g in goal:
        lit = _parse(g, where)
        why = planning.check_atom(lit.atom)
        if why:
            raise InputError(f"{where}: field goal", why)
        out.append(lit)
    return tuple(out)


def problem_text(name: str, objects: dict[str, str], facts: set[Atom], goal: list[Lit]) -> str:
    """A PDDL problem for the household domain (so unified-planning and Fast Downward read it)."""
    by_type: dict[str, list[str]] = {}
    for o, t in sorted(objects.items()):
        by_type.setdefault(t, []).append(o)
    objs = "\n    ".join(f"{' '.join(names)} - {t}" for t, names in by_type.items())
    init = "\n    ".join(a.pddl() for a in sorted(facts))
    goals = " ".join(l.atom.pddl() if l.positive else f"(not {l.atom.pddl()})" for l in goal)
    # the task's name as a PDDL name: any name: is the user's to choose, a space in it no PDDL error
    name = re.sub(r"[^A-Za-z0-9_-]", "_", name)
    name = name if name[:1].isalpha() else f"task_{name}"
    return (f"(define (problem {name}) (:domain household)\n  (:objects\n    {objs})\n"
            f"  (:init\n    {init})\n  (:goal (and {goals})))\n")
