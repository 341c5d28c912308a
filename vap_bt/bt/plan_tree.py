"""PlanTree: a compiled plan's behaviour tree, ticked without walking every node after each tick.

py_trees' :class:`~py_trees.trees.BehaviourTree` ticks the root and then walks the *whole* tree,
every tick, to show each node to the visitors that ask for the full tree (``visitor.full``). A
compiled plan has about a dozen nodes per action, so a thousand-step plan (IPC visitall) is a tree
of some twelve thousand, and that walk, tick after tick, took more time than the episode's
planning, perception and acting together (36 s of the first 120 of visitall-sat14's episode,
under a profiler). The executive registers no visitor; when none wants the full tree the walk is
skipped, and otherwise the tree ticks exactly as py_trees' does. The handlers and visitors run in
py_trees' order either way.
"""

from __future__ import annotations

from typing import Callable

import py_trees


class PlanTree(py_trees.trees.BehaviourTree):
    """A BehaviourTree whose tick skips the whole-tree walk when no visitor asks for it."""

    def tick(self, pre_tick_handler: Callable[[py_trees.trees.BehaviourTree], None] | None = None,
             post_tick_handler: Callable[[py_trees.trees.BehaviourTree], None] | None = None) -> None:
        if any(v.full for v in self.visitors):
            super().tick(pre_tick_handler, post_tick_handler)
            return
        for handler in (pre_tick_handler, *self.pre_tick_handlers):
            if handler is not None:
                handler(self)
        for visitor in self.visitors:
            visitor.initialise()
        for node in self.root.tick():
            for visitor in self.visitors:
                node.visit(visitor)
        for visitor in self.visitors:
            visitor.finalise()
        for handler in (*self.post_tick_handlers, post_tick_handler):
            if handler is not None:
                handler(self)
        self.count += 1
