"""The layering rules of the design, checked on the source: data flows one way.

* the executive (domain, scene, perception, bt, robot) never imports pybullet or the simulator
  (vap_bt.sim, vap_bt.world), never reads an oracle, and holds nothing that reaches one; nor do
  the skills import the simulator or read an oracle (they move the robot through its drivers and
  know what its camera shows, re-identified by themselves);
* skills and the transport never import py_trees;
* only vap_bt/viz imports rerun;
* motion is pure array code: no pybullet, no py_trees;
* the simulator decides no motion: it plans nothing (no IK, no collision checks, no path timing)
  and imports no skill; its drivers only track what they are given, as a robot's controllers do.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from conftest import ROOT


def imports(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(), filename=str(path))
    out: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.add(node.module.split(".")[0])
    return out


def files(*rooms: str) -> list[Path]:
    return sorted(p for r in rooms for p in (ROOT / r).rglob("*.py"))


RULES = [
    (("vap_bt/domain", "vap_bt/scene", "vap_bt/perception", "vap_bt/bt"), "pybullet"),
    (("skills", "vap_bt/transport"), "py_trees"),
    (("vap_bt/motion",), "pybullet"),
    (("vap_bt/motion",), "py_trees"),
]


@pytest.mark.parametrize("rooms,forbidden", RULES, ids=[f"{'+'.join(r)}-no-{f}" for r, f in RULES])
def test_room_does_not_import(rooms, forbidden):
    offenders = [str(p.relative_to(ROOT)) for p in files(*rooms) if forbidden in imports(p)]
    assert files(*rooms), f"no source found under {rooms}"
    assert not offenders, f"{forbidden} imported by {offenders}"


def test_only_viz_imports_rerun():
    offenders = [str(p.relative_to(ROOT)) for p in files("vap_bt", "skills", "robots")
                 if "rerun" in imports(p) and "vap_bt/viz" not in str(p)]
    assert not offenders, offenders


EXECUTIVE_ROOMS = ("vap_bt/domain", "vap_bt/scene", "vap_bt/perception", "vap_bt/bt", "vap_bt/robot")
#: where no code may reach the simulator or its truth: the executive and the skills
ORACLE_FREE_ROOMS = (*EXECUTIVE_ROOMS, "skills")


def module_imports(path: Path) -> set[str]:
    """Dotted names of the modules ``path`` imports (absolute imports only)."""
    tree = ast.parse(path.read_text(), filename=str(path))
    out: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.add(node.module)
    return out


def test_the_executive_side_never_imports_the_simulator():
    """Neither the executive nor the skills import the simulator (skills may name the World
    contract they are bound to, :mod:`vap_bt.world`: it holds no truth)."""
    offenders = {str(p.relative_to(ROOT)): sorted(m for m in module_imports(p) if m == "vap_bt.sim"
                                                  or m.startswith("vap_bt.sim.")
                                                  or (m == "vap_bt.world" and "skills" not in p.parts))
                 for p in files(*ORACLE_FREE_ROOMS)}
    assert files("skills"), "no source found under skills"
    assert not {k: v for k, v in offenders.items() if v}


#: what of vap_bt.motion a robot's controllers use too: the joint limits and the jerk-limited
#: point-to-point profile of the base driver (a base controller's own, not a plan)
CONTROLLER_MOTION = {"vap_bt.motion.limits", "vap_bt.motion.tracking"}
#: and rigid-body maths, no planning: the simulator's cameras are posed with the skills' look_pose
GEOMETRY = {"vap_bt.motion.se3"}
PLANNING = ("vap_bt.motion", "skills", "pinocchio", "toppra", "coal")


def test_the_simulator_decides_no_motion():
    """Nothing under vap_bt/sim plans how the robot moves: no IK, collision checking or path
    timing (vap_bt.motion beyond the controllers' limits and profile, pinocchio, toppra, coal)
    and no skill code; motion is the skills', through the drivers."""
    offenders = {str(p.relative_to(ROOT)): sorted(m for m in module_imports(p) - CONTROLLER_MOTION - GEOMETRY
                                                  if any(m == r or m.startswith(r + ".") for r in PLANNING))
                 for p in files("vap_bt/sim")}
    assert files("vap_bt/sim"), "no source found under vap_bt/sim"
    assert not {k: v for k, v in offenders.items() if v}
    used = {m for p in files("vap_bt/sim") for m in module_imports(p)}
    assert CONTROLLER_MOTION | GEOMETRY <= used  # the allowance is what the sim really imports, no more


def identifiers(path: Path) -> list[tuple[str, str]]:
    """(identifier, what it belongs to) for every name, attribute and argument in the code
    (docstrings and comments are not code)."""
    out = []
    for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
        if isinstance(node, ast.Name):
            out.append((node.id, ""))
        elif isinstance(node, ast.Attribute):
            out.append((node.attr, ast.unparse(node.value)))
        elif isinstance(node, ast.arg):
            out.append((node.arg, ""))
    return out


def test_the_executive_side_never_reads_an_oracle():
    """No executive-side or skill code names an oracle or a truth, or asks anything but its own
    scene graph whether an atom holds."""
    hits = [f"{p.relative_to(ROOT)}: {owner + '.' if owner else ''}{name}" for p in files(*ORACLE_FREE_ROOMS)
            for name, owner in identifiers(p)
            if "oracle" in name.lower() or "truth" in name.lower()
            or (name == "holds" and owner and not owner.endswith("graph") and owner != "self")]
    assert not hits, hits


def reachable(root: object, skip: set[int] = frozenset(), limit: int = 200_000):
    """Every object reachable from ``root`` through references (modules, classes and functions'
    globals are not followed: they lead everywhere and hold no episode's state; nor are the
    objects in ``skip``)."""
    import gc
    import types

    seen, todo = {id(root), *skip}, [root]
    while todo and len(seen) < limit:
        obj = todo.pop()
        yield obj
        for ref in gc.get_referents(obj):
            if isinstance(ref, (types.ModuleType, type)) or id(ref) in seen:
                continue
            if isinstance(ref, dict) and "__builtins__" in ref:  # a module's or function's globals
                continue
            seen.add(id(ref))
            todo.append(ref)


@pytest.mark.slow
def test_no_object_the_executive_holds_can_reach_the_oracle():
    """Over the embedded Zenoh transport (the default), everything the executive is handed — skill
    client, camera and body, VLM, planner, task — and everything it builds leads to no world and
    no oracle: its senses are Zenoh clients."""
    from vap_bt import taskfile
    from vap_bt.bt.executive import Executive
    from vap_bt.app.runner import RunConfig, Session
    from vap_bt.sim.oracle import FunctionOracle
    from vap_bt.sim.symbolic import SymbolicWorld

    task = taskfile.load(ROOT / "trees" / "collect_cup.yaml")
    session = Session(task, RunConfig.from_task(task, world="symbolic", transport="zenoh", injection=False,
                                                vlm_noise=0.0))
    held: list[Executive] = []
    original = Executive.run

    def keep(self):
        held.append(self)
        return original(self)

    Executive.run = keep
    try:
        report = session.episode(0)
    finally:
        Executive.run = original
        session.close()
    assert report["success"] and held
    executive = held[0]
    # the runner's instrumentation (progress lines, the rerun recorder, the survey, verification
    # and situation scorers) is handed information and returns none; it is where the walk stops
    hooks = {id(executive.progress), id(executive.on_tree), id(executive.on_survey), id(executive.on_verification),
             id(executive.on_situation)}
    found = [type(o).__name__ for o in reachable(executive, skip=hooks) if isinstance(o, (FunctionOracle, SymbolicWorld))]
    assert not found, found
    # and the check itself can see an oracle where there is one
    assert any(isinstance(o, FunctionOracle) for o in reachable(session))


# -- the executive's geometric thresholds are its own ---------------------------------------------


def _relative_imports(path: Path) -> set[str]:
    """Dotted names of the modules ``path`` imports relatively, resolved against its package."""
    package = path.relative_to(ROOT).with_suffix("").parts[:-1]
    out: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
        if isinstance(node, ast.ImportFrom) and node.level > 0:
            base = package[:len(package) - (node.level - 1)]
            out.add(".".join((*base, *(node.module.split(".") if node.module else ()))))
    return out


def test_the_scene_graph_never_imports_the_simulator():
    """vap_bt/scene (the RGB-D scene graph, its relations) imports nothing of vap_bt.sim, however
    written (absolute or relative), nor pybullet."""
    offenders = {str(p.relative_to(ROOT)): sorted(m for m in module_imports(p) | _relative_imports(p)
                                                  if m == "vap_bt.sim" or m.startswith("vap_bt.sim.")
                                                  or m.split(".")[0] == "pybullet")
                 for p in files("vap_bt/scene")}
    assert files("vap_bt/scene") and not {k: v for k, v in offenders.items() if v}


def _module_constants(path: Path, module: str) -> dict[str, float]:
    """The module-level numeric constants (UPPER_CASE names) of ``path``, importable as
    ``module``, by name, with their values."""
    import importlib

    names = set()
    for node in ast.parse(path.read_text(), filename=str(path)).body:
        targets = node.targets if isinstance(node, ast.Assign) else [node.target] if isinstance(node, ast.AnnAssign) else []
        names |= {t.id for t in targets if isinstance(t, ast.Name) and t.id.isupper()}
    mod = importlib.import_module(module)
    values = {n: getattr(mod, n) for n in names}
    return {n: float(v) for n, v in values.items() if isinstance(v, (int, float)) and not isinstance(v, bool)}


def test_the_relation_thresholds_are_not_the_oracles():
    """Every default of :class:`vap_bt.scene.relations.Thresholds` is a number written there (with
    its reason), none is a name, none of the oracle's constant names appears anywhere in
    vap_bt/scene, and no threshold equals one of the oracle's constants: the executive's
    perception and the truth it is scored against share nothing by construction."""
    relations = ROOT / "vap_bt/scene/relations.py"
    cls = next(n for n in ast.walk(ast.parse(relations.read_text())) if isinstance(n, ast.ClassDef) and n.name == "Thresholds")
    fields = [n for n in cls.body if isinstance(n, ast.AnnAssign)]
    assert fields and all(isinstance(f.value, ast.Constant) and isinstance(f.value.value, float) for f in fields), \
        "every threshold is a literal number"
    values = {f.target.id: f.value.value for f in fields}
    oracle = _module_constants(ROOT / "vap_bt/sim/pb_truth.py", "vap_bt.sim.pb_truth")
    assert {"CONTACT_GAP", "SUPPORT_NORMAL"} <= set(oracle)  # the oracle's physical tolerances
    used = {name for p in files("vap_bt/scene") for name, _ in identifiers(p)}
    assert not used & set(oracle), f"oracle constants named in vap_bt/scene: {sorted(used & set(oracle))}"
    shared = {k: v for k, v in values.items() if any(abs(v - c) < 1e-12 for c in oracle.values())}
    assert not shared, f"thresholds equal to an oracle constant: {shared}"
    from vap_bt.scene.relations import THRESHOLDS, Thresholds

    assert THRESHOLDS == Thresholds() and {k: getattr(THRESHOLDS, k) for k in values} == values


def test_the_composition_root_is_imported_from_the_command_line_only():
    """:mod:`vap_bt.app` wires the parts together; no part imports it back (no arrow up;
    ``python -m vap_bt`` is its door), and the wire (:mod:`vap_bt.transport`) knows neither
    the parts' wiring nor the tree."""
    below = [p for p in files("vap_bt") if "vap_bt/app" not in str(p) and p.name != "__main__.py"]
    offenders = {str(p.relative_to(ROOT)): sorted(m for m in module_imports(p)
                                                  if m == "vap_bt.app" or m.startswith("vap_bt.app."))
                 for p in below}
    assert below
    assert not {k: v for k, v in offenders.items() if v}
    wire = {str(p.relative_to(ROOT)): sorted(m for m in module_imports(p)
                                             if any(m == r or m.startswith(r + ".")
                                                    for r in ("vap_bt.app", "vap_bt.bt", "vap_bt.sim", "vap_bt.viz")))
            for p in files("vap_bt/transport")}
    assert files("vap_bt/transport")
    assert not {k: v for k, v in wire.items() if v}


# -- the executive names no household predicate -------------------------------------------------------

#: the words of a task file's scene format (``place: on table``, a door's ``state: open``): the file's
#: own syntax, which :func:`vap_bt.scene.layout.layout_facts` writes out in the roles' predicates
LAYOUT_WORDS = {"on", "inside", "open", "closed"}


def _household_vocabulary() -> tuple[set[str], set[str]]:
    """The household domain's predicates and types, as its PDDL declares them."""
    import re

    text = (ROOT / "domains" / "household.pddl").read_text()
    types = text[text.index("(:types"):text.index("(:predicates")]
    block = text[text.index("(:predicates"):text.index("(:action")]
    return set(re.findall(r"\(\s*([a-z][a-z0-9_-]*)", block)) - {"predicates"}, \
        set(re.findall(r"[a-z][a-z0-9_-]*", types.split(None, 1)[1])) - {"object"}


def string_literals(path: Path) -> list[tuple[int, str]]:
    """(line, text) of every string constant in the code (docstrings are not code)."""
    tree = ast.parse(path.read_text(), filename=str(path))
    docs = {id(n.body[0].value) for n in ast.walk(tree)
            if isinstance(n, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))
            and n.body and isinstance(n.body[0], ast.Expr) and isinstance(n.body[0].value, ast.Constant)}
    return [(n.lineno, n.value) for n in ast.walk(tree)
            if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docs]


def household_literals(*rooms: str) -> list[str]:
    """Every string constant in ``rooms`` that is a household predicate or type, except the scene
    layout's format words and the household types a layout's scene is written in."""
    predicates, types = _household_vocabulary()
    layout = ROOT / "vap_bt/scene/layout.py"
    return [f"{p.relative_to(ROOT)}:{line}: {text!r}" for p in files(*rooms) for line, text in string_literals(p)
            if (text in predicates and not (p == layout and text in LAYOUT_WORDS))
            or (text in types and p != layout)]


def test_the_executive_names_no_household_predicate():
    """What a predicate means to the executive (in view, held, on, in a room...) is the perception
    profile's word (:mod:`vap_bt.domain.roles`), so ``bt/`` and ``scene/`` name no predicate or type
    of the household; the household's names are the roles' defaults, in vap_bt/domain/roles.py."""
    predicates, types = _household_vocabulary()
    assert {"inview", "holding", "hand_empty", "on", "in_room"} <= predicates and {"item", "room"} <= types
    hits = household_literals("vap_bt/bt", "vap_bt/scene")
    assert files("vap_bt/bt") and files("vap_bt/scene")
    assert not hits, hits
    # the check sees a literal where there is one: the world speaks the household
    assert any("symbolic.py" in h and "'holding'" in h for h in household_literals("vap_bt/sim"))
    defaults = {t for _, t in string_literals(ROOT / "vap_bt/domain/roles.py")}
    assert {"inview", "holding", "hand_empty", "item", "room"} <= defaults
