"""The layering rules of the design, checked on the source: data flows one way.

* the executive (domain, scene, perception, bt) never imports pybullet;
* skills and the transport never import py_trees;
* only vap_bt/viz imports rerun;
* motion is pure array code: no pybullet, no py_trees.
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
