"""Start-up: a command imports only what it uses (docs/BENCHMARKS.md, "Start-up (issue 25)").

Each check runs a command in a fresh interpreter and lists the modules it loaded: a check on what
was imported, not on seconds, so a busy machine cannot make it flake. The heavy modules are the
simulator, point clouds, the live view, kinematics, trajectory timing and scipy (which
unified-planning's engines would pull in through ConfigSpace, see :mod:`vap_bt.domain.up_engines`).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from conftest import DOMAINS, ROOT, TREES

#: what no command that neither simulates, moves an arm nor records may load
HEAVY = ("pybullet", "open3d", "rerun", "pinocchio", "toppra", "scipy", "ConfigSpace")
#: what hosts parts over Zenoh: the command line defines serve's and sim's arguments on every
#: start, and imports their servers only when one of those commands runs
SERVERS = {"vap_bt.transport.server", "vap_bt.transport.drivers", "vap_bt.transport.messages", "vap_bt.plugins"}


def loaded_by(code: str) -> tuple[set[str], str]:
    """The modules a fresh interpreter has loaded after ``code`` (which may print; its output is
    returned), run from the checkout."""
    program = ("import contextlib, io, json, sys\n"
               "out = io.StringIO()\n"
               "with contextlib.redirect_stdout(out):\n"
               + "".join(f"    {line}\n" for line in code.splitlines()) +
               "print(json.dumps({'modules': sorted(sys.modules), 'out': out.getvalue()}))\n")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    done = subprocess.run([sys.executable, "-c", program], cwd=ROOT, env=env, capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    result = json.loads(done.stdout.splitlines()[-1])
    return set(result["modules"]), result["out"]


def packages(modules: set[str]) -> set[str]:
    """The top-level packages of ``modules``."""
    return {m.split(".")[0] for m in modules}


def command(*argv: str) -> str:
    """``code`` for :func:`loaded_by` that runs ``vap-bt ARGV`` and fails unless it exits 0."""
    return (f"from vap_bt.app.cli import main\n"
            f"code = main({[str(a) for a in argv]!r})\n"
            f"assert code == 0, code")


def test_help_imports_none_of_the_heavy_modules_nor_unified_planning():
    modules, out = loaded_by("try:\n    " + command("--help").replace("\n", "\n    ")
                             + "\nexcept SystemExit as stop:\n    assert stop.code == 0")
    assert "usage: vap-bt" in out
    assert not packages(modules) & {*HEAVY, "unified_planning", "py_trees"}
    assert "vap_bt.settings" in modules  # every flag and default comes from the settings, nothing else of the executive
    assert not modules & {"vap_bt.bt.repeats", "vap_bt.bt.context", "vap_bt.perception.evidence", "vap_bt.perception.profile"}
    assert "numpy" not in modules and not modules & SERVERS


@pytest.mark.parametrize("argv", [("tree", TREES / "collect_cup.yaml"),
                                  ("plan", DOMAINS / "gripper-domain.pddl", DOMAINS / "gripper-p4.pddl")],
                         ids=["tree", "plan"])
def test_tree_and_plan_read_pddl_and_plan_without_the_heavy_modules(argv):
    modules, out = loaded_by(command(*argv))
    assert "unified_planning" in packages(modules) and out.strip()  # they read PDDL and printed a result
    assert not packages(modules) & set(HEAVY)
    assert not modules & SERVERS


def test_the_engines_leave_configspace_for_when_an_engine_builds_a_configuration_space():
    """unified-planning's engines load without ConfigSpace; the one thing they use it for still
    returns the real class, and a later import gets the real package."""
    modules, out = loaded_by("from vap_bt.domain import up_engines\n"
                             "up_engines.load()\n"
                             "assert 'ConfigSpace' not in sys.modules\n"
                             "from unified_planning.engines.engine import Engine\n"
                             "space = Engine.get_configuration_space()\n"
                             "import ConfigSpace\n"
                             "assert type(space) is ConfigSpace.ConfigurationSpace\n"
                             "print(ConfigSpace.__file__)")
    assert "ConfigSpace" in packages(modules) and out.strip().endswith("__init__.py")


def test_a_symbolic_run_moves_no_arm_so_loads_no_kinematics_nor_simulator():
    """The world performs the actions, so the skill classes load without their motion modules.
    scipy is used (the search's sparse matrices, the identifier's assignment), its statistics
    are not."""
    modules, out = loaded_by(command("run", TREES / "collect_cup.yaml", "--world", "symbolic", "--transport",
                                     "inproc", "--no-injection", "-q", "--json"))
    assert json.loads(out)["success"]
    assert "skills.manipulation" in modules and "skills.kit" not in modules
    assert not packages(modules) & (set(HEAVY) - {"scipy"})
    assert "scipy.stats" not in modules
