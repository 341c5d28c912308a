"""Which PDDL vap_bt runs, and one clear error for the rest.

vap_bt runs the classical subset that Fast Downward handles: STRIPS with typing, negative,
disjunctive and quantified (``forall``/``exists``) preconditions, equality, conditional effects
(``when``, ``forall``) and action costs (``:action-costs``: a ``total-cost`` that actions
increase by constants or by static numeric fluents, minimized by the metric). Whatever
unified-planning reads beyond that — durative actions, numeric fluents other than action costs,
object fluents, other metrics, constraints — is refused here with one :class:`InputError` that
names the file, the line where the construct is found, and the PDDL requirement it belongs to.

The check is on what the problem *uses* (unified-planning's problem kind), not on what its
``:requirements`` line declares: many domains declare more than they use. The declared
requirements explain a file unified-planning could not read at all (``:derived-predicates``,
``either`` types).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from vap_bt.errors import InputError, read_text

#: unified-planning problem-kind features vap_bt plans, executes and verifies
SUPPORTED_FEATURES = frozenset({
    "ACTION_BASED", "FLAT_TYPING", "HIERARCHICAL_TYPING",
    "NEGATIVE_CONDITIONS", "DISJUNCTIVE_CONDITIONS", "EQUALITIES", "EXISTENTIAL_CONDITIONS",
    "UNIVERSAL_CONDITIONS", "CONDITIONAL_EFFECTS", "FORALL_EFFECTS",
    "ACTIONS_COST", "PLAN_LENGTH", "STATIC_FLUENTS_IN_ACTIONS_COST", "INT_NUMBERS_IN_ACTIONS_COST",
    # PDDL's ``number`` is read as a real; that the values are integers is checked separately
    "REAL_NUMBERS_IN_ACTIONS_COST",
    # a cost left undefined (IPC elevators defines travel costs only where a lift can travel):
    # PDDL 2.1 makes an action that uses an undefined value inapplicable. Other numeric fluents
    # are refused by their own features, so this one only ever concerns action costs here
    "UNDEFINED_INITIAL_NUMERIC",
})


@dataclass(frozen=True)
class Requirement:
    """A PDDL requirement vap_bt does not support, and where to find its constructs in a file."""

    name: str
    what: str
    pattern: str  # a regular expression for the construct, to name its line


_DURATIVE = Requirement(":durative-actions", "durative actions", r"\(\s*:durative-action")
_NUMERIC = Requirement(":numeric-fluents", "numeric fluents beyond action costs",
                       r"\((?:increase|decrease|assign|scale-up|scale-down)\s|\([<>]=?\s|\(=\s*\(|\(\s*:functions")
_FEATURES: dict[str, Requirement] = {
    **dict.fromkeys(("CONTINUOUS_TIME", "DISCRETE_TIME", "INTERMEDIATE_CONDITIONS_AND_EFFECTS",
                     "EXTERNAL_CONDITIONS_AND_EFFECTS", "DURATION_INEQUALITIES", "SELF_OVERLAPPING",
                     "STATIC_FLUENTS_IN_DURATIONS", "FLUENTS_IN_DURATIONS", "INT_TYPE_DURATIONS",
                     "REAL_TYPE_DURATIONS"), _DURATIVE),
    **dict.fromkeys(("TIMED_EFFECTS", "TIMED_GOALS"),
                    Requirement(":timed-initial-literals", "timed initial literals", r"\(\s*at\s+[\d.]+\s")),
    **dict.fromkeys(("PROCESSES", "EVENTS"), Requirement(":time", "processes and events", r"\(\s*:(?:process|event)")),
    **dict.fromkeys(("SIMPLE_NUMERIC_PLANNING", "GENERAL_NUMERIC_PLANNING", "INT_FLUENTS", "REAL_FLUENTS",
                     "NUMERIC_FLUENTS", "INCREASE_EFFECTS", "DECREASE_EFFECTS", "INCREASE_CONTINUOUS_EFFECTS",
                     "DECREASE_CONTINUOUS_EFFECTS", "NON_LINEAR_CONTINUOUS_EFFECTS",
                     "STATIC_FLUENTS_IN_NUMERIC_ASSIGNMENTS", "FLUENTS_IN_NUMERIC_ASSIGNMENTS", "BOUNDED_TYPES",
                     "FLUENTS_IN_ACTIONS_COST"), _NUMERIC),
    **dict.fromkeys(("OBJECT_FLUENTS", "FLUENTS_IN_OBJECT_ASSIGNMENTS", "STATIC_FLUENTS_IN_OBJECT_ASSIGNMENTS"),
                    Requirement(":object-fluents", "object fluents", r"\(\s*:functions")),
    **dict.fromkeys(("FINAL_VALUE", "MAKESPAN", "OVERSUBSCRIPTION", "TEMPORAL_OVERSUBSCRIPTION"),
                    Requirement(":metric", "a metric other than minimizing total-cost", r"\(\s*:metric")),
    **dict.fromkeys(("TRAJECTORY_CONSTRAINTS", "STATE_INVARIANTS"),
                    Requirement(":constraints", "constraints", r"\(\s*:constraints")),
}

#: requirements that make unified-planning's reader fail outright, named when it does
_UNREADABLE = {
    ":derived-predicates": Requirement(":derived-predicates", "derived predicates (axioms)", r"\(\s*:derived"),
    ":durative-actions": _DURATIVE,
    ":timed-initial-literals": _FEATURES["TIMED_EFFECTS"],
    ":preferences": Requirement(":preferences", "preferences", r"\(\s*preference\s"),
    ":constraints": _FEATURES["TRAJECTORY_CONSTRAINTS"],
    ":object-fluents": _FEATURES["OBJECT_FLUENTS"],
}
_EITHER = Requirement("`either` types", "unified-planning's PDDL reader does not read them here",
                      r"\(\s*either\s")


@dataclass(frozen=True)
class Source:
    """A PDDL file's path and text, to find the line of a construct."""

    path: str
    text: str

    @classmethod
    def read(cls, path: Path | str) -> "Source":
        """The PDDL file at ``path`` (not UTF-8: an :class:`InputError`)."""
        return cls(str(path), read_text(path))

    def line_of(self, pattern: str) -> int | None:
        """The 1-based line of the first match of regex ``pattern`` outside comments (case-insensitive),
        or None."""
        m = re.search(pattern, _without_comments(self.text), flags=re.IGNORECASE)
        return self.text.count("\n", 0, m.start()) + 1 if m else None

    def declares(self, requirement: str) -> int | None:
        """The line of ``requirement`` in this file's ``:requirements``, if declared."""
        return self.line_of(r"\(\s*:requirements[^)]*?" + re.escape(requirement) + r"(?![\w-])")


def _without_comments(text: str) -> str:
    # blank out ; comments but keep every character's offset, so line numbers stay right
    return re.sub(r";[^\n]*", lambda m: " " * len(m.group(0)), text)


def _refuse(req: Requirement, sources: list[Source], found_by: str = "") -> InputError:
    for src in sources:
        line = src.line_of(req.pattern) or src.declares(req.name)
        if line is not None:
            where = f"{src.path}:{line}"
            break
    else:
        where = sources[0].path
    kind = "requirement " if req.name.startswith(":") else ""
    extra = f"; {found_by}" if found_by else ""
    return InputError(where, f"unsupported PDDL {kind}{req.name} ({req.what}{extra}). vap_bt runs classical "
                             "PDDL as Fast Downward does: typing, negative, disjunctive and quantified "
                             "preconditions, equality, conditional effects, action costs")


def check_kind(kind, sources: list[Source]) -> None:
    """Refuse a parsed problem that uses more than vap_bt supports."""
    extra = sorted(set(kind.features) - SUPPORTED_FEATURES)
    if not extra:
        return
    req = _FEATURES.get(extra[0])
    if req is None:
        req = Requirement(extra[0].lower().replace("_", "-"), "a feature beyond classical planning", r"$^")
    raise _refuse(req, sources, found_by="unified-planning reports " + ", ".join(extra))


def check_costs(problem, sources: list[Source]) -> None:
    """Fast Downward's action costs are non-negative integers."""
    for fluent_exp, value in problem.explicit_initial_values.items():
        if value.is_constant() and not value.type.is_bool_type():
            v = value.constant_value()
            if v < 0 or int(v) != v:
                pattern = r"\(\s*=\s*\(\s*" + re.escape(fluent_exp.fluent().name) + r"[\s)]"
                src = next((s for s in reversed(sources) if s.line_of(pattern)), sources[-1])
                line = src.line_of(pattern)
                raise InputError(f"{src.path}:{line}" if line else src.path,
                                 f"action cost {fluent_exp} = {v}: costs must be non-negative integers "
                                 "(Fast Downward's action costs)")


def explain_unreadable(sources: list[Source]) -> InputError | None:
    """When unified-planning cannot read a file: a construct it does not read, if one is used."""
    for src in sources:
        if src.line_of(_EITHER.pattern) is not None:
            return _refuse(_EITHER, [src])
    for src in sources:
        for name, req in _UNREADABLE.items():
            if src.declares(name) is not None or src.line_of(req.pattern) is not None:
                return _refuse(req, [src], found_by="unified-planning cannot read it")
    return None


__all__ = ["SUPPORTED_FEATURES", "Source", "check_costs", "check_kind", "explain_unreadable"]
