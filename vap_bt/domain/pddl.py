"""Reading PDDL files into a :class:`~vap_bt.domain.task.PlanningTask`, with clear errors.

unified-planning does the parsing; this module translates its problem into the flat form of
:mod:`vap_bt.domain.knowledge` and turns every parser complaint into one
:class:`~vap_bt.errors.InputError` naming the file and, when the parser knows it, the line.
"""

from __future__ import annotations

import warnings
from pathlib import Path

from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.knowledge import ActionSchema, DomainKnowledge, LiteralTemplate
from vap_bt.domain.task import PlanningTask
from vap_bt.errors import InputError


def _reader():
    from unified_planning.io import PDDLReader
    from unified_planning.shortcuts import get_environment

    env = get_environment()
    env.credits_stream = None  # keep stdout for our own progress and reports
    env.error_used_name = False  # the paper names both an action and a predicate "open"
    warnings.filterwarnings("ignore", message="Name .* already defined", category=UserWarning)
    return PDDLReader()


def _parse_error(path: Path, exc: Exception) -> InputError:
    line = getattr(exc, "lineno", None)
    where = f"{path}:{line}" if line else str(path)
    msg = getattr(exc, "msg", None) or str(exc).splitlines()[0] if str(exc) else type(exc).__name__
    return InputError(where, f"PDDL error: {msg}")


def load_task(domain_file: str | Path, problem_file: str | Path) -> PlanningTask:
    """Parse a domain and a problem; every failure is an :class:`InputError`."""
    domain_path, problem_path = Path(domain_file), Path(problem_file)
    for p in (domain_path, problem_path):
        if not p.is_file():
            raise InputError(str(p), "no such file")
    reader = _reader()
    try:
        reader.parse_problem(str(domain_path))
    except Exception as exc:  # the parser raises many kinds; all are bad input here
        raise _parse_error(domain_path, exc) from None
    try:
        up_problem = reader.parse_problem(str(domain_path), str(problem_path))
    except Exception as exc:
        raise _parse_error(problem_path, exc) from None
    return from_up(up_problem, source=f"{domain_path} + {problem_path}", where=problem_path)


def parse_strings(domain_file: str | Path, problem_text: str, where: str) -> PlanningTask:
    """Parse a domain file with a problem given as text (generated from a task file's scene)."""
    domain_path = Path(domain_file)
    if not domain_path.is_file():
        raise InputError(str(domain_path), "no such file")
    reader = _reader()
    try:
        up_problem = reader.parse_problem_string(domain_path.read_text(), problem_text)
    except Exception as exc:
        raise _parse_error(Path(where), exc) from None
    return from_up(up_problem, source=f"{domain_path} + {where}", where=where)


def from_up(problem, source: str, where: Path | str) -> PlanningTask:
    """Translate a unified-planning problem (typed STRIPS) into a :class:`PlanningTask`."""
    parents = {t.name: (t.father.name if t.father is not None else None) for t in problem.user_types}
    predicates = {f.name: tuple(p.type.name if p.type.is_user_type() else "object" for p in f.signature)
                  for f in problem.fluents}
    for f in problem.fluents:
        if not f.type.is_bool_type():
            raise InputError(str(where), f"fluent {f.name!r} is not boolean: only STRIPS is supported")
    schemas = {a.name: _schema(a, where) for a in problem.actions}
    objects = {o.name: o.type.name for o in problem.all_objects}
    knowledge = DomainKnowledge(name=problem.name, parents=parents, predicates=predicates, schemas=schemas)
    init = frozenset(_atom(k) for k, v in problem.initial_values.items() if v.is_true())
    goal = tuple(l for g in problem.goals for l in _literals(g, where, "the goal"))
    return PlanningTask(knowledge=knowledge, objects=objects, init=init, goal=goal,
                        name=problem.name, source=source, up_problem=problem)


def _schema(action, where) -> ActionSchema:
    from unified_planning.model import InstantaneousAction

    if not isinstance(action, InstantaneousAction):
        raise InputError(str(where), f"action {action.name!r}: only instantaneous actions are supported")
    params = tuple((f"?{p.name}", p.type.name if p.type.is_user_type() else "object") for p in action.parameters)
    pre: list[LiteralTemplate] = []
    for c in action.preconditions:
        pre.extend(_templates(c, where, f"action {action.name!r}"))
    add, delete = [], []
    for e in action.effects:
        if e.is_conditional() or e.is_forall() or not e.value.is_bool_constant():
            raise InputError(str(where), f"action {action.name!r}: only unconditional STRIPS effects are supported")
        t = _template(e.fluent, where, f"action {action.name!r}")
        (add if e.value.is_true() else delete).append(t)
    return ActionSchema(action.name, params, tuple(pre), tuple(add), tuple(delete))


def _term(node) -> str:
    if node.is_parameter_exp():
        return f"?{node.parameter().name}"
    if node.is_object_exp():
        return node.object().name
    raise ValueError(node)


def _template(node, where, what, positive=True) -> LiteralTemplate:
    if not node.is_fluent_exp():
        raise InputError(str(where), f"{what}: unsupported expression {node}")
    try:
        terms = tuple(_term(a) for a in node.args)
    except ValueError:
        raise InputError(str(where), f"{what}: unsupported argument in {node}") from None
    return LiteralTemplate(node.fluent().name, terms, positive)


def _templates(node, where, what) -> list[LiteralTemplate]:
    if node.is_and():
        return [t for a in node.args for t in _templates(a, where, what)]
    if node.is_not():
        return [_template(node.arg(0), where, what, positive=False)]
    if node.is_bool_constant() and node.is_true():
        return []
    return [_template(node, where, what)]


def _atom(node) -> Atom:
    return Atom(node.fluent().name, tuple(a.object().name for a in node.args))


def _literals(node, where, what) -> list[Literal]:
    return [t.bind({}) for t in _templates(node, where, what)]
