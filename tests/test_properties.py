"""Property-based tests: whatever a user writes, vap_bt answers with one clear error or a run.

The contract (:mod:`vap_bt.errors`): every mistake in a user's input is a :class:`VapBtError` —
an :class:`InputError` (exit 2) naming the file and the line or field at fault, an
:class:`UnsolvableError` (3), a :class:`PlanningTimeout` (5) — and the command line prints it in
one line on stderr, never a traceback. Hand-written tests check the mistakes someone thought of;
here hypothesis makes up the rest, starting from inputs that work and breaking them the way
people do:

1. goal strings (``on(cup, counter)`` and ``(on cup counter)``): random text and near-valid atoms
   with missing parentheses, unknown predicates, wrong arity, unknown objects, unicode;
2. task files (``trees/*.yaml``): keys dropped, values of the wrong type, junk YAML, broken
   indentation, bytes that are not UTF-8, scene entries that name nothing;
3. PDDL domains and problems (``tests/domains``): tokens deleted, inserted or duplicated,
   parentheses lost, predicates renamed, requirements changed, odd numbers in costs.

Each property also runs a few examples through ``vap-bt`` itself. The runs are derandomized (the
same examples every time, so CI is reproducible) and bounded (well under a minute together on
one core); ``VAP_BT_FUZZ=10`` multiplies the number of examples, random ones, for a longer hunt.
Bugs the properties found stay covered as explicit ``@example`` cases.
"""

from __future__ import annotations

import functools
import json
import os
import re
from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, event, example, given, settings, strategies as st

from vap_bt import taskfile
from vap_bt.domain import pddl
from vap_bt.domain.atoms import Atom, AtomSyntaxError
from vap_bt.domain.planner import Planner
from vap_bt.errors import (EXIT_BAD_INPUT, EXIT_GOAL_NOT_REACHED, EXIT_OK, EXIT_PLANNING_TIMEOUT, EXIT_UNSOLVABLE,
                            InputError, PlanningTimeout, UnsolvableError, VapBtError)

from conftest import DOMAINS, HOUSEHOLD, HOUSEHOLD_TASKS, TREES

#: VAP_BT_FUZZ=N: N times the examples, new ones on every run (a hunt); unset: the same few (CI)
SCALE = int(os.environ.get("VAP_BT_FUZZ", "1"))
HUNT = "VAP_BT_FUZZ" in os.environ


def bounded(n: int, **kw) -> settings:
    """Settings for a property: ``n`` examples (times VAP_BT_FUZZ), the same ones on every run.

    No deadline: a PDDL parse takes 0.1–1 s on a loaded CI machine. tmp_path is shared by a
    test's examples, which is safe here because each example overwrites the one file it uses."""
    return settings(max_examples=n * SCALE, deadline=None, derandomize=not HUNT, database=None,
                    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow,
                                           HealthCheck.filter_too_much, HealthCheck.data_too_large], **kw)


#: what ``vap-bt`` may exit with on a task it could read (or not): never anything else
DOCUMENTED_EXITS = {EXIT_OK, EXIT_GOAL_NOT_REACHED, EXIT_BAD_INPUT, EXIT_UNSOLVABLE, EXIT_PLANNING_TIMEOUT}


def assert_clear(exc: BaseException, *files: Path | str, field: str | None = None) -> None:
    """``exc`` keeps the contract: a VapBtError in one line; an InputError names one of ``files``
    (and ``field``, when given)."""
    assert isinstance(exc, VapBtError), f"not a VapBtError: {type(exc).__name__}: {exc}"
    text = str(exc)
    assert text and "\n" not in text, f"not one line: {text!r}"
    if isinstance(exc, InputError):
        assert any(str(f) in text for f in files), f"names none of {[str(f) for f in files]}: {text}"
        if field is not None:
            assert f"field {field}" in text, f"does not name field {field}: {text}"


def assert_one_line_on_stderr(code: int, err: str) -> None:
    """A quiet command's stderr: one line for bad input, at most one otherwise (a quiet run says
    "no plan" in its JSON on stdout), never a traceback."""
    assert code in DOCUMENTED_EXITS, (code, err)
    assert "Traceback" not in err, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 if code == EXIT_BAD_INPUT else len(lines) <= 1, f"not one line on stderr: {err!r}"


@pytest.fixture
def cached_scene_parse(monkeypatch):
    """Parsing the household domain with a scene's problem takes about a second; many examples
    share a scene (only the goal differs), so each distinct (domain, problem text) is parsed once.
    Transparent: the parse is deterministic and its result is immutable."""
    monkeypatch.setattr(pddl, "parse_strings", functools.lru_cache(maxsize=64)(pddl.parse_strings))


# -- 1. goal strings ---------------------------------------------------------------------------

#: two tasks' predicates with the objects each argument fits, and all their objects, to build goals
#: and near-misses from: the collect-cup scene in the household, and gripper's PDDL problem
ROOMS, SURFACES = ["kitchen", "living_room"], ["counter", "coffee_table", "floor_kitchen"]
CUP_WORDS = ({"on": [["cup"], SURFACES], "holding": [["cup"]], "hand_empty": [], "robot_in": [ROOMS],
              "filled": [["cup"]], "in_room": [["cup", "counter"], ROOMS], "robot_at": [SURFACES + ["door_lk"]]},
             ["cup", "counter", "coffee_table", "kitchen", "living_room", "door_lk", "floor_kitchen"])
BALLS = ["ball1", "ball2", "ball4"]
GRIPPER_WORDS = ({"at-robby": [["rooma", "roomb"]], "at": [BALLS, ["rooma", "roomb"]], "free": [["left", "right"]],
                  "carry": [BALLS, ["left", "right"]]},
                 ["rooma", "roomb", "ball1", "ball2", "ball4", "left", "right"])
#: characters people (and editors) put where they do not belong
JUNK_CHARS = "()(),, ?-_'\"\t\n;:=!ü€中\u00a0\u200b"


@st.composite
def atoms(draw, words) -> str:
    """A goal as a person would write it: a predicate of the domain over objects that fit it, in
    either notation, sometimes negated."""
    signatures, _ = words
    pred = draw(st.sampled_from(sorted(signatures)))
    args = [draw(st.sampled_from(fits)) for fits in signatures[pred]]
    if draw(st.booleans()):
        text = f"({' '.join([pred, *args])})"
    else:
        text = f"{pred}({', '.join(args)})" if args or draw(st.booleans()) else pred
    return ("not " if draw(st.integers(0, 3)) == 0 else "") + text


@st.composite
def near_misses(draw, words) -> str:
    """An atom with made-up words in it, a wrong arity, a stray "not", or broken a character at a time."""
    signatures, objects = words
    pred = draw(st.sampled_from(sorted(signatures)) | st.text(max_size=6))
    args = draw(st.lists(st.sampled_from(objects) | st.text(max_size=5), max_size=4))
    text = (f"({' '.join([pred, *args])})" if draw(st.booleans())
            else f"{pred}({', '.join(args)})" if args or draw(st.booleans()) else pred)
    if draw(st.booleans()):
        text = draw(st.sampled_from(["not ", "not", "NOT ", "  not  ", "¬", "not not "])) + text
    for _ in range(draw(st.integers(0, 3))):
        text = draw(char_edits(text))
    return text


@st.composite
def char_edits(draw, text: str) -> str:
    """``text`` with one character deleted, inserted, or a span duplicated."""
    i = draw(st.integers(0, len(text)))
    op = draw(st.sampled_from(["delete", "insert", "duplicate"]))
    if op == "delete":
        return text[:i] + text[i + 1:]
    if op == "insert":
        return text[:i] + draw(st.sampled_from(JUNK_CHARS) | st.characters()) + text[i:]
    j = draw(st.integers(i, len(text)))
    return text[:j] + text[i:j] + text[j:]


def goal_texts(words) -> st.SearchStrategy[str]:
    return atoms(words) | near_misses(words) | st.text(max_size=30)


GOAL_TEXT = goal_texts(CUP_WORDS)


@given(text=GOAL_TEXT)
@bounded(300)
def test_an_atom_parses_or_says_why(text):
    try:
        atom = Atom.parse(text)
    except AtomSyntaxError as exc:  # the task file's loader adds the file and field
        assert str(exc)
        return
    assert atom.predicate and atom.predicate == atom.predicate.lower()


@given(text=atoms(CUP_WORDS).map(lambda t: t.removeprefix("not ")))
@bounded(50)
def test_a_well_formed_atom_reads_back_in_both_notations(text):
    atom = Atom.parse(text)
    assert Atom.parse(str(atom)) == atom == Atom.parse(atom.pddl())


def write_task(path: Path, doc: dict) -> Path:
    path.write_text(yaml.safe_dump(doc, allow_unicode=True, sort_keys=False))
    return path


def tree_doc(name: str) -> dict:
    """A task file of trees/ as a mapping whose paths work from anywhere (tmp_path)."""
    doc = yaml.safe_load((TREES / name).read_text())
    doc["domain"] = str(HOUSEHOLD)
    return doc


def loads_or_names(path: Path, field: str | None = None, others: list[str] = ()):
    """Load the task file at ``path``: the task, or None after checking the error is clear."""
    try:
        task = taskfile.load(path)
    except Exception as exc:  # noqa: BLE001 — the property is about which exceptions arrive
        event(f"error: {type(exc).__name__}")  # --hypothesis-show-statistics: how far examples get
        assert_clear(exc, path, *others, field=field)
        return None
    event("loaded")
    return task


@given(goal=st.lists(GOAL_TEXT, min_size=1, max_size=2))
@example(goal=["onn(cup, counter)"])  # an unknown predicate was blamed on field scene, by the PDDL parser
@example(goal=["on(cup)"])  # so was a wrong arity
@example(goal=["on(cup, door_lk)"])  # and an argument of the wrong type
@example(goal=["not "])  # "not" alone reached the PDDL parser as a predicate
@bounded(40)
def test_a_scene_tasks_goal_loads_or_names_the_field(tmp_path, cached_scene_parse, goal):
    path = write_task(tmp_path / "task.yaml", {**tree_doc("collect_cup.yaml"), "goal": goal})
    task = loads_or_names(path, "goal")
    if task is not None:
        assert len(task.planning.goal) == len(goal)


@given(goal=st.lists(goal_texts(GRIPPER_WORDS), min_size=1, max_size=2))
@bounded(20)
def test_a_problem_tasks_goal_loads_or_names_the_field(tmp_path, goal):
    doc = {"name": "gripper", "domain": str(DOMAINS / "gripper-domain.pddl"),
           "problem": str(DOMAINS / "gripper-p4.pddl"), "goal": goal}
    task = loads_or_names(write_task(tmp_path / "task.yaml", doc), "goal")
    if task is not None:
        assert len(task.planning.goal) == len(goal)


# -- 2. task files -------------------------------------------------------------------------------

def paths_in(doc, prefix=()) -> list[tuple]:
    """Every key path into a nested mapping/list: ("scene", "items", "cup", "place"), ..."""
    out = []
    items = doc.items() if isinstance(doc, dict) else enumerate(doc) if isinstance(doc, list) else ()
    for k, v in items:
        out.append((*prefix, k))
        out += paths_in(v, (*prefix, k))
    return out


def parent_of(doc, path: tuple):
    for k in path[:-1]:
        doc = doc[k]
    return doc


#: values of every YAML type, for a field that expects another
JUNK_VALUES = (st.none() | st.booleans() | st.integers(-3, 10**12) | st.floats() | st.text(max_size=12)
               | st.lists(st.integers(0, 3) | st.text(max_size=4), max_size=3)
               | st.dictionaries(st.text(max_size=4), st.integers(0, 3), max_size=2))
#: files a task file may wrongly name (as its domain, problem or perception profile): an error in
#: one of them may name that file rather than the task file
OTHER_FILES = [str(DOMAINS / "gripper-domain.pddl"), str(DOMAINS / "gripper-p4.pddl"), str(TREES / "boil_water.yaml"),
               str(DOMAINS / "ferry-domain.perception.yaml"), str(HOUSEHOLD.with_suffix(".perception.yaml"))]
#: names a scene entry (or a field) may wrongly refer to
SCENE_NAMES = st.sampled_from(["", "kitchen", "living_room", "cup", "counter", "nowhere", "on nowhere", "inside cup",
                               "on kitchen", "held", "floor_kitchen", "on floor_kitchen", "a b", "(x)", "Küche",
                               "and", "object", "door_lk", "inside counter", "on cup", "-", "42", "Counter",
                               "problem", "perception", *OTHER_FILES])


@st.composite
def mutated_docs(draw) -> dict:
    """A task file of trees/, its mapping changed in one to three places."""
    doc = tree_doc(draw(st.sampled_from(HOUSEHOLD_TASKS)))
    for _ in range(draw(st.integers(1, 3))):
        paths = paths_in(doc)
        if not paths:
            break
        path = draw(st.sampled_from(paths))
        parent = parent_of(doc, path)
        op = draw(st.sampled_from(["drop", "retype", "rename", "add"]))
        if op == "drop":
            del parent[path[-1]]
        elif op == "retype":
            parent[path[-1]] = draw(JUNK_VALUES)
        elif op == "rename":  # a scene entry naming something else, or nothing at all
            parent[path[-1]] = draw(SCENE_NAMES)
        elif isinstance(parent, dict):
            parent[draw(SCENE_NAMES | st.text(max_size=6))] = draw(JUNK_VALUES | SCENE_NAMES)
        else:
            parent.append(draw(JUNK_VALUES | SCENE_NAMES))
    return doc


#: lines that are not what the task file means, or not YAML at all
JUNK_LINES = st.sampled_from(["- - -", ": :", "{", "[", "]", "!!python/object/apply:os.system ['true']", "&a *a",
                              "? x", "key: [1, 2", "\t- x", "%YAML 1.2", "---", "...", "<<: *x", "goal: [", "'",
                              "name: x: y", "  - on(cup, counter)", "scene: null", "@", "`", "!!binary x",
                              "*undefined", "a: !!int x"]) | st.text(max_size=20)


@st.composite
def mutated_texts(draw) -> bytes:
    """A task file of trees/ as bytes, edited as text: junk lines, indentation, bytes, deletions."""
    text = yaml.safe_dump(tree_doc(draw(st.sampled_from(HOUSEHOLD_TASKS))), sort_keys=False)
    lines = text.splitlines(keepends=True)
    for _ in range(draw(st.integers(1, 2))):
        i = draw(st.integers(0, len(lines) - 1))
        op = draw(st.sampled_from(["junk", "indent", "dedent", "delete"]))
        if op == "junk":
            lines.insert(i, draw(JUNK_LINES) + "\n")
        elif op == "indent":
            lines[i] = draw(st.sampled_from([" ", "  ", "\t", "    "])) + lines[i]
        elif op == "dedent":
            lines[i] = lines[i].lstrip()
        else:
            del lines[i]
    data = "".join(lines).encode()
    if draw(st.booleans()):  # bytes an editor in another encoding would write
        i = draw(st.integers(0, len(data)))
        data = data[:i] + draw(st.binary(min_size=1, max_size=4) | st.sampled_from([b"\xff", b"\xe9", b"\x00", b"\xc3"])) + data[i:]
    return data


def with_scene(name: str, **changes) -> dict:
    """A task file of trees/ with some of its scene's entries replaced."""
    doc = tree_doc(name)
    doc["scene"] = {**doc["scene"], **changes}
    return doc


#: task files the properties found answered unclearly, and what they are told now
FOUND_IN_TASK_FILES = {
    # the folder the task file is in was named, "no such file", and no field
    "missing domain": ({**tree_doc("boil_water.yaml"), "domain": ""}, r"field domain: no such PDDL file"),
    # blamed on field scene, at a line of the PDDL generated from it
    "name with a space": ({**tree_doc("collect_cup.yaml"), "name": "collect cup"}, None),
    # these two were PDDL type errors quoting a line of generated PDDL
    "an item named as a room": (with_scene("collect_cup.yaml", items={"kitchen": {"place": "on counter"}}),
                                r"field scene: .*'kitchen' is the name of a room already"),
    "a name PDDL cannot read": (with_scene("collect_cup.yaml", rooms=["living_room", "kitchen", "1"]),
                                r"field scene: .*room '1': a name is lower-case"),
    # PDDL read Counter as counter, and no goal could name it: "unknown object 'counter'"
    "a capital letter": (with_scene("collect_cup.yaml", furniture={
        "coffee_table": {"type": "surface", "room": "living_room"}, "Counter": {"type": "surface", "room": "kitchen"}}),
        r"field scene: .*furniture 'Counter': a name is lower-case"),
}


@given(doc=mutated_docs())
@example(doc=FOUND_IN_TASK_FILES["missing domain"][0])
@example(doc=FOUND_IN_TASK_FILES["an item named as a room"][0])
@bounded(60)
def test_a_task_file_with_wrong_fields_loads_or_names_it(tmp_path, cached_scene_parse, doc):
    loads_or_names(write_task(tmp_path / "task.yaml", doc), others=OTHER_FILES)


@pytest.mark.parametrize("found", sorted(FOUND_IN_TASK_FILES))
def test_what_the_properties_found_in_task_files_is_said_precisely(tmp_path, found):
    doc, said = FOUND_IN_TASK_FILES[found]
    path = write_task(tmp_path / "task.yaml", doc)
    if said is None:
        assert taskfile.load(path).name == doc["name"]
        return
    with pytest.raises(InputError, match=re.escape(str(path)) + ": " + said):
        taskfile.load(path)


@given(data=mutated_texts())
@example(data=b"name: x\ndomain: d.pddl\n\xff\n")  # not UTF-8: a UnicodeDecodeError escaped
@example(data=b"name: x\x00\n")  # a character YAML refuses: the message took three lines
@bounded(60)
def test_a_task_file_with_broken_text_loads_or_names_it(tmp_path, cached_scene_parse, data):
    path = tmp_path / "task.yaml"
    path.write_bytes(data)
    loads_or_names(path)


@given(data=mutated_texts() | mutated_docs().map(lambda d: yaml.safe_dump(d, allow_unicode=True).encode()))
@bounded(8)
def test_vap_bt_tree_on_a_broken_task_file_exits_as_documented(tmp_path, cli, data):
    path = tmp_path / "task.yaml"
    path.write_bytes(data)
    code, _, err = cli("tree", path)
    assert_one_line_on_stderr(code, err)


# -- 3. PDDL -------------------------------------------------------------------------------------

#: small domain/problem pairs of tests/domains that load and plan, between them typing, negative and
#: conditional effects, equality, quantifiers, ``either`` predicates, action costs from functions
PDDL_PAIRS = [("gripper-domain.pddl", "gripper-p4.pddl"), ("rooms-domain.pddl", "rooms-unreachable.pddl"),
              ("roads-domain.pddl", "roads-p1.pddl"), ("briefcase-domain.pddl", "briefcase-p1.pddl"),
              ("ferry-domain.pddl", "ferry-p1.pddl"), ("lamps-domain.pddl", "lamps-p1.pddl"),
              ("miconic-domain.pddl", "miconic-p1.pddl"), ("elevators-domain.pddl", "elevators-p1.pddl"),
              ("storage-domain.pddl", "storage-p1.pddl"), ("up-grounder-domain.pddl", "up-grounder-p1.pddl"),
              ("clash-domain.pddl", "clash-p1.pddl"), ("packing-domain.pddl", "packing-p1.pddl")]
TOKEN = re.compile(r"\(|\)|[^\s()]+")
REQUIREMENTS = [":strips", ":typing", ":negative-preconditions", ":disjunctive-preconditions", ":equality",
                ":existential-preconditions", ":universal-preconditions", ":quantified-preconditions",
                ":conditional-effects", ":action-costs", ":adl", ":numeric-fluents", ":fluents",
                ":derived-predicates", ":durative-actions", ":constraints", ":preferences", ":object-fluents",
                ":timed-initial-literals", ":bogus"]
JUNK_TOKENS = st.sampled_from(["(", ")", "?x", "-", "object", "not", "and", "or", "forall", "either", "when", "=",
                               ":parameters", ":precondition", ":effect", ":requirements", ":types", ":objects",
                               ":init", ":goal", ":metric", "minimize", "(total-cost)", "increase", "0", "-1",
                               "1.5", "1e400", "nan", "ü", ";", "define", "domain", "problem", ":domain"])
NUMBERS = st.integers(-10, 10**20).map(str) | st.sampled_from(["-0", "0.5", "1e400", "-1.5", "nan", "inf", "1/2",
                                                               ".", "007", "1e3"])


def _predicates_of(domain_text: str) -> list[str]:
    m = re.search(r"\(:predicates(.*?)\(:(?:action|functions|constants|derived)", domain_text, re.S | re.I)
    return re.findall(r"\(\s*([^\s()?]+)", m.group(1)) if m else []


@st.composite
def pddl_edits(draw, text: str, predicates: list[str]) -> str:
    """``text`` changed at one token (or its requirements, or a predicate's name), layout kept so
    that the line an error names is still the line the edit is on."""
    spans = [m.span() for m in TOKEN.finditer(text)]
    op = draw(st.sampled_from(["delete", "insert", "duplicate", "paren", "rename", "requirements", "number"]))
    a, b = spans[draw(st.integers(0, len(spans) - 1))]
    if op == "delete":
        return text[:a] + text[b:]
    if op == "insert":
        return text[:a] + draw(JUNK_TOKENS | st.sampled_from([text[x:y] for x, y in spans])) + " " + text[a:]
    if op == "duplicate":
        return text[:b] + " " + text[a:b] + text[b:]
    if op == "paren":  # a parenthesis lost, or one too many
        parens = [s for s in spans if text[s[0]] in "()"]
        a, b = draw(st.sampled_from(parens))
        return text[:a] + draw(st.sampled_from(["", "((", "))"])) + text[b:]
    if op == "rename" and predicates:
        name = draw(st.sampled_from(predicates))
        uses = [m.span(1) for m in re.finditer(r"\(\s*(" + re.escape(name) + r")[\s)]", text)]
        if uses:
            a, b = draw(st.sampled_from(uses))
            return text[:a] + draw(st.sampled_from([*predicates, name + "x", "at", "not", "=", "Ü"])) + text[b:]
    if op == "requirements" and ":requirements" in text:
        chosen = draw(st.lists(st.sampled_from(REQUIREMENTS), max_size=4, unique=True))
        return re.sub(r"\(:requirements[^)]*\)", lambda _: f"(:requirements {' '.join(chosen)})", text, count=1)
    numbers = [s for s in spans if re.fullmatch(r"-?\d+(\.\d+)?", text[s[0]:s[1]])]
    if numbers:  # a cost, a count: anything a person might type there
        a, b = draw(st.sampled_from(numbers))
        return text[:a] + draw(NUMBERS) + text[b:]
    return text[:a] + text[b:]


@st.composite
def goal_formulas(draw, predicates: list[str], objects: list[str], depth: int = 2) -> str:
    """A PDDL goal over the domain's predicates and the problem's objects (arity not checked):
    conjunctions, negations, equalities, the connectives the executive cannot check, quantifiers."""
    kind = draw(st.sampled_from(["atom", "atom", "=", "and", "not", "or", "imply", "forall", "exists"])
                if depth else st.sampled_from(["atom", "="]))
    if kind == "atom":
        return f"({' '.join([draw(st.sampled_from(predicates)), *draw(st.lists(st.sampled_from(objects), max_size=3))])})"
    if kind == "=":
        return f"(= {draw(st.sampled_from(objects))} {draw(st.sampled_from(objects))})"
    parts = draw(st.lists(goal_formulas(predicates, objects, depth - 1), max_size=3))
    if kind in ("forall", "exists"):  # a variable the body may not even use
        return f"({kind} (?v - object) {parts[0] if parts else '(and)'})"
    if kind in ("not", "imply"):
        parts = parts[:1 if kind == "not" else 2] or ["(and)"]
    return f"({kind} {' '.join(parts)})"


def _objects_of(problem_text: str) -> list[str]:
    m = re.search(r"\(:objects(.*?)\)", problem_text, re.S | re.I)
    return [w for w in m.group(1).split() if w != "-"] if m else ["x"]


@st.composite
def mutated_pddl(draw) -> tuple[str, str, str, str]:
    """(domain name, problem name, domain text, problem text), one of the two edited once or twice,
    or the problem given another goal."""
    dname, pname = draw(st.sampled_from(PDDL_PAIRS))
    dtext, ptext = (DOMAINS / dname).read_text(), (DOMAINS / pname).read_text()
    predicates = _predicates_of(dtext)
    if predicates and draw(st.integers(0, 3)) == 0:
        goal = draw(goal_formulas(predicates, _objects_of(ptext)))
        return dname, pname, dtext, re.sub(r"\(:goal.*\Z", lambda _: f"(:goal {goal}))\n", ptext, flags=re.S)
    for _ in range(draw(st.integers(1, 2))):
        if draw(st.booleans()):
            dtext = draw(pddl_edits(dtext, predicates))
        else:
            ptext = draw(pddl_edits(ptext, predicates))
    return dname, pname, dtext, ptext


def write_pddl(tmp_path: Path, case) -> tuple[Path, Path]:
    _, _, dtext, ptext = case
    d, p = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    d.write_text(dtext)
    p.write_text(ptext)
    return d, p


def edited(name: str, old: str, new: str) -> str:
    """A file of tests/domains with one edit, for explicit examples."""
    text = (DOMAINS / name).read_text()
    assert old in text, old
    return text.replace(old, new, 1)


def gripper(domain: str | None = None, problem: str | None = None) -> tuple:
    return ("gripper-domain.pddl", "gripper-p4.pddl", domain or (DOMAINS / "gripper-domain.pddl").read_text(),
            problem or (DOMAINS / "gripper-p4.pddl").read_text())


@given(case=mutated_pddl())
@example(case=gripper(problem=edited("gripper-p4.pddl", "(at ball1 roomb)", "(at ball1)")))  # two-line message
@example(case=gripper(domain=edited("gripper-domain.pddl", "; Gripper", "; Gr\u00efpper")))  # unicode comment
@bounded(50)
def test_a_broken_pddl_task_loads_and_plans_or_names_its_file(tmp_path, case):
    d, p = write_pddl(tmp_path, case)
    try:
        task = pddl.load_task(d, p)
    except Exception as exc:  # noqa: BLE001 — the property is about which exceptions arrive
        event(f"error: {type(exc).__name__}")
        assert_clear(exc, d, p)
        return
    try:
        Planner(task, first_engine="search", fd_timeout_s=10).plan()
        event("planned")
    except (UnsolvableError, PlanningTimeout) as exc:
        event(f"no plan: {type(exc).__name__}")
        assert_clear(exc)


@given(case=mutated_pddl())
@example(case=gripper(problem=edited("gripper-p4.pddl", "(:goal (and", "(:goal (or")))  # a goal the executive cannot check
@bounded(4)
def test_vap_bt_run_on_broken_pddl_exits_as_documented(tmp_path, cli, case):
    d, p = write_pddl(tmp_path, case)
    code, out, err = cli("run", "--domain", d, "--problem", p, "--world", "symbolic", "--no-injection",
                         "--vlm-noise", "0", "--json", "-q", "--transport", "inproc")
    assert_one_line_on_stderr(code, err)
    if code != EXIT_BAD_INPUT:  # a run that started ends with its summary, whatever the outcome
        assert "success" in json.loads(out)


# -- what the properties found, said precisely ---------------------------------------------------

def test_pddl_that_is_not_utf8_names_the_file_and_line(tmp_path):
    domain = tmp_path / "domain.pddl"
    domain.write_bytes((DOMAINS / "gripper-domain.pddl").read_bytes().replace(b"(:action move", b"(:action m\xf6ve"))
    with pytest.raises(InputError, match=r"domain\.pddl:6: not UTF-8 text \(byte 0xf6\)"):
        pddl.load_task(domain, DOMAINS / "gripper-p4.pddl")


@pytest.mark.parametrize("goal", ["(or)", "(= kitchen hall)"])
def test_a_goal_that_is_false_as_written_says_so(tmp_path, goal):
    problem = tmp_path / "p.pddl"
    problem.write_text(edited("rooms-unreachable.pddl", "(:goal (at r attic))", f"(:goal {goal})"))
    with pytest.raises(InputError, match="the goal can never hold"):
        pddl.load_task(DOMAINS / "rooms-domain.pddl", problem)


def test_a_missing_domain_file_is_the_task_files_field(tmp_path):
    path = write_task(tmp_path / "task.yaml", {**tree_doc("collect_cup.yaml"), "domain": "nope.pddl"})
    with pytest.raises(InputError, match=r"task\.yaml: field domain: no such PDDL file: .*nope\.pddl"):
        taskfile.load(path)


def test_a_missing_pddl_file_on_the_command_line_is_named_as_given(cli, tmp_path):
    code, _, err = cli("run", "--domain", tmp_path / "nope.pddl", "--problem", DOMAINS / "gripper-p4.pddl")
    assert code == EXIT_BAD_INPUT and err.strip() == f"vap-bt: {tmp_path / 'nope.pddl'}: no such file (given as --domain)"
