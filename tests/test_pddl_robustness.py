"""Public PDDL that broke the executive: each case runs end to end, or ends in one line with the
exit code the README promises.

The cases come from trying public domains as a new user would (the IPC sweep,
``tools/bench/pddl_sweep.py``): unified-planning's grounder raising inside driverlog and
elevators, a type and an object of one name, a goal that already holds, action costs read from
a static function with total-cost left uninitialised (agricola), no plan at all, and a planner
that runs out of time.
"""

from __future__ import annotations

import pytest
from unified_planning.engines.compilers import GrounderHelper
from unified_planning.io import PDDLReader

from vap_bt.domain.grounding import ground
from vap_bt.domain import dialect
from vap_bt.domain.dialect import total_cost_from_zero
from vap_bt.domain.pddl import load_task
from vap_bt.domain.planner import Planner
from vap_bt.errors import EXIT_PLANNING_TIMEOUT, EXIT_UNSOLVABLE, InputError, PlanningTimeout
from vap_bt.taskfile import load

from conftest import DOMAINS, TREES, load_json

ROOT = DOMAINS.parent.parent
IPC = ROOT / "tools" / "bench" / "ipc"


def run(cli, tmp_path, domain, problem):
    code, out, err = cli("run", "--domain", domain, "--problem", problem, "--world", "symbolic",
                         "--no-injection", "--vlm-noise", "0", "--report", tmp_path / "r.json", "--json")
    assert "Traceback" not in err
    return code, load_json(out), err


def test_unified_plannings_grounder_still_fails_on_the_reproducer():
    """The upstream bug our grounder sidesteps (tests/domains/up-grounder-domain.pddl says how it
    arises). When this test fails, unified-planning has fixed it."""
    problem = PDDLReader().parse_problem(str(DOMAINS / "up-grounder-domain.pddl"), str(DOMAINS / "up-grounder-p1.pddl"))
    with pytest.raises(ValueError, match="list.remove"):
        list(GrounderHelper(problem, prune_actions=True).get_possible_parameters(problem.actions[0]))


def test_two_static_preconditions_on_one_parameter_prune_instead_of_failing():
    task = load_task(DOMAINS / "up-grounder-domain.pddl", DOMAINS / "up-grounder-p1.pddl")
    assert task.knowledge.instances.candidates("go") == [("a",)]  # b has no road: pruned, once
    assert [str(a) for a in ground(task).actions] == ["go(a)"]


@pytest.mark.parametrize("name", ["driverlog", "elevators-opt08-strips"])
def test_ipc_domains_that_ended_in_unified_plannings_grounder_run_end_to_end(cli, tmp_path, name):
    code, summary, _ = run(cli, tmp_path, IPC / name / "domain.pddl", IPC / name / "problem.pddl")
    assert code == 0 and summary["success"] and summary["goal_satisfied"], summary["reason"]


def test_a_goal_of_atoms_without_arguments_is_looked_at_and_settled(cli, tmp_path):
    """movie's goal is seven 0-ary atoms (``(have-chips)``). The goal check took every 0-ary atom
    for one about the hand (the household's ``hand_empty``), which no move shows anew, so each
    stayed on one view — never enough to claim a goal — and the run looked until its time ran out."""
    code, summary, _ = run(cli, tmp_path, IPC / "movie" / "domain.pddl", IPC / "movie" / "problem.pddl")
    assert code == 0 and summary["success"] and summary["goal_satisfied"], summary["reason"]
    report = load_json((tmp_path / "r.json").read_text())
    looked = {e["predicate"] for e in report["goal_evidence"]["looked"]}
    assert {"have-chips", "movie-rewound", "counter-at-zero"} <= looked, report["goal_evidence"]


def test_a_type_and_an_object_of_one_name_are_told_apart(cli, tmp_path):
    code, summary, _ = run(cli, tmp_path, DOMAINS / "clash-domain.pddl", DOMAINS / "clash-p1.pddl")
    assert code == 0 and summary["success"] and summary["goal_satisfied"], summary["reason"]
    moved = {a.split("(")[1].split(",")[0] for a in summary["plans"][0] if a.startswith("drop(")}
    assert moved == {"cup", "thing"}  # the objects, not the types, were carried


def test_a_goal_that_already_holds_is_reached_by_the_empty_plan(cli, tmp_path):
    code, summary, err = run(cli, tmp_path, DOMAINS / "rooms-domain.pddl", DOMAINS / "rooms-goal-holds.pddl")
    assert code == 0 and summary["success"] and summary["goal_satisfied"], err
    assert summary["actions_executed"] == 0


def test_no_initial_plan_exits_3_with_its_report(cli, tmp_path):
    code, summary, _ = run(cli, tmp_path, DOMAINS / "rooms-domain.pddl", DOMAINS / "rooms-unreachable.pddl")
    assert code == EXIT_UNSOLVABLE and not summary["success"]
    report = load_json((tmp_path / "r.json").read_text())
    assert report["no_initial_plan"] == "unsolvable" and report["reason"].startswith("no initial plan")


def test_costs_from_a_static_function_without_an_initial_total_cost_are_planned_with(cli, tmp_path):
    code, summary, _ = run(cli, tmp_path, DOMAINS / "roads-domain.pddl", DOMAINS / "roads-p1.pddl")
    assert code == 0 and summary["success"], summary["reason"]
    assert summary["plans"] == [["drive(a, b)", "drive(b, c)"]] and summary["plan_costs"] == [5]  # not a-c, 9


def test_total_cost_is_initialised_on_the_init_line_so_line_numbers_stay():
    text = (DOMAINS / "roads-p1.pddl").read_text()
    fixed = total_cost_from_zero(text)
    assert "(= (total-cost) 0)" in fixed and fixed.count("\n") == text.count("\n")
    assert total_cost_from_zero(fixed) == fixed  # given once, never twice


def test_a_planner_that_runs_out_of_time_says_so():
    task = load_task(IPC / "pegsol-08-strips" / "domain.pddl", IPC / "pegsol-08-strips" / "problem.pddl")
    with pytest.raises(PlanningTimeout, match="within") as raised:
        Planner(task, fd_timeout_s=0.01).plan()
    assert raised.value.exit_code == EXIT_PLANNING_TIMEOUT


def test_a_run_whose_planner_runs_out_of_time_exits_5_and_says_so(cli, tmp_path, monkeypatch):
    """Not "no plan reaches the goal" (3): a time-out says nothing of whether a plan exists. Here
    the real Fast Downward is given 10 ms on pegsol, where it needs about 3 s."""
    from vap_bt.domain import planner as planner_mod

    real = planner_mod.Planner._fast_downward_with
    monkeypatch.setattr(planner_mod.Planner, "_fast_downward_with",
                        lambda self, task, params, timeout: real(self, task, params, 0.01))
    code, summary, err = run(cli, tmp_path, IPC / "pegsol-08-strips" / "domain.pddl",
                             IPC / "pegsol-08-strips" / "problem.pddl")
    assert code == EXIT_PLANNING_TIMEOUT and not summary["success"], (code, summary["reason"])
    report = load_json((tmp_path / "r.json").read_text())
    assert report["no_initial_plan"] == "timeout", report["reason"]
    assert "within" in report["reason"] and "no plan reaches" not in report["reason"], report["reason"]


def test_pegsol_is_grounded_without_unified_plannings_grounder(monkeypatch):
    """pegsol's smallest problem took 142 s to run, 40 s of it in 2,271 calls of unified-planning's
    ``ground_action``, after its parameter pruning left 54,483 candidates. Our lifted templates
    keep the 185 instances the rigid facts allow, and never ask unified-planning to ground
    (timings: docs/BENCHMARKS.md, tools/bench/grounding.py)."""
    from unified_planning.engines.compilers import grounder

    from vap_bt.domain.grounding import ground

    calls = []
    for name in ("ground_action", "get_possible_parameters"):
        real = getattr(grounder.GrounderHelper, name)
        monkeypatch.setattr(grounder.GrounderHelper, name,
                            lambda self, *a, _real=real, _name=name, **k: calls.append(_name) or _real(self, *a, **k))
    task = load_task(IPC / "pegsol-08-strips" / "domain.pddl", IPC / "pegsol-08-strips" / "problem.pddl")
    assert len(ground(task).actions) == 185
    assert calls == []


def test_an_error_in_the_domain_of_a_task_file_names_the_domain_file_and_its_line(tmp_path):
    lines = (ROOT / "domains" / "household.pddl").read_text().splitlines()
    broken = next(i for i, line in enumerate(lines) if line.strip().startswith("(:action"))
    lines[broken] = lines[broken].replace("(:action", "(:acton", 1)
    (tmp_path / "household.pddl").write_text("\n".join(lines) + "\n")
    spec = (TREES / "boil_water.yaml").read_text().splitlines()
    (tmp_path / "task.yaml").write_text("\n".join("domain: household.pddl" if line.startswith("domain:") else line
                                                  for line in spec) + "\n")
    with pytest.raises(InputError) as raised:
        load(tmp_path / "task.yaml")
    assert raised.value.where == f"{tmp_path / 'household.pddl'}:{broken + 1}"  # the file, and the broken line


def test_a_predicate_declared_with_one_parameter_name_twice_keeps_its_arity(cli, tmp_path):
    """IPC 2000 logistics declares ``(in ?obj ?obj)``; unified-planning read a one-place ``in``
    and refused every use of it."""
    code, summary, _ = run(cli, tmp_path, IPC / "logistics00" / "domain.pddl", IPC / "logistics00" / "problem.pddl")
    assert code == 0 and summary["success"] and summary["goal_satisfied"], summary["reason"]
    assert any(a.startswith("load-") for a in summary["plans"][0])


def test_a_parse_error_is_one_line_naming_the_file_and_line(cli, tmp_path):
    domain = tmp_path / "d.pddl"
    domain.write_text((DOMAINS / "rooms-domain.pddl").read_text().replace("(at ?r ?x)", "(at ?r ?x ?x)", 1))
    code, out, err = cli("run", "--domain", domain, "--problem", DOMAINS / "rooms-unreachable.pddl",
                         "--world", "symbolic")
    assert code == 2 and len(err.strip().splitlines()) == 1, err
    assert err.startswith(f"vap-bt: {domain}") and "Traceback" not in err


def test_a_variable_glued_to_the_word_before_it_is_read_as_fast_downward_reads_it():
    """IPC 2002 zenotravel writes ``(aircraft?a)``: unified-planning read the word ``aircraft?a``."""
    task = load_task(IPC / "zenotravel" / "domain.pddl", IPC / "zenotravel" / "problem.pddl")
    refuel = task.knowledge.instances.candidates("refuel")
    assert {args[0] for args in refuel} == {"plane1"}  # (aircraft ?a) read, and pruning by it
    assert dialect.problem_text("(at plane1?c)") == "(at plane1 ?c)"


def test_more_action_instances_than_the_limit_leave_planning_to_fast_downward():
    """caldera-sat18's smb_copy, all of whose preconditions are fluents, has 13.7 million
    candidate instances: enumerating them for the in-process search held the episode 32 s before
    its first action, and grounding them never ended. Beyond the limit the count stops at once
    and replanning is Fast Downward's."""
    from vap_bt.domain.grounding import TooManyInstances

    task = load_task(DOMAINS / "gripper-domain.pddl", DOMAINS / "gripper-p4.pddl")
    assert len(ground(task).actions) > 5
    with pytest.raises(TooManyInstances, match="more than 5 action instances"):
        ground(task, instance_limit=5)
    caldera = load_task(IPC / "caldera-sat18-adl" / "domain.pddl", IPC / "caldera-sat18-adl" / "problem.pddl")
    assert len(caldera.knowledge.instances.candidates("smb_copy", limit=100)) == 101  # stops at the limit
    planner = Planner(caldera, ground_eagerly=True)
    assert planner.grounded is None  # too many: no in-process search, and no wait for it


def test_the_problem_handed_to_unified_planning_lists_no_false_atom():
    """unified-planning's ``initial_values`` builds every false ground atom too (7 s on
    maintenance-sat14, once in its quantifiers remover and again in its PDDL writer for every
    Fast Downward call). The problems vap_bt hands it report only the explicit values, and plans
    come out as before."""
    task = load_task(IPC / "maintenance-sat14-adl" / "domain.pddl", IPC / "maintenance-sat14-adl" / "problem.pddl")
    problem = task.to_up()
    true_atoms = [k for k, v in problem.initial_values.items() if k.type.is_bool_type() and v.is_true()]
    assert len(true_atoms) == len(task.init)
    assert not [k for k, v in problem.initial_values.items() if k.type.is_bool_type() and v.is_false()]
    assert len(problem.initial_values) <= 2 * len(task.init)  # the full state would be thousands more
    assert len(task.up_problem.explicit_initial_values) == len(task.init)  # the parsed problem is left as it was
    plan = Planner(task).plan()
    assert task.validate(plan.actions)


def test_a_cost_aware_search_that_runs_out_of_time_hands_over_to_lama_first(monkeypatch):
    """data-network-sat18: LAMA's cost-aware greedy search ran out of the 60 s, where lama-first
    (cost-blind) plans in a second. The cost-aware search has a third of the time; then lama-first."""
    from vap_bt.domain import planner as planner_mod

    task = load_task(IPC / "elevators-opt08-strips" / "domain.pddl", IPC / "elevators-opt08-strips" / "problem.pddl")
    assert task.knowledge.has_costs
    calls, real = [], planner_mod.Planner._fast_downward_with

    def cost_aware_gives_up(self, task, params, timeout):
        calls.append((bool(params), round(timeout, 3)))
        if params:
            raise PlanningTimeout("cost-aware search: no plan in time")
        return real(self, task, params, timeout)

    monkeypatch.setattr(planner_mod.Planner, "_fast_downward_with", cost_aware_gives_up)
    plan = Planner(task, fd_timeout_s=30.0).plan()
    assert calls == [(True, 10.0), (False, 20.0)]
    assert plan.engine == "fast-downward" and task.validate(plan.actions)
