"""Fast Downward's PDDL as unified-planning's reader takes it: rewrites that keep every line.

vap_bt promises to run the PDDL Fast Downward reads, and parses it with unified-planning, whose
reader is stricter in a few places where the IPC domains are not. Each gap is closed here by a
rewrite of the text that means the same to Fast Downward and leaves every construct on its line,
so that an error still names the line of the user's file:

* ``either`` types in predicate declarations (:mod:`vap_bt.domain.either`);
* a predicate declared with one parameter name twice, ``(in ?obj ?obj)`` (IPC 2000 logistics):
  the names of a declaration's parameters mean nothing, unified-planning merges the two and reads
  a one-place predicate; the second becomes ``?obj-2``;
* a variable glued to the word before it, ``(aircraft?a)`` (IPC 2002 zenotravel): Fast
  Downward's tokenizer starts a new token at every ``?``, unified-planning's reads one word;
* a problem that minimizes ``total-cost`` without giving it an initial value (IPC 2018 agricola
  and settlers): Fast Downward starts it at 0, unified-planning then reads the metric as an
  arbitrary final-state expression and the task as numeric planning; ``(= (total-cost) 0)`` is
  added on the ``(:init`` line.
"""

from __future__ import annotations

import re

from vap_bt.domain import either
from vap_bt.domain.requirements import Source

_DECLARATION = re.compile(r"\(\s*[^\s()?;]+((?:\s+[^\s()]+)*)\s*\)")
_GLUED = re.compile(r"(?<=[^\s()?])\?")
_METRIC = re.compile(r"\(\s*:metric\s+minimize\s+\(\s*total-cost\s*\)", re.IGNORECASE)
_TOTAL_COST_SET = re.compile(r"\(\s*=\s*\(\s*total-cost\s*\)", re.IGNORECASE)


def domain_text(src: Source) -> str:
    """The domain's text as unified-planning's reader takes it."""
    return _distinct_parameters(either.rewrite(Source(src.path, _split_variables(src.text))))


def problem_text(text: str) -> str:
    """The problem's text as unified-planning's reader takes it."""
    return total_cost_from_zero(_split_variables(text))


def _split_variables(text: str) -> str:
    """A space before every ``?`` that follows a word, as Fast Downward's tokenizer reads it."""
    return _GLUED.sub(" ?", text)


def total_cost_from_zero(text: str) -> str:
    """``(= (total-cost) 0)`` on the ``(:init`` line of a problem that minimizes total-cost and
    does not set it."""
    plain = either.blank_comments(text)
    if not _METRIC.search(plain) or _TOTAL_COST_SET.search(plain):
        return text
    m = re.search(r"\(\s*:init\b", plain, flags=re.IGNORECASE)
    return text if m is None else text[:m.end()] + " (= (total-cost) 0)" + text[m.end():]


def _distinct_parameters(text: str) -> str:
    """Every predicate declaration with its parameter names made distinct."""
    span = either.block(either.blank_comments(text), ":predicates")
    if span is None:
        return text
    start, end = span  # "(:predicates" itself never matches: a "(" follows its name
    return text[:start] + _DECLARATION.sub(_renamed, text[start:end]) + text[end:]


def _renamed(m: re.Match) -> str:
    seen: dict[str, int] = {}

    def name(v: re.Match) -> str:
        token = v.group(0)
        seen[token.lower()] = seen.get(token.lower(), 0) + 1
        return token if seen[token.lower()] == 1 else f"{token}-{seen[token.lower()]}"

    return re.sub(r"\?[^\s()]+", name, m.group(0))


__all__ = ["domain_text", "problem_text", "total_cost_from_zero"]
