"""BehaviorTree.CPP 4 itself loads and ticks the export of every task file.

The exported XML (``vap-bt export TASK``) goes into BT.CPP's own factory through the
``behaviortreepy`` bindings (PyPI), with a Python node registered for every ID of the export's
``TreeNodesModel`` (ExecuteSkill, ApplyEffects, VerifyPredicate, ActivePerception, GoalCheck, FeelHand), and is
ticked to the end. BT.CPP's ``FileLogger2`` records what BT.CPP built and ran: its dump of the
instantiated tree (tags, names, UIDs) and every status transition, which the test reads back.

**Ports.** behaviortreepy 0.1.4 registers Python nodes (``register_simple_action`` /
``_condition`` / ``_decorator`` / ``_stateful_action``) without a port list: their
``providedPorts()`` is empty, and BT.CPP rejects any XML attribute that is not a declared port ("a
port with name [action] is found in the XML ... but not in the providedPorts() of its registered
node type"). So before loading, the test checks that every attribute of a custom node is an input
port its ID declares in the export's ``TreeNodesModel`` (the contract a C++ runtime registers
against), then moves exactly those attributes out of the XML into a table keyed by the node's BT.CPP
UID. UIDs are handed out in document order; the test confirms this against BT.CPP's own dump of the
instantiated tree. The registered nodes read their port values from that table by
``node.uid()``. Everything else stays in the XML and reaches BT.CPP: an undeclared attribute, an
unregistered node ID, or a control node without children still fails the load.
"""

from __future__ import annotations

from collections import Counter

import functools
import gc
import struct
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import behaviortreepy as btpy
import pytest

from conftest import HOUSEHOLD_TASKS, TREES, tree_for

S = btpy.NodeStatus
#: BT.CPP's NodeStatus numbering, as FileLogger2 writes it
IDLE, RUNNING, SUCCESS, FAILURE = 0, 1, 2, 3


@functools.cache
def planned(task_file: str):
    """The task's planning task and the first plan from its stated initial state (as ``export``)."""
    from vap_bt.domain.planner import Planner
    from vap_bt.taskfile import load

    planning = load(TREES / task_file).planning
    return planning, Planner(planning).plan().actions


def declared_ports(doc: ET.Element) -> dict[str, set[str]]:
    return {d.get("ID"): {p.get("name") for p in d if p.tag == "input_port"} for d in doc.find("TreeNodesModel")}


def without_ports(xml: str) -> tuple[str, dict[int, dict[str, str]]]:
    """The XML with every declared port attribute of a custom node moved out, and the ports by UID
    (document order from 1, BT.CPP's numbering)."""
    doc = ET.fromstring(xml)
    model = declared_ports(doc)
    ports: dict[int, dict[str, str]] = {}
    for uid, el in enumerate(doc.find("BehaviorTree")[0].iter(), start=1):
        if el.tag not in model:
            continue
        undeclared = set(el.attrib) - {"name"} - model[el.tag]
        assert not undeclared, f"{el.tag} {el.get('name')!r}: attributes {undeclared} are not declared ports"
        ports[uid] = {p: el.attrib.pop(p) for p in model[el.tag] if p in el.attrib}
    return ET.tostring(doc, encoding="unicode"), ports


def read_btlog(path: Path) -> tuple[ET.Element, list[tuple[int, int]]]:
    """BT.CPP's FileLogger2 file: its dump of the instantiated tree, and the (uid, status) transitions."""
    data = path.read_bytes()
    magic = b"BTCPP4-FileLogger2"
    assert data.startswith(magic) and data[len(magic)] == 1, "not a FileLogger2 (protocol 1) file"
    at = len(magic) + 1
    (n,) = struct.unpack_from("<i", data, at)
    tree = ET.fromstring(data[at + 4:at + 4 + n])
    body = data[at + 4 + n + 8:]  # after the XML: the first timestamp (8 bytes), then 9 bytes a transition
    assert len(body) % 9 == 0
    transitions = [(int.from_bytes(body[i + 6:i + 8], "little"), body[i + 8]) for i in range(0, len(body), 9)]
    return tree, transitions


@dataclass
class BtcppRun:
    """One load-and-tick of an exported tree in BT.CPP, with what every registered node saw."""

    status: S
    instantiated: list[ET.Element]  # BT.CPP's own tree, in document order
    transitions: list[tuple[int, int]]
    calls: list[tuple[str, int]] = field(default_factory=list)  # (node ID, uid) per tick of a custom node
    ports: dict[int, dict[str, str]] = field(default_factory=dict)

    def skills(self) -> list[str]:
        """The actions ExecuteSkill started, in order, as ``name(arg, ...)``."""
        return [f"{self.ports[u]['action']}({', '.join(filter(None, self.ports[u]['args'].split(';')))})"
                for kind, u in self.calls if kind == "ExecuteSkill:start"]

    def reached(self, status: int) -> set[int]:
        return {u for u, s in self.transitions if s == status}


def run_in_btcpp(xml: str, tmp_path: Path, verdict=lambda ports: True) -> BtcppRun:
    """Load ``xml`` into BT.CPP with the executive's node IDs registered and tick it to the end.

    ExecuteSkill is a stateful action that is RUNNING for one tick, like a goal in flight;
    VerifyPredicate, likewise RUNNING for one tick (its round in flight), then answers
    ``verdict(ports)``; the others succeed. Ticks are bounded, so a tree
    that keeps re-running finished work ends RUNNING (and fails the test) instead of hanging."""
    loadable, ports = without_ports(xml)
    calls: list[tuple[str, int]] = []

    def leaf(kind: str, result=lambda node: S.SUCCESS):
        def tick(node):
            calls.append((kind, node.uid()))
            return result(node)
        return tick

    factory = btpy.BehaviorTreeFactory()
    registered = {
        "ExecuteSkill": lambda: factory.register_simple_stateful_action(
            "ExecuteSkill", leaf("ExecuteSkill:start", lambda n: S.RUNNING), leaf("ExecuteSkill:done"),
            lambda node: calls.append(("ExecuteSkill:halted", node.uid()))),
        "ApplyEffects": lambda: factory.register_simple_action("ApplyEffects", leaf("ApplyEffects")),
        "VerifyPredicate": lambda: factory.register_simple_stateful_action(  # a round in flight, then its answer
            "VerifyPredicate", leaf("VerifyPredicate:start", lambda n: S.RUNNING), leaf(
                "VerifyPredicate", lambda n: S.SUCCESS if verdict(ports[n.uid()]) else S.FAILURE),
            lambda node: calls.append(("VerifyPredicate:halted", node.uid()))),
        "VerifyAction": lambda: factory.register_simple_action("VerifyAction", leaf("VerifyAction")),
        "ActivePerception": lambda: factory.register_simple_decorator(
            "ActivePerception", lambda child, node: (calls.append(("ActivePerception", node.uid())), child)[1]),
        "GoalCheck": lambda: factory.register_simple_condition("GoalCheck", leaf("GoalCheck")),
        "FeelHand": lambda: factory.register_simple_condition("FeelHand", leaf("FeelHand")),
    }
    model = declared_ports(ET.fromstring(xml))
    assert set(model) == set(registered), "a node ID of the export has no BT.CPP registration here (or vice versa)"
    for register in registered.values():
        register()
    tree = factory.create_tree_from_text(loadable)
    log = tmp_path / "run.btlog"
    logger = btpy.FileLogger(tree, str(log))
    status = S.RUNNING
    for _ in range(2 * len(ports) + 10):  # bounded: a tree that re-runs finished work never ends
        status = tree.tick_once()
        if status != S.RUNNING:
            break
    # FileLogger2 queues transitions for a writer thread that wakes at least every 10 ms; its
    # destructor stops that thread without draining the queue, so give it time to drain first
    time.sleep(0.1)
    del logger  # closes the file
    gc.collect()
    instantiated, transitions = read_btlog(log)
    return BtcppRun(status, list(instantiated.find("BehaviorTree")[0].iter()), transitions, calls, ports)


def walk(node):
    yield node
    for c in node.children:
        yield from walk(c)


@pytest.mark.parametrize("task_file", HOUSEHOLD_TASKS)
def test_every_task_export_loads_and_ticks_in_btcpp(task_file, tmp_path):
    from vap_bt.bt.export import to_btcpp_xml

    planning, actions = planned(task_file)
    root = tree_for(planning, actions, "both")
    xml = to_btcpp_xml(root)  # what `vap-bt export` writes (the command itself: the tests below)
    ours = list(walk(root))
    run = run_in_btcpp(xml, tmp_path)

    assert run.status == S.SUCCESS
    # BT.CPP built the tree node for node: same count, order, types and names as py_trees'
    exported = list(ET.fromstring(xml).find("BehaviorTree")[0].iter())
    assert len(run.instantiated) == len(exported) == len(ours)
    assert [(e.tag, e.get("name")) for e in run.instantiated] == [(e.tag, e.get("name")) for e in exported]
    assert [int(e.get("_uid")) for e in run.instantiated] == list(range(1, len(ours) + 1))
    # every node ran to SUCCESS, none failed
    assert run.reached(SUCCESS) == set(range(1, len(ours) + 1))
    assert not run.reached(FAILURE)
    # each custom node ticked once per tick its work took, and no more: memory Sequences resume
    # the running skill or check rather than re-ticking the checks before it (a ReactiveSequence
    # would check them again on every tick). A check's round is in flight for one tick and
    # answered on the next, so its decorator sees two ticks; the rest one
    custom = {u: e.tag for u, e in enumerate(exported, start=1) if e.tag in ("VerifyPredicate", "ActivePerception",
                                                                             "ApplyEffects", "GoalCheck")}
    ticks = Counter(u for k, u in run.calls if k in custom.values())
    assert set(ticks) == set(custom)
    assert {u: n for u, n in ticks.items() if n != (2 if custom[u] == "ActivePerception" else 1)} == {}
    assert run.skills() == [str(a) for a in actions]
    assert [k for k, _ in run.calls].count("ExecuteSkill:done") == len(actions)


def test_a_failed_check_fails_the_tree_where_it_stands(cli, tmp_path):
    """The effect check of the grasp fails: BT.CPP stops there, as py_trees does — nothing after it
    runs, the failure climbs to the root, and the goal is never checked."""
    planning, actions = planned("collect_cup.yaml")
    code, xml, _ = cli("export", TREES / "collect_cup.yaml")
    assert code == 0
    run = run_in_btcpp(xml, tmp_path, verdict=lambda p: not (p["predicate"] == "holding" and p["args"] == "cup"))
    assert run.status == S.FAILURE
    grasp = next(i for i, a in enumerate(actions) if a.name == "grasp")
    assert run.skills() == [str(a) for a in actions[:grasp + 1]]
    assert "GoalCheck" not in {k for k, _ in run.calls}
    failed = run.reached(FAILURE)
    by_uid = {int(e.get("_uid")): e for e in run.instantiated}
    assert {by_uid[u].get("name") for u in failed} == {
        "holding(cup)", "look(K=3)", "eff", f"a{grasp}: {actions[grasp]}", "plan"}


def test_the_bindings_cannot_declare_ports_so_the_xml_would_not_load_as_is(cli):
    """Why the ports are moved aside: the unmodified export names ports the bindings' nodes lack."""
    _, xml, _ = cli("export", TREES / "collect_cup.yaml")
    factory = btpy.BehaviorTreeFactory()
    factory.register_simple_action("ExecuteSkill", lambda node: S.SUCCESS)
    factory.register_simple_action("ApplyEffects", lambda node: S.SUCCESS)
    factory.register_simple_action("VerifyPredicate", lambda node: S.SUCCESS)
    factory.register_simple_decorator("ActivePerception", lambda child, node: child)
    factory.register_simple_condition("GoalCheck", lambda node: S.SUCCESS)
    factory.register_simple_condition("FeelHand", lambda node: S.SUCCESS)
    with pytest.raises(RuntimeError, match="not in the providedPorts"):
        factory.create_tree_from_text(xml)


def test_an_empty_control_node_is_refused_by_btcpp_and_never_exported():
    """The load error of issue 11, reproduced on BT.CPP, and the export's answer to a hand-built tree."""
    import py_trees

    from vap_bt.bt.export import to_btcpp_xml

    with pytest.raises(RuntimeError, match="must have 1 or more children"):
        btpy.BehaviorTreeFactory().create_tree_from_text(
            '<root BTCPP_format="4"><BehaviorTree ID="t"><Sequence name="s"><Sequence name="pre"/>'
            '</Sequence></BehaviorTree></root>')
    root = py_trees.composites.Sequence("plan", memory=True, children=[
        py_trees.composites.Sequence("pre", memory=True), py_trees.composites.Selector("any", memory=False),
        py_trees.behaviours.Success("ok")])
    with pytest.raises(ValueError, match="no BehaviorTree.CPP mapping"):
        to_btcpp_xml(root)  # a plain py_trees leaf has no mapping: say so, never guess
    root.remove_child(root.children[-1])
    tree = btpy.BehaviorTreeFactory().create_tree_from_text(to_btcpp_xml(root))
    assert tree.tick_while_running() == S.FAILURE  # py_trees: empty sequence succeeds, empty selector fails


def test_the_compiler_emits_no_empty_check_sequence():
    import py_trees

    for task_file in HOUSEHOLD_TASKS:
        planning, actions = planned(task_file)
        for mode in ("both", "pre", "eff"):
            empty = [n.name for n in walk(tree_for(planning, actions, mode))
                     if isinstance(n, py_trees.composites.Composite) and not n.children]
            assert not empty, (task_file, mode, empty)
