"""The reverse lookup: from a question's text (or a whole prompt) back to the atom it asks about,
exact for every question a profile can produce — the household's paper paraphrases and the IPC
domains' generated ones."""

from __future__ import annotations

import itertools

import pytest

from vap_bt import taskfile
from vap_bt.domain.atoms import Atom
from vap_bt.domain.pddl import load_task
from vap_bt.perception import prompts
from vap_bt.perception.lookup import QuestionLookup, atom_of_question
from vap_bt.perception.profile import resolve

from conftest import DOMAINS, HOUSEHOLD_TASKS, TREES, household_profile

IPC = ["ferry", "gripper", "logistics", "depots", "zenotravel", "miconic", "blocksworld"]


def problem_of(domain: str):
    return next(p for p in sorted(DOMAINS.glob(f"{domain}-p*.pddl")))


def prompts_of(question: str, target: str) -> list[str]:
    """The question as asked: bare, and inside each appendix prompt that carries it."""
    return [question, prompts.predicate_query(question), prompts.view_sufficiency(question),
            prompts.viewpoint_selection(question, target)]


def every_question(task, profile):
    """(atom, text) for every typed atom of every predicate with paraphrases, every paraphrase,
    bare and in every prompt."""
    for p in profile.predicates.values():
        if not p.paraphrases:
            continue
        for args in itertools.product(*(task.objects_of(t) for t in p.types)):
            atom = Atom(p.name, args)
            for q in profile.questions(atom):
                for text in prompts_of(q, args[0] if args else "gripper"):
                    yield atom, text


def assert_exact(task, profile) -> int:
    lookup = QuestionLookup(profile, task.objects, task.knowledge)
    n = 0
    for atom, text in every_question(task, profile):
        assert lookup.atom_of_question(text) == atom, text
        n += 1
    return n


@pytest.mark.parametrize("name", HOUSEHOLD_TASKS)
def test_every_household_question_leads_back_to_its_atom(name):
    task = taskfile.load(TREES / name)
    n = assert_exact(task.planning, task.profile)
    asked = {p.name for p in task.profile.predicates.values() if p.paraphrases}
    assert {"on", "inside", "holding", "hand_empty", "open", "inview", "clear", "closed"} <= asked
    assert n > 100


@pytest.mark.parametrize("domain", IPC)
def test_every_generated_question_of_an_ipc_domain_leads_back_to_its_atom(domain):
    task = load_task(DOMAINS / f"{domain}-domain.pddl", problem_of(domain))
    profile = resolve(task.knowledge)
    assert profile.generated(), "these domains' questions are (mostly) generated"
    assert assert_exact(task, profile) > 20


def test_what_no_paraphrase_says_is_no_atom():
    task = taskfile.load(TREES / "collect_cup.yaml")
    lookup = QuestionLookup(task.profile, task.planning.objects, task.planning.knowledge)
    assert lookup.atom_of_question("Is the cup on the counter?") == Atom("on", ("cup", "counter"))
    assert lookup.atom_of_question("Is the cup on the moon?") is None  # no such object
    assert lookup.atom_of_question("Is the counter on the cup?") is None  # on(item, surface): wrong types
    assert lookup.atom_of_question("Is the cup on the counter") is None  # not the paraphrase's text
    action_level = prompts.book().success_vqa.format(action=prompts.action_phrase("grasp", ("cup", "coffee_table")))
    assert lookup.atom_of_question(action_level) is None  # the action-level baselines ask no atom
    # the household's on/2 question about the ferry's objects is no ferry atom
    ferry = load_task(DOMAINS / "ferry-domain.pddl", DOMAINS / "ferry-p1.pddl")
    assert atom_of_question(resolve(ferry.knowledge), ferry.objects, "Is the c1 on the l1?", ferry.knowledge) is None
    assert atom_of_question(resolve(ferry.knowledge), ferry.objects, "Is the c1 on the ferry?",
                            ferry.knowledge) == Atom("on", ("c1",))


def test_a_question_two_atoms_would_be_worded_alike_is_no_atom():
    """Never a guess: two parses, two atoms, no answer."""
    objects = {"cup": "item", "cup_on_the_table": "item", "table": "surface", "table_on_the_counter": "surface",
               "counter": "surface"}
    lookup = QuestionLookup(household_profile(), objects)
    assert lookup.atom_of_question("Is the cup on the table?") == Atom("on", ("cup", "table"))
    assert lookup.atom_of_question("Is the cup on the table on the counter?") is None


def test_parse_prompt_names_the_purpose():
    lookup = QuestionLookup(household_profile(), {"cup": "item"})
    q = "Is the cup visible in this image?"
    assert lookup.parse_prompt(prompts.predicate_query(q)) == ("predicate", q)
    assert lookup.parse_prompt(prompts.view_sufficiency(q)) == ("sufficiency", q)
    assert lookup.parse_prompt(prompts.viewpoint_selection(q, "cup")) == ("viewpoint", q)
    assert lookup.parse_prompt(q) is None
