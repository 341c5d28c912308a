"""The planner: Fast Downward through unified-planning, and the in-process replanner."""

from __future__ import annotations

import pytest
from unified_planning.engines import ValidationResultStatus
from unified_planning.plans import ActionInstance, SequentialPlan
from unified_planning.shortcuts import PlanValidator

from vap_bt.domain.atoms import Atom
from vap_bt.domain.pddl import load_task
from vap_bt.domain.planner import Planner
from vap_bt.errors import UnsolvableError
from vap_bt.taskfile import load

from conftest import DOMAINS, HOUSEHOLD_TASKS, LITERATURE, TREES


def up_valid(task, actions) -> bool:
    """Validate with unified-planning's own validator (independent of our semantics)."""
    problem = task.to_up()
    acts = {a.name: a for a in problem.actions}
    objs = {o.name: o for o in problem.all_objects}
    plan = SequentialPlan([ActionInstance(acts[a.name], [objs[x] for x in a.args]) for a in actions])
    with PlanValidator(problem_kind=problem.kind) as v:
        return v.validate(problem, plan).status == ValidationResultStatus.VALID


@pytest.mark.parametrize("domain,problem", LITERATURE)
@pytest.mark.parametrize("engine", ["fast-downward", "search"])
def test_plans_are_valid_for_literature_domains(domain, problem, engine):
    task = load_task(DOMAINS / domain, DOMAINS / problem)
    plan = Planner(task, first_engine=engine).plan()
    assert plan.engine == engine and len(plan) > 0
    assert task.validate(plan.actions)
    assert up_valid(task, plan.actions)


@pytest.mark.parametrize("name", HOUSEHOLD_TASKS)
def test_household_plans_are_valid(name):
    task = load(TREES / name).planning
    plan = Planner(task, first_engine="search").plan()
    assert up_valid(task, plan.actions)


def test_unsolvable_problem_is_reported_by_both_engines():
    task = load_task(DOMAINS / "blocksworld-domain.pddl", DOMAINS / "unsolvable-p.pddl")
    for engine in ("fast-downward", "search"):
        with pytest.raises(UnsolvableError):
            Planner(task, first_engine=engine).plan()


def test_replan_reuses_the_tail_of_the_previous_plan():
    task = load(TREES / "collect_cup.yaml").planning
    planner = Planner(task, first_engine="search")
    plan = planner.plan()
    # after the first action, belief is the state that action leads to: the tail still works
    state = plan.actions[0].apply(task.init)
    again = planner.replan(state, plan.actions)
    assert again.engine == "reuse" and again.actions == plan.actions[1:]


def test_replan_after_the_whole_plan_ran_is_the_empty_tail_when_the_goal_holds():
    """The tree got through but the camera did not confirm the goal: the replan from a belief in
    which the goal holds is the previous plan's empty tail, found without a search."""
    task = load(TREES / "collect_cup.yaml").planning
    planner = Planner(task, first_engine="search")
    plan = planner.plan()
    state = task.init
    for a in plan.actions:
        state = a.apply(state)
    again = planner.replan(state, plan.actions[len(plan):])
    assert again.engine == "reuse" and again.actions == []
    assert planner.replan(task.init, []).engine == "cache"  # an empty tail that does not reach the goal


def test_replan_searches_when_the_tail_no_longer_works():
    task = load(TREES / "collect_cup.yaml").planning
    planner = Planner(task, first_engine="search")
    plan = planner.plan()
    # the cup fell on the floor: the old plan grasps it from the table, which no longer holds
    state = set(task.init) - {Atom("on", ("cup", "coffee_table"))}
    state |= {Atom("on", ("cup", "floor_living_room"))}
    again = planner.replan(frozenset(state), plan.actions)
    assert again.engine == "search"
    assert any(a.name == "grasp" and a.args[1] == "floor_living_room" for a in again.actions)
    assert task.with_state(state).validate(again.actions)


def test_a_door_left_ajar_is_opened_though_it_is_neither_open_nor_closed():
    """Table I: open needs only the door in view. The camera found the door neither open nor
    closed (ajar), so the belief holds neither atom; the plan still gets through it by opening it."""
    task = load(TREES / "collect_cup.yaml").planning
    ajar = task.with_state(set(task.init) - {Atom("open", ("door_lk",)), Atom("closed", ("door_lk",))})
    plan = Planner(ajar, first_engine="search").plan()
    assert [a.args for a in plan.actions if a.name == "open"] == [("door_lk",)]
    assert ajar.validate(plan.actions)
    assert up_valid(ajar, plan.actions)


def test_replan_of_a_seen_state_comes_from_the_cache():
    task = load(TREES / "boil_water.yaml").planning
    planner = Planner(task, first_engine="search")
    first = planner.plan()
    assert planner.replan(task.init).engine == "cache"
    assert planner.replan(task.init).actions == first.actions


def test_a_cached_plan_is_the_one_the_same_engine_would_find_afresh():
    """A warm session's planner must plan as a fresh one would: Fast Downward's first plan of a
    state is no answer to a replan from it (the in-process search's, found afresh), or an
    episode's plans would depend on the episodes run before it in the same worker."""
    task = load(TREES / "boil_water.yaml").planning
    warm = Planner(task)
    warm.plan()
    again = warm.replan(task.init)
    assert again.engine != "cache"
    assert again.actions == Planner(task).replan(task.init).actions
    assert warm.replan(task.init).engine == "cache" and warm.plan().engine == "cache"


def test_fast_downward_runs_side_by_side_in_one_folder(tmp_path):
    """Fast Downward's driver puts its translated task in the working directory by default: two
    planners at once from one folder searched each other's task (the task benchmark's workers
    crashed on a plan naming another task's floor). Each run keeps its own: eight ``vap-bt
    plan`` processes at once in one folder all plan their own problem."""
    import subprocess
    import sys
    from pathlib import Path

    problems = [("gripper", "gripper-p4.pddl"), ("blocksworld", "blocksworld-p6.pddl"),
                ("logistics", "logistics-p1.pddl"), ("depots", "depots-p1.pddl")] * 2
    vap_bt = Path(sys.executable).parent / "vap-bt"
    procs = [subprocess.Popen([str(vap_bt), "plan", str(DOMAINS / f"{d}-domain.pddl"), str(DOMAINS / p)],
                              cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for d, p in problems]
    outs = [proc.communicate(timeout=120) for proc in procs]
    for (_, p), proc, (out, err) in zip(problems, procs, outs):
        assert proc.returncode == 0 and "fast-downward" in out + err and "0: " in out, f"{p}: {err[-400:]}"
    assert not list(tmp_path.iterdir())  # nothing left in the working folder



#: a household task of each room and some public domains: action costs (elevators), conditional
#: effects and negative preconditions (briefcase, lamps)
KIND_PROBLEMS = [("household", "collect_cup.yaml"), ("household", "gather_kindling.yaml")] + [
    ("pddl", d, p) for d, p in [("blocksworld-domain.pddl", "blocksworld-p6.pddl"),
                                ("elevators-domain.pddl", "elevators-p1.pddl"),
                                ("briefcase-domain.pddl", "briefcase-p1.pddl"),
                                ("lamps-domain.pddl", "lamps-p1.pddl")]]


@pytest.mark.parametrize("source", KIND_PROBLEMS, ids=lambda s: s[-1])
def test_the_validators_cached_problem_kind_is_the_kind_computed_afresh(source):
    """validation.with_known_kind computes a task problem's kind once per read problem and goal;
    the validator must see the kind unified-planning would compute for the problem in the state
    at hand. States: the initial state, the plan's last, and four with ten random atoms (rigid
    ones included) made true or false; goals: the task's, its first literal alone, and that
    literal negated (a negative goal is a feature of the kind). Each read is a copy, which the
    validator may change without changing the next read."""
    import random

    from vap_bt.domain.atoms import Literal
    from vap_bt.domain.validation import with_known_kind

    task = load(TREES / source[1]).planning if source[0] == "household" else \
        load_task(DOMAINS / source[1], DOMAINS / source[2])
    planner = Planner(task, first_engine="search")
    end = task.init
    for a in planner.plan().actions:
        end = a.apply(end)
    atoms = sorted(planner.grounded.atoms)
    rng = random.Random(0)
    states = [task.init, end] + [frozenset(set(s) ^ set(rng.sample(atoms, min(10, len(atoms)))))
                                 for s in (task.init, task.init, end, end)]
    first = task.goal[0]
    for goal in (task.goal, (first,), (Literal(first.atom, not first.positive),)):
        for s in states:
            t = task.with_state(s, goal)
            fresh = t.to_up().kind
            cached = with_known_kind(t, t.to_up())
            assert cached.kind == fresh, f"{sorted(map(str, s))} {goal}"
            cached.kind.unset_typing("FLAT_TYPING")
            assert cached.kind == fresh
