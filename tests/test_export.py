"""BehaviorTree.CPP XML export: the same tree, node for node, with BT.CPP's semantics."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from vap_bt.bt.export import NODE_MODELS, to_btcpp_xml

from conftest import TREES, tree_for


def walk(node):
    yield node
    for c in node.children:
        yield from walk(c)


def test_export_is_node_for_node(cup):
    task, actions = cup
    root = tree_for(task, actions, "both")
    doc = ET.fromstring(to_btcpp_xml(root))
    assert doc.tag == "root" and doc.get("BTCPP_format") == "4" and doc.get("main_tree_to_execute") == "plan"
    top = doc.find("BehaviorTree")
    exported = list(top[0].iter())
    ours = list(walk(root))
    assert len(exported) == len(ours)
    assert [e.get("name") for e in exported] == [n.name for n in ours]
    # memory sequences are BT.CPP Sequences (restart on failure, resume a running child)
    assert {e.tag for e in exported if e.get("name") in ("plan", "pre", "eff")} == {"Sequence"}
    # every custom node used is declared with its ports
    declared = {d.get("ID"): {p.get("name") for p in d} for d in doc.find("TreeNodesModel")}
    for e in exported:
        if e.tag in NODE_MODELS:
            assert set(e.attrib) - {"name"} <= declared[e.tag], e.tag
    grasp = next(e for e in exported if e.tag == "ExecuteSkill" and e.get("action") == "grasp")
    assert grasp.get("args") == ";".join(next(a for a in actions if a.name == "grasp").args)


def test_export_command_writes_a_file(cli, tmp_path):
    out = tmp_path / "tree.xml"
    code, _, _ = cli("export", TREES / "pick_plate.yaml", "--verify", "eff", "-o", out)
    doc = ET.parse(out).getroot()
    assert code == 0
    tags = {e.tag for e in doc.iter()}
    assert "ExecuteSkill" in tags and "VerifyPredicate" in tags
    assert not any(e.get("name") == "pre" for e in doc.iter()), "--verify eff has no precondition checks"


def test_an_action_level_baseline_exports_its_questions(cup):
    task, actions = cup
    doc = ET.fromstring(to_btcpp_xml(tree_for(task, actions, "suc_aff")))
    asked = [(e.get("phase"), e.get("action")) for e in doc.find("BehaviorTree").iter("VerifyAction")]
    assert asked and {p for p, _ in asked} == {"pre", "eff"} and {a for _, a in asked} <= {a.name for a in actions}
    assert not list(doc.iter("VerifyPredicate")) and doc.find("TreeNodesModel/Action[@ID='VerifyAction']") is not None
