"""PlanTree ticks as py_trees' BehaviourTree does, without walking the whole tree after each tick
unless a visitor asks for the full tree."""

from __future__ import annotations

import py_trees
from py_trees.common import Status

from vap_bt.bt.plan_tree import PlanTree


def _plan(n: int) -> py_trees.composites.Sequence:
    """n steps, each running for two ticks, then succeeding."""
    steps = [py_trees.behaviours.StatusQueue(f"a{k}", queue=[Status.RUNNING, Status.RUNNING], eventually=Status.SUCCESS)
             for k in range(n)]
    return py_trees.composites.Sequence("plan", memory=True, children=steps)


class Walk(py_trees.visitors.VisitorBase):
    """A visitor that wants every node, every tick (as py_trees' full visitors do)."""

    def __init__(self) -> None:
        super().__init__(full=True)
        self.seen = 0

    def run(self, behaviour) -> None:
        self.seen += 1


def _ticks(tree_class, n: int, visitors=()) -> list[tuple[Status, ...]]:
    tree = tree_class(_plan(n))
    for v in visitors:
        tree.add_visitor(v)
    handled = []
    tree.add_pre_tick_handler(lambda t: handled.append("pre"))
    tree.add_post_tick_handler(lambda t: handled.append("post"))
    out = []
    while tree.root.status != Status.SUCCESS:
        tree.tick()
        out.append(tuple(b.status for b in tree.root.iterate()))
    assert handled == ["pre", "post"] * len(out) and tree.count == len(out)
    return out


def test_a_plan_tree_ticks_as_a_behaviour_tree_does():
    assert _ticks(PlanTree, 5) == _ticks(py_trees.trees.BehaviourTree, 5)


def test_the_whole_tree_is_walked_only_for_a_visitor_that_asks_for_it(monkeypatch):
    walked = []
    real = py_trees.behaviour.Behaviour.iterate

    def counting(self, direct_descendants=False):
        if self.name == "plan":
            walked.append(1)
        return real(self, direct_descendants)

    monkeypatch.setattr(py_trees.behaviour.Behaviour, "iterate", counting)
    tree = PlanTree(_plan(50))
    tree.tick()
    assert walked == []  # BehaviourTree walks the 51 nodes here, every tick
    full = Walk()
    tree.add_visitor(full)
    tree.tick()
    assert walked and full.seen == 51
