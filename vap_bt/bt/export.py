"""Export a compiled tree as BehaviorTree.CPP (v4) XML, so it can be read, diffed, or opened in
Groot and other BT.CPP tools.

Composites map by semantics, not by name: a py_trees ``Sequence(memory=True)`` restarts after a
failure and resumes a running child, which is BT.CPP's ``Sequence``; without memory it is
``ReactiveSequence``; selectors map to ``Fallback``/``ReactiveFallback`` likewise. The executive's
own nodes are declared in a ``TreeNodesModel`` with their ports, and their parameters become port
attributes (``action``, ``args``, ``predicate``, ...), so a BT.CPP runtime that registers nodes of
those IDs ticks the same tree (``tests/test_btcpp.py`` loads and ticks every task's export in
BehaviorTree.CPP 4 itself).

BT.CPP refuses a control node without children, where py_trees ticks it to its result at once
(an empty sequence succeeds, an empty selector fails). The compiler emits none, but a tree built
by hand may hold one: it is written as the leaf with that result (``AlwaysSuccess`` /
``AlwaysFailure``) under the same name, so the export stays node for node and always loads.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import py_trees

from vap_bt.bt.action_check import VerifyAction
from vap_bt.bt.active_perception import ActivePerception
from vap_bt.bt.apply_effects import ApplyEffects
from vap_bt.bt.execute_skill import ExecuteSkill
from vap_bt.bt.feel_hand import FeelHand
from vap_bt.bt.goal_check import GoalCheck
from vap_bt.bt.verify_predicate import VerifyPredicate

#: the executive's node types: BT.CPP kind and the input ports each declares
NODE_MODELS: dict[str, tuple[str, tuple[str, ...]]] = {
    "ExecuteSkill": ("Action", ("action", "args")),
    "ApplyEffects": ("Action", ("action", "args")),
    "VerifyPredicate": ("Action", ("predicate", "args", "expected")),  # RUNNING while its round is in flight
    "VerifyAction": ("Action", ("phase", "action", "args")),  # an action-level question (the baselines')
    "ActivePerception": ("Decorator", ("budget", "phase")),
    "GoalCheck": ("Condition", ("goal",)),
    "FeelHand": ("Condition", ("action", "args")),
}


def _args(xs) -> str:
    return ";".join(xs)  # BT.CPP's separator for vector-like port values


def _element(node: py_trees.behaviour.Behaviour) -> ET.Element:
    if isinstance(node, py_trees.composites.Composite) and not node.children:
        el = ET.Element("AlwaysFailure" if isinstance(node, py_trees.composites.Selector) else "AlwaysSuccess")
    elif isinstance(node, py_trees.composites.Sequence):
        el = ET.Element("Sequence" if node.memory else "ReactiveSequence")
    elif isinstance(node, py_trees.composites.Selector):
        el = ET.Element("Fallback" if node.memory else "ReactiveFallback")
    elif isinstance(node, py_trees.composites.Parallel):
        el = ET.Element("Parallel", success_count=str(len(node.children)), failure_count="1")
    elif isinstance(node, ActivePerception):
        el = ET.Element("ActivePerception", budget=str(node.ctx.budget), phase=node.phase)
    elif isinstance(node, VerifyPredicate):
        el = ET.Element("VerifyPredicate", predicate=node.atom.predicate, args=_args(node.atom.args),
                        expected=str(node.expected).lower())
    elif isinstance(node, VerifyAction):
        el = ET.Element("VerifyAction", phase=node.phase, action=node.action.name, args=_args(node.action.args))
    elif isinstance(node, (ExecuteSkill, ApplyEffects, FeelHand)):
        el = ET.Element(type(node).__name__, action=node.action.name, args=_args(node.action.args))
    elif isinstance(node, GoalCheck):
        el = ET.Element("GoalCheck", goal=_args(str(l) for l in node.goal))
    else:
        raise ValueError(f"no BehaviorTree.CPP mapping for {type(node).__name__} ({node.name!r})")
    el.set("name", node.name)
    for child in node.children:
        el.append(_element(child))
    return el


def to_btcpp_xml(root: py_trees.behaviour.Behaviour, tree_id: str = "plan") -> str:
    """The tree under ``root`` as a BehaviorTree.CPP v4 document named ``tree_id``, with the executive's
    node models."""
    doc = ET.Element("root", BTCPP_format="4", main_tree_to_execute=tree_id)
    bt = ET.SubElement(doc, "BehaviorTree", ID=tree_id)
    bt.append(_element(root))
    model = ET.SubElement(doc, "TreeNodesModel")
    for node_id, (kind, ports) in NODE_MODELS.items():
        decl = ET.SubElement(model, kind, ID=node_id)
        for p in ports:
            ET.SubElement(decl, "input_port", name=p)
    ET.indent(doc)
    return ET.tostring(doc, encoding="unicode", xml_declaration=False) + "\n"
