"""Predicate roles: the executive acts on what each predicate means, which the profile says, not on its name.

The household domain with every predicate renamed (its PDDL, its perception profile with the
roles, and a task file) runs the same episode as the original: the same outcome, the same checks
in the same order (modulo the renaming), the same number of VLM queries. The world stays the
household — the symbolic world, its relation detector and its simulated VLM speak the
household's predicates, as a world may — and the renaming is inverted at the world's boundary:
an adapter renames the relations the detector reports and the map's rigid facts on their way to
the executive, and the atoms a VLM query is about on their way back. (The other choice, a world
that reads the profile's roles, would put the executive's vocabulary into the world's ~60
household names; the world is not the executive's to name.) What the executive knows of its VLM's
accuracy is measured per predicate (``perception/calibration.yaml``); the renamed run is given
the same counts under the renamed names.

Also: a profile's roles are checked against the domain like the rest of the file, and a role the
domain lacks is off.
"""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import pytest
import yaml

from conftest import HOUSEHOLD, TREES
from vap_bt.domain.atoms import Atom
from vap_bt.domain.roles import ARITY, Roles
from vap_bt.errors import InputError

#: a prefix renames every predicate and keeps their order: a tie broken by sorted atoms breaks
#: the same way in both runs, so any difference is the executive reading a name
PREFIX = "p_"
PREDICATE = re.compile(r"\((\s*)([A-Za-z][A-Za-z0-9_\-]*)(?=[\s)])")


def _declared(pddl: str) -> set[str]:
    """The predicates the domain declares (its ``(:predicates ...)`` block)."""
    block = pddl[pddl.index("(:predicates"):pddl.index("(:action")]
    return {m.group(2) for m in PREDICATE.finditer(block)} - {":predicates"}


def renamed_household(tmp_path: Path, task: str = "collect_cup.yaml") -> tuple[Path, dict[str, str]]:
    """The household domain, its profile and ``task`` with every predicate renamed, written to
    ``tmp_path``; returns the task file and the renaming."""
    names = {p: PREFIX + p for p in _declared(HOUSEHOLD.read_text())}

    def pddl_rename(m: re.Match) -> str:
        return f"({m.group(1)}{names.get(m.group(2), m.group(2))}"

    # predicates appear as "(name ...": an action named like one (open) is declared ":action open"
    text = PREDICATE.sub(pddl_rename, HOUSEHOLD.read_text()).replace("(domain household)", "(domain renamed)")
    (tmp_path / "renamed.pddl").write_text(text)

    profile = yaml.safe_load(HOUSEHOLD.with_suffix(".perception.yaml").read_text())
    profile["domain"] = "renamed"
    profile["predicates"] = {f"{names[k.split('/')[0]]}/{k.split('/')[1]}": v for k, v in profile["predicates"].items()}
    profile["roles"] = {r: names[v] if r in ARITY else v for r, v in profile["roles"].items()}
    (tmp_path / "renamed.perception.yaml").write_text(yaml.safe_dump(profile, sort_keys=False))

    spec = yaml.safe_load((TREES / task).read_text())
    spec["domain"] = "renamed.pddl"
    spec["goal"] = [re.sub(r"^(\w+)\(", lambda m: names[m.group(1)] + "(", g) for g in spec["goal"]]
    spec["belief"] = [re.sub(r"^(\w+)\(", lambda m: names[m.group(1)] + "(", b) for b in spec.get("belief", [])]
    (tmp_path / task).write_text(yaml.safe_dump(spec, sort_keys=False))
    return tmp_path / task, names


class Renaming:
    """The world's boundary, for an executive that speaks renamed predicates: what the world
    reports (a detector's relations, the map's facts) is renamed on the way in, what a VLM query
    is about is named back on the way out. Everything else passes through."""

    def __init__(self, names: dict[str, str]) -> None:
        self.to_executive, self.to_world = names, {v: k for k, v in names.items()}

    @staticmethod
    def atom(a: Atom, names: dict[str, str]) -> Atom:
        return Atom(names.get(a.predicate, a.predicate), a.args)

    def frame(self, frame, names: dict[str, str]):
        return replace(frame, detections=tuple(
            replace(d, relations=tuple(self.atom(a, names) for a in d.relations)) for d in frame.detections))

    def robot(self, inner):
        return _RenamedRobot(inner, self)

    def vlm(self, inner):
        return _RenamedVLM(inner, self)


class _RenamedRobot:
    """The camera service and body of the world, renamed (see :class:`Renaming`)."""

    def __init__(self, inner, r: Renaming) -> None:
        self.inner, self.r = inner, r

    def capture(self, aim=None):
        return self.r.frame(self.inner.capture(aim), self.r.to_executive)

    def site_map(self):
        m = self.inner.site_map()
        return replace(m, facts=frozenset(self.r.atom(a, self.r.to_executive) for a in m.facts))

    def goto_view(self, view):
        return self.inner.goto_view(view)

    def move_view(self, aim, direction):
        return self.inner.move_view(aim, direction)

    def state(self):
        return self.inner.state()


class _RenamedVLM:
    """The world-side simulated VLM, asked about the world's own atoms (see :class:`Renaming`)."""

    def __init__(self, inner, r: Renaming) -> None:
        self.inner, self.r, self.name = inner, r, inner.name

    def ask(self, query, frame):
        query = replace(query, about=tuple(self.r.atom(a, self.r.to_world) for a in query.about))
        return self.inner.ask(query, self.r.frame(frame, self.r.to_world))

    def describe(self) -> dict:
        return self.inner.describe()


def run(task_file: Path, seed: int, names: dict[str, str]):
    """One symbolic episode of the household world (``trees/`` task of the same name) driven by an
    executive that reads ``task_file``; returns the outcome and the VLM queries asked."""
    from vap_bt.app.inprocess import InProcessRobot, InProcessSkillClient
    from vap_bt.app.runner import RunConfig, make_skills, make_world, sim_vlm
    from vap_bt.bt.executive import Executive
    from vap_bt.domain.planner import Planner
    from vap_bt.perception import evidence
    from vap_bt.perception.evidence import Calibration
    from vap_bt.perception.vlm import MeteredVLM
    from vap_bt.taskfile import load

    world_task, task = load(TREES / task_file.name), load(task_file)
    cfg = RunConfig.from_task(world_task, world="symbolic", seed=seed)
    world = make_world(world_task, cfg)
    measured = evidence.default_calibration()
    # the model's accuracy is measured per predicate (perception/calibration.yaml): the same model
    # asked the same questions is calibrated under the renamed names alike
    evidence._DEFAULT = Calibration({names.get(p, p): row for p, row in measured.counts.items()}, measured.source)
    try:
        world.reset(seed)
        vlm = sim_vlm(world_task, world, cfg)
        vlm.reseed(seed)
        boundary = Renaming(names)
        robot = boundary.robot(InProcessRobot(world))
        metered = MeteredVLM(boundary.vlm(vlm))
        executive = Executive(task.planning, Planner(task.planning, first_engine=cfg.planner, ground_eagerly=True),
                              InProcessSkillClient(make_skills(world_task, world)), robot, robot, metered,
                              prior=task.prior, profile=task.profile)
        return executive.run(), metered.total
    finally:
        evidence._DEFAULT = measured
        world.close()


def checks(outcome, names: dict[str, str]) -> list[tuple]:
    """Every verification of the episode, in the original's names."""
    back = {v: k for k, v in names.items()}
    return [(v.phase, v.action, str(Renaming.atom(v.atom, back)), v.expected, v.value, v.outcome, v.basis, v.queries)
            for v in outcome.context.board.verifications]


@pytest.mark.parametrize("task,seed", [("collect_cup.yaml", 0), ("cut_lemon.yaml", 3), ("heat_pie.yaml", 2),
                                       ("store_firewood.yaml", 4)])
def test_the_household_with_every_predicate_renamed_runs_the_same_episode(tmp_path, task, seed):
    renamed_file, names = renamed_household(tmp_path, task)
    assert len(names) == 20 and all(n.startswith(PREFIX) for n in names.values())
    original, original_queries = run(TREES / task, seed, {})
    renamed, renamed_queries = run(renamed_file, seed, names)

    # the original is a real episode with recovery in it, so the comparison has something to compare
    assert original.success and original.replans > 0 and original.context.board.verifications
    # (not the tick count: the gripper is asked on a worker thread, so how many ticks its answer
    # takes is the scheduler's, in either run)
    assert (renamed.success, renamed.reason, renamed.replans, len(renamed.surveys)) == \
        (original.success, original.reason, original.replans, len(original.surveys))
    assert [s.kind for s in renamed.situations] == [s.kind for s in original.situations]
    assert checks(renamed, names) == checks(original, {})
    assert renamed_queries == original_queries
    back = {v: k for k, v in names.items()}
    assert {Renaming.atom(a, back) for a in renamed.graph.facts} == original.graph.facts
    # and the renamed run really spoke the renamed predicates
    assert all(a.predicate.startswith(PREFIX) for a in renamed.graph.facts)
    assert all(v.atom.predicate.startswith(PREFIX) for v in renamed.context.board.verifications)


# -- the profile's roles -------------------------------------------------------------------------


def test_the_household_profile_states_the_household_roles():
    from conftest import household_profile

    assert household_profile().roles == Roles()


def test_a_profile_without_roles_gets_the_household_names_its_domain_has():
    from vap_bt.domain.pddl import load_task
    from vap_bt.perception.profile import resolve

    from conftest import DOMAINS

    ferry = resolve(load_task(DOMAINS / "ferry-domain.pddl", DOMAINS / "ferry-p1.pddl").knowledge).roles
    assert ferry.on is None  # the ferry's on/1 (a car on the ferry) is not the support on/2
    assert ferry.held is None and ferry.portable == () and ferry.location == frozenset()
    blocks = resolve(load_task(DOMAINS / "blocksworld-domain.pddl", DOMAINS / "blocksworld-p6.pddl").knowledge).roles
    assert (blocks.on, blocks.held, blocks.hand_empty) == ("on", "holding", None)


@pytest.mark.parametrize("roles,field,why", [
    ("{held: grasped}", "roles.held", "no predicate 'grasped'"),
    ("{in_view: in_room}", "roles.in_view", "takes 1 argument, the domain's in_room 2"),
    ("{portable: [gadget]}", "roles.portable", "no type 'gadget'"),
    ("{on: on}", "field roles", "quote"),
    ("{wields: holding}", "roles", "wields"),
])
def test_a_bad_role_is_one_input_error_naming_file_and_field(tmp_path, roles, field, why):
    from vap_bt.perception.profile import resolve
    from vap_bt.taskfile import load

    path = tmp_path / "p.perception.yaml"
    path.write_text(f"roles: {roles}\n")
    knowledge = load(TREES / "collect_cup.yaml").planning.knowledge
    with pytest.raises(InputError) as e:
        resolve(knowledge, path)
    assert str(path) in str(e.value) and field in str(e.value) and why in str(e.value)


def test_a_role_switched_off_switches_its_behaviour_off(tmp_path):
    """``held: null``: no FeelHand after a grasp (the compiler adds it for the held role only)."""
    from vap_bt.bt.compiler import compile_plan
    from vap_bt.bt.context import ExecutionContext
    from vap_bt.domain.planner import Planner
    from vap_bt.perception.profile import resolve
    from vap_bt.scene.graph import SceneGraph
    from vap_bt.taskfile import load

    task = load(TREES / "collect_cup.yaml")
    plan = Planner(task.planning).plan(task.planning.init, task.planning.goal)

    def feels(profile) -> int:
        ctx = ExecutionContext(SceneGraph.of_facts(task.planning.init), None, None, None, profile=profile)
        tree = compile_plan(ctx, plan.actions, task.planning.goal, task.planning.knowledge)
        return sum(b.name == "feel hand" for b in tree.iterate())

    path = tmp_path / "p.perception.yaml"
    path.write_text(HOUSEHOLD.with_suffix(".perception.yaml").read_text().replace("  held: holding\n", "  held: null\n"))
    assert feels(task.profile) >= 1
    assert feels(resolve(task.planning.knowledge, path)) == 0
