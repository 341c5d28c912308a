"""The whole tree in words: py_trees' own unicode display, with every node's status mark.

The drawing (:mod:`~vap_bt.viz.tree_graph`) folds what is not running; beside it, this text
keeps the full tree — every action, phase, check and decorator, with ``[✓]``, ``[✕]``, ``[*]``
(running) or ``[-]`` (not run) and the feedback message — exactly as
``py_trees.display.unicode_tree(root, show_status=True)`` prints it. py_trees colours the marks
with terminal escape codes when stdout is a terminal; they are removed, as the viewer shows
plain text.
"""

from __future__ import annotations

import re

import py_trees
import rerun as rr

_ESCAPES = re.compile(r"\x1b\[[0-9;]*m")


def tree_text(root: py_trees.behaviour.Behaviour) -> str:
    """The whole tree under ``root`` as py_trees prints it with status marks, without terminal colour
    codes."""
    return _ESCAPES.sub("", py_trees.display.unicode_tree(root, show_status=True))


def tree_document(root: py_trees.behaviour.Behaviour) -> rr.TextDocument:
    """The tree's text as a rerun plain-text document."""
    return rr.TextDocument(tree_text(root), media_type=rr.MediaType.TEXT)
