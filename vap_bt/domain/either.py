"""PDDL ``either`` types in predicate declarations, rewritten for unified-planning's reader.

IPC domains such as storage declare predicates over a union of types, ``(in ?x - (either
storearea crate) ?p - place)``. unified-planning 1.3 does not read ``either`` at all. In a
predicate's declaration the union can be widened to the types' nearest common ancestor without
changing what the domain means: a predicate only ever holds of the atoms the initial state and the
actions' (typed) effects give it. So before parsing, each ``(either t1 t2 …)`` inside
``(:predicates …)`` is replaced by that ancestor (``object`` if nothing nearer), on the same line.

Elsewhere — action parameters, quantified variables, objects or constants of several types — the
union does restrict what an action may be applied to, and widening it would change the domain:
that stays an error, naming the line.
"""

from __future__ import annotations

import re

from vap_bt.domain.requirements import Source
from vap_bt.errors import InputError

_EITHER = re.compile(r"\(\s*either\s+([^()]*)\)", re.IGNORECASE)


def rewrite(src: Source) -> str:
    """``src``'s text with every predicate-declaration ``either`` widened to a common ancestor."""
    text = blank_comments(src.text)
    if not _EITHER.search(text):
        return src.text
    parents = _type_parents(text)
    predicates = block(text, ":predicates")
    out, last = [], 0
    for m in _EITHER.finditer(text):
        if predicates is None or not predicates[0] <= m.start() < predicates[1]:
            line = text.count("\n", 0, m.start()) + 1
            raise InputError(f"{src.path}:{line}", "`either` types are supported in predicate declarations only "
                                                   "(unified-planning does not read them; here they would widen what "
                                                   "an action or object may be)")
        names = [t.lower() for t in m.group(1).split()]
        widened = _common_ancestor(names, parents)
        out += [src.text[last:m.start()], widened.ljust(m.end() - m.start() - m.group(0).count("\n"))
                + "\n" * m.group(0).count("\n")]
        last = m.end()
    out.append(src.text[last:])
    return "".join(out)


def blank_comments(text: str) -> str:
    """``text`` with every ``;`` comment replaced by spaces of the same length, so that offsets and line
    numbers still match the file."""
    return re.sub(r";[^\n]*", lambda m: " " * len(m.group(0)), text)


def block(text: str, keyword: str) -> tuple[int, int] | None:
    """The span of the ``(keyword …)`` section, by matching parentheses."""
    m = re.search(r"\(\s*" + re.escape(keyword) + r"\b", text, re.IGNORECASE)
    if not m:
        return None
    depth = 0
    for i in range(m.start(), len(text)):
        depth += {"(": 1, ")": -1}.get(text[i], 0)
        if depth == 0:
            return m.start(), i + 1
    return m.start(), len(text)


def _type_parents(text: str) -> dict[str, str]:
    """``(:types a b - p c)`` as {a: p, b: p, c: object}."""
    span = block(text, ":types")
    if span is None:
        return {}
    body = text[span[0]:span[1]].strip()[1:-1]
    tokens = body.split()[1:]  # drop ":types"
    parents: dict[str, str] = {}
    pending: list[str] = []
    i = 0
    while i < len(tokens):
        if tokens[i] == "-" and i + 1 < len(tokens):
            parents.update({t.lower(): tokens[i + 1].lower() for t in pending})
            pending, i = [], i + 2
        else:
            pending.append(tokens[i])
            i += 1
    parents.update({t.lower(): "object" for t in pending})
    return parents


def _common_ancestor(types: list[str], parents: dict[str, str]) -> str:
    def chain(t: str) -> list[str]:
        out = [t]
        while out[-1] in parents and parents[out[-1]] not in out:
            out.append(parents[out[-1]])
        return out + ["object"]

    others = [set(chain(t)) for t in types[1:]]
    return next(t for t in chain(types[0]) if all(t in o for o in others))


__all__ = ["rewrite"]
