"""Action knowledge: PDDL loading, grounded actions, and clear errors for bad input."""

from __future__ import annotations

import pytest

from vap_bt.domain.atoms import Atom, AtomSyntaxError, Literal
from vap_bt.domain.grounding import ground
from vap_bt.domain.pddl import load_task
from vap_bt.errors import InputError
from vap_bt.taskfile import load

from conftest import DOMAINS, HOUSEHOLD_TASKS, LITERATURE, TREES


def test_atoms_parse_both_notations():
    assert Atom.parse("on(cup, table)") == Atom("on", ("cup", "table"))
    assert Atom.parse("(on cup table)") == Atom("on", ("cup", "table"))
    assert Atom.parse("hand_empty") == Atom("hand_empty")
    assert str(Atom("on", ("cup", "table"))) == "on(cup, table)"
    with pytest.raises(AtomSyntaxError):
        Atom.parse("on(cup,")


@pytest.mark.parametrize("domain,problem", LITERATURE)
def test_literature_domains_load_and_ground(domain, problem):
    task = load_task(DOMAINS / domain, DOMAINS / problem)
    g = ground(task)
    assert g.actions, "grounding produced no action"
    # every grounded action's preconditions and effects are ground atoms over the task's objects
    for a in g.actions[:50]:
        for atom in (*a.pre_pos, *a.add, *a.delete):
            assert all(x in task.objects for x in atom.args), atom


def test_grounded_action_exposes_pre_add_delete():
    task = load_task(DOMAINS / "blocksworld-domain.pddl", DOMAINS / "blocksworld-p6.pddl")
    a = task.knowledge.ground("unstack", ("a", "b"))
    assert set(a.pre_pos) == {Atom("on", ("a", "b")), Atom("clear", ("a",)), Atom("handempty")}
    assert a.add == {Atom("holding", ("a",)), Atom("clear", ("b",))}
    assert a.delete == {Atom("clear", ("a",)), Atom("handempty"), Atom("on", ("a", "b"))}
    assert a.applicable(task.init)
    after = a.apply(task.init)
    assert Atom("holding", ("a",)) in after and Atom("on", ("a", "b")) not in after


def test_rigid_and_complementary_predicates_of_the_household():
    task = load(TREES / "boil_water.yaml").planning
    k = task.knowledge
    assert k.is_rigid("connects") and k.is_rigid("openable") and k.is_rigid("clear")
    assert not k.is_rigid("open") and not k.is_rigid("in_room")
    assert k.complements == {"open": "closed", "closed": "open"}


def test_household_domain_has_every_table_action():
    task = load(TREES / "collect_cup.yaml").planning
    assert {"find", "grasp", "placein", "placeon", "open", "close", "turnon", "cut", "fill"} <= set(
        task.knowledge.schemas)


@pytest.mark.parametrize("name", HOUSEHOLD_TASKS)
def test_every_task_file_loads_with_a_valid_goal(name):
    task = load(TREES / name)
    assert task.planning.goal and all(isinstance(l, Literal) for l in task.planning.goal)
    assert not task.planning.goal_holds(task.planning.init)


def test_syntax_error_names_file_and_line():
    with pytest.raises(InputError) as e:
        load_task(DOMAINS / "syntax-error-domain.pddl", DOMAINS / "blocksworld-p6.pddl")
    assert "syntax-error-domain.pddl:8" in str(e.value)


def test_unknown_name_in_problem_is_bad_input():
    with pytest.raises(InputError) as e:
        load_task(DOMAINS / "blocksworld-domain.pddl", DOMAINS / "unknown-name-p.pddl")
    assert "unknown-name-p.pddl" in str(e.value) and "line: 4" in str(e.value)


def test_missing_file_is_bad_input(tmp_path):
    with pytest.raises(InputError) as e:
        load_task(tmp_path / "nope.pddl", DOMAINS / "blocksworld-p6.pddl")
    assert "no such file" in str(e.value)


@pytest.mark.parametrize("text,where", [
    ("name: x\ndomain: ../d.pddl\ngoal: [\n", ":4"),  # unclosed list: found at the end, line 4
    ("name: x\ndomain: d.pddl\nscene: {rooms: [a], robot: {room: b}}\ngoal: ['on(a, b)']\n", "field scene"),
    ("name: x\ndomain: d.pddl\ncolour: red\n", "field colour"),
])
def test_task_file_errors_name_the_line_or_field(tmp_path, text, where):
    f = tmp_path / "task.yaml"
    f.write_text(text)
    with pytest.raises(InputError) as e:
        load(f)
    assert where in str(e.value)


def test_goal_with_unknown_object_is_reported_on_the_goal_field(tmp_path):
    src = (TREES / "collect_cup.yaml").read_text().replace('on(cup, counter)', 'on(teapot, counter)')
    f = tmp_path / "t.yaml"
    f.write_text(src.replace("../domains/household.pddl", str(TREES.parent / "domains" / "household.pddl")))
    with pytest.raises(InputError) as e:
        load(f)
    assert "field goal" in str(e.value) and "teapot" in str(e.value)
