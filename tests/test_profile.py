"""Perception profiles: loading and validation, arity-keyed paraphrases, generated paraphrases,
what the compiler and the survey ask, and the profile in the report."""

from __future__ import annotations

import pytest

from vap_bt import taskfile
from vap_bt.bt.compiler import compile_plan
from vap_bt.bt.context import ExecutionContext
from vap_bt.strategy import Strategy
from vap_bt.bt.verify_predicate import VerifyPredicate
from vap_bt.domain.atoms import Atom
from vap_bt.domain.pddl import load_task
from vap_bt.errors import InputError
from vap_bt.perception import profile as profiles
from vap_bt.perception.paraphrase import template_paraphrases, template_problem
from vap_bt.app.runner import RunConfig, Session
from vap_bt.scene.graph import SceneGraph

from conftest import DOMAINS, HOUSEHOLD, TREES, household_profile

FERRY = (DOMAINS / "ferry-domain.pddl", DOMAINS / "ferry-p1.pddl")
#: what the household's trees checked before profiles (paraphrases in prompts.yaml and not rigid)
HOUSEHOLD_ASKED = {"inview", "on", "inside", "holding", "hand_empty", "open", "closed", "reachable", "blocking",
                   "filled", "sliced", "turned_on", "heated"}


def ferry():
    return load_task(*FERRY)


def write(tmp_path, text: str, name: str = "p.perception.yaml"):
    path = tmp_path / name
    path.write_text(text)
    return path


# -- the household's profile ----------------------------------------------------------------------

def test_household_profile_keeps_what_the_household_asked():
    p = household_profile()
    assert p.file == HOUSEHOLD.with_suffix(".perception.yaml")
    assert {q.name for q in p.predicates.values() if q.source == "vlm"} == HOUSEHOLD_ASKED
    assert not p.generated(), "every household predicate asked of the VLM has written paraphrases"
    sources = {q.name: q.source for q in p.predicates.values()}
    assert {n for n, s in sources.items() if s == "map"} == {"connects", "openable", "clear", "fillable"}
    assert {n for n, s in sources.items() if s == "proprioception"} == {"robot_in", "robot_at"}
    assert sources["in_room"] == "none"
    assert p.questions(Atom("on", ("coffee_table_cup", "coffee_table")))[0] == \
        "Is the coffee table cup on the coffee table?"


def test_household_trees_check_exactly_the_vlm_sourced_atoms(cup):
    task, actions = cup
    ctx = ExecutionContext(graph=SceneGraph.of_facts(task.init), vlm=None, camera=None, skills=None,
                           strategy=Strategy.parse("both"))
    root = compile_plan(ctx, actions, task.goal, task.knowledge)
    asked = {b.atom.predicate for b in root.iterate() if isinstance(b, VerifyPredicate)}
    assert asked and asked <= HOUSEHOLD_ASKED
    unchecked = {u.atom.predicate: u.reason for u in ctx.board.unchecked.values()}
    assert "robot_in" in unchecked and "source proprioception" in unchecked["robot_in"]
    assert "in_room" in unchecked and "source none" in unchecked["in_room"]
    assert not set(unchecked) & HOUSEHOLD_ASKED


# -- loading and validation -----------------------------------------------------------------------

GOOD_ON = """predicates:
  on/1:
    source: vlm
    paraphrases: ["Is the {X} on the ferry?", "Is the {X} aboard?", "Is the {X} on deck?",
                  "Is the {X} carried by the ferry?", "Is the {X} on board?"]
"""


@pytest.mark.parametrize("text,field,words", [
    ("predicates: {on/1: {source: camera}}", "predicates.on/1.source", "'vlm'"),
    ("predicates: {on/1: {source: vlm, colour: red}}", "predicates.on/1.colour", "Extra inputs"),
    ("predicates: {board: {source: vlm}}", "predicates.board", "name and arity"),
    ("predicates: {on: {source: vlm}}", "predicates.True", "name and arity"),  # YAML 1.1: a bare on is true
    ("predicates: {on/1: {source: vlm, paraphrases: [a, b]}}", "predicates.on/1.paraphrases", "leaves out {X}"),
    (GOOD_ON.replace("Is the {X} on deck?", "Is the {X} on the {Y}?"), "predicates.on/1.paraphrases",
     "names {Y}, but the predicate takes 1 argument"),
    (GOOD_ON.replace("Is the {X} on deck?", "Is the {X} on deck"), "predicates.on/1.paraphrases", "not a question"),
    (GOOD_ON.replace("Is the {X} on deck?", "Is the {X on deck?"), "predicates.on/1.paraphrases", "paraphrase 3"),
    (GOOD_ON.replace("Is the {X} on deck?", "Is the {X} aboard?"), "predicates.on/1.paraphrases", "given twice"),
    ("predicates:\n  on/1:\n    source: vlm\n    paraphrases: ['Is the {X} on?', 'Is the {X} aboard?']\n",
     "predicates.on/1.paraphrases", "at least 5"),
    ("predicates: {on/2: {source: vlm}}", "predicates.on/2", "takes 1 argument: write on/1"),
    ("predicates: {sail/2: {source: map}}", "predicates.sail/2", "no predicate 'sail'"),
    ("domain: household\npredicates: {}", "domain", "defines 'ferry'"),
    (GOOD_ON + "  at-ferry/1:\n    source: vlm\n    paraphrases: ['Is the {X} on the ferry?', 'a {X}?', "
               "'b {X}?', 'c {X}?', 'd {X}?']\n", "predicates.on/1.paraphrases", "also a paraphrase of at-ferry/1"),
    ("actions: {sail: 'sail to the {Y}'}", "actions.sail", "an action's name and arity"),
    ("actions: {sail/1: 'sail to the {X}'}", "actions.sail/1", "takes 2 parameters: write sail/2"),
    ("actions: {fly/2: 'fly to the {Y}'}", "actions.fly/2", "no action 'fly'"),
    ("actions: {board/2: 'put the {X} on the {Z}'}", "actions.board/2", "names {Z}, but the predicate takes 2"),
])
def test_a_bad_profile_is_one_input_error_naming_file_and_field(tmp_path, text, field, words):
    path = write(tmp_path, text)
    with pytest.raises(InputError) as exc:
        profiles.resolve(ferry().knowledge, path)
    assert exc.value.where == f"{path}: field {field}"
    assert words in str(exc.value)


@pytest.mark.parametrize("text,words", [("predicates: [on/1", "not valid YAML"), ("- on/1", "is a mapping")])
def test_a_profile_that_is_not_a_mapping_names_the_file(tmp_path, text, words):
    path = write(tmp_path, text)
    with pytest.raises(InputError) as exc:
        profiles.load_spec(path)
    assert str(path) in exc.value.where and words in str(exc.value)


def test_a_task_file_names_its_profile_and_a_bad_one_exits_2_in_one_line(cli, tmp_path):
    bad = write(tmp_path, "predicates: {on/1: {source: camera}}", "mine.perception.yaml")
    task = tmp_path / "ferry.yaml"
    task.write_text(f"name: ferry\ndomain: {FERRY[0]}\nproblem: {FERRY[1]}\nperception: {bad.name}\n")
    code, out, err = cli("run", task, "--world", "symbolic", "--transport", "inproc", "-q")
    assert code == 2 and out == "" and "Traceback" not in err
    assert err.strip().splitlines() == [f"vap-bt: {bad}: field predicates.on/1.source: "
                                        + err.split("field predicates.on/1.source: ", 1)[1].strip()]
    task.write_text(f"name: ferry\ndomain: {FERRY[0]}\nproblem: {FERRY[1]}\nperception: missing.yaml\n")
    code, out, err = cli("run", task, "--world", "symbolic", "--transport", "inproc", "-q")
    assert code == 2 and f"{task}: field perception: no such perception profile" in err


def test_a_task_files_profile_overrides_the_one_beside_the_domain(tmp_path):
    good = write(tmp_path, GOOD_ON, "mine.perception.yaml")
    task = tmp_path / "ferry.yaml"
    task.write_text(f"name: ferry\ndomain: {FERRY[0]}\nproblem: {FERRY[1]}\nperception: {good.name}\n")
    loaded = taskfile.load(task)
    assert loaded.perception_file == good
    assert loaded.profile.questions(Atom("on", ("c1",)))[1] == "Is the c1 aboard?"
    # without it, the ferry's own profile beside the domain file
    task.write_text(f"name: ferry\ndomain: {FERRY[0]}\nproblem: {FERRY[1]}\n")
    assert taskfile.load(task).perception_file == DOMAINS / "ferry-domain.perception.yaml"


def test_the_action_level_questions_say_each_action_as_the_profile_does(tmp_path):
    """The household's profile phrases every action of its domain; an action a profile leaves out
    is said with every argument named, never cut to the first two."""
    household = household_profile()
    assert household.action_phrase("grasp", ("cup", "coffee_table", "kitchen")) == "grasp the cup from the coffee table"
    assert household.action_phrase("fill", ("cup", "kitchen_sink")) == "fill the cup at the kitchen sink"
    assert {name for name, _ in household.actions} == set(taskfile.load(TREES / "collect_cup.yaml").planning.knowledge.schemas)
    path = write(tmp_path, "actions: {board/2: 'drive the {X} onto the ferry at the {Y}'}")
    ferry_ = profiles.resolve(ferry().knowledge, path)
    assert ferry_.action_phrase("board", ("c1", "l0")) == "drive the c1 onto the ferry at the l0"
    assert ferry_.action_phrase("sail", ("l0", "l1")) == "sail the l0 and the l1"


# -- arity-keyed paraphrases -----------------------------------------------------------------------

def test_the_ferrys_on_of_one_argument_never_takes_the_households_on_of_two():
    household_on = set(household_profile().get("on", 2).paraphrases)
    own = profiles.resolve(ferry().knowledge)  # the ferry's profile beside its domain file
    assert own.get("on", 2) is None and own.get("on", 1).origin == "vap_bt"
    assert own.questions(Atom("on", ("c1",)))[0] == "Is the c1 on the ferry?"
    defaults = profiles.resolve(_without_file(ferry().knowledge))  # as if the ferry had no profile
    on1 = defaults.get("on", 1)
    assert on1.generated and on1.origin == "templates" and not household_on & set(on1.paraphrases)
    assert all("{Y}" not in t for t in on1.paraphrases)
    assert defaults.questions(Atom("on", ("c1",)))[0] == "Is the car c1 on?"
    with pytest.raises(KeyError, match="on/2 is not a predicate"):
        defaults.questions(Atom("on", ("c1", "l1")))  # there is no on/2 in the ferry domain


def _without_file(knowledge):
    """The same domain as if no profile lay beside it."""
    from dataclasses import replace

    return replace(knowledge, domain_file=None)


# -- generated paraphrases ------------------------------------------------------------------------

def test_templates_are_deterministic_five_questions_naming_every_argument():
    at = template_paraphrases("at", ("truck", "location"))
    assert at == template_paraphrases("at", ("truck", "location")) and len(at) == 5 == len(set(at))
    assert at[0] == "Is the truck {X} at the location {Y}?"
    for name, types in [("at", ("truck", "location")), ("empty-ferry", ()), ("connects", ("door", "room", "room")),
                        ("lifting", ("hoist", "crate")), ("fuel-level", ("aircraft", "flevel")), ("x", ("object",))]:
        texts = template_paraphrases(name, types)
        assert len(texts) == 5 and all(template_problem(t, len(types)) is None for t in texts), name
        rendered = [t.format(**dict(zip("XYZ", ("a1", "b2", "c3")))) for t in texts]
        assert all(all(o in q for o in ("a1", "b2", "c3")[:len(types)]) for q in rendered), rendered
        assert all(name.replace("-", " ") in q for q in rendered)
    assert template_paraphrases("at", ("truck", "location"), 3) == at[:3]
    with pytest.raises(ValueError):
        template_paraphrases("at", ("truck", "location"), 6)


class WritingVLM:
    """A paraphrasing backend that writes ``texts`` for every predicate (the protocol's optional part)."""

    name = "writer"

    def __init__(self, texts):
        self.texts, self.asked = texts, []

    def paraphrase(self, predicate, arg_types, n):
        self.asked.append((predicate, tuple(arg_types), n))
        return self.texts(predicate, arg_types) if callable(self.texts) else self.texts

    def describe(self):
        return {"backend": self.name, "model": "m-1"}


def test_a_backend_writes_the_missing_paraphrases_and_bad_writing_falls_back_to_templates():
    k = ferry().knowledge
    good = WritingVLM(lambda p, types: [f"Q{i} {p}: " + " ".join(f"{{{c}}}" for c in "XY"[:len(types)]) + "?"
                                        for i in range(5)])
    p = profiles.resolve(k, paraphraser=good)
    assert sorted(a[0] for a in good.asked) == ["at", "empty-ferry"]  # on/1, at-ferry/1 are the file's
    at = p.get("at", 2)
    assert at.generated and at.origin == "writer (m-1)" and at.paraphrases[0] == "Q0 at: {X} {Y}?"
    # another predicate's question is no paraphrase of this one: a backend that writes the same
    # five texts for every predicate of one argument gets them used once (at-ferry/1, first)
    echo = WritingVLM(["Is the {X} here?", "Is the {X} there?", "Is it the {X}?", "Is the {X} it?", "The {X}?"])
    bare = profiles.resolve(_without_file(k), paraphraser=echo)
    assert bare.get("at-ferry", 1).origin == "writer (m-1)" and bare.get("on", 1).origin == "templates"
    assert "writer (m-1) wrote no 5 usable paraphrases" in bare.get("on", 1).fallback
    junk = WritingVLM(["Is it?", "Is the {X} there?", "{Q}?", "", "Is the {X} there?"])
    p = profiles.resolve(k, paraphraser=junk)
    at = p.get("at", 2)
    assert at.origin == "templates" and at.paraphrases == tuple(template_paraphrases("at", ("car", "location")))
    assert "writer (m-1) wrote no 5 usable paraphrases" in at.fallback
    record = next(g for g in p.to_json()["generated"] if g["predicate"] == "at/2")
    assert record["by"] == "templates" and "fallback" in record


def test_the_report_records_the_profile_and_each_generated_paraphrase():
    task = taskfile.from_spec(taskfile.TaskFile(name="ferry", domain=str(FERRY[0]), problem=str(FERRY[1])),
                              base=DOMAINS, where=FERRY[1])
    session = Session(task, RunConfig(world="symbolic", injection=False, vlm_noise=0.0))
    try:
        rep = session.episode()
    finally:
        session.close()
    prof = rep["perception"]["profile"]
    assert prof["file"] == str(DOMAINS / "ferry-domain.perception.yaml")
    generated = {g["predicate"]: g for g in prof["generated"]}
    assert set(generated) == {"at/2", "empty-ferry/0"}
    assert generated["at/2"]["by"] == "templates"
    assert generated["at/2"]["texts"] == template_paraphrases("at", ("car", "location"))
    by_key = {e["predicate"]: e for e in prof["predicates"]}
    assert by_key["on/1"] == {"predicate": "on/1", "source": "vlm", "origin": "vap_bt", "generated": False}


# -- what the survey asks follows the profile ------------------------------------------------------

def test_the_survey_asks_open_only_where_the_profile_sources_it_from_the_vlm(tmp_path):
    spec = (HOUSEHOLD.with_suffix(".perception.yaml")).read_text()
    base = taskfile.load(TREES / "heat_pie.yaml")
    session = Session(base, RunConfig(world="symbolic", injection=False, vlm_noise=0.0))
    try:
        asked = session.episode()
    finally:
        session.close()
    assert any(s["predicate"].startswith("open(") for s in asked["perception"]["surveys"][0]["states"])
    mine = write(tmp_path, spec.replace("  open/1:\n    source: vlm", "  open/1:\n    source: none"), "h.perception.yaml")
    task = tmp_path / "heat_pie.yaml"
    task.write_text((TREES / "heat_pie.yaml").read_text().replace("../domains/household.pddl", str(HOUSEHOLD))
                    + f"perception: {mine.name}\n")
    session = Session(taskfile.load(task), RunConfig(world="symbolic", injection=False, vlm_noise=0.0))
    try:
        rep = session.episode()
    finally:
        session.close()
    assert rep["perception"]["surveys"][0]["states"] == []
    assert not any(v["predicate"].startswith("open(") for v in rep["verifications"])
    assert any(u["name"] == "open" and "source none" in u["reason"] for u in rep["unchecked"])


def test_the_runner_lets_a_writing_vlm_write_and_keeps_the_task_profile_otherwise():
    from vap_bt.app.runner import make_profile
    from vap_bt.sim.sim_vlm import SimVLM

    task = taskfile.from_spec(taskfile.TaskFile(name="ferry", domain=str(FERRY[0]), problem=str(FERRY[1])),
                              base=DOMAINS, where=FERRY[1])
    assert make_profile(task, SimVLM(lambda frame_id: None)) is task.profile  # the sim VLM writes nothing
    writer = WritingVLM(lambda p, types: [f"W{i} {p} " + " ".join(f"{{{c}}}" for c in "XY"[:len(types)]) + "?"
                                          for i in range(5)])
    written = make_profile(task, writer)
    assert written.get("at", 2).origin == "writer (m-1)" and written.get("on", 1).origin == "vap_bt"
