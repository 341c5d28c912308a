"""Reading PDDL files into a :class:`~vap_bt.domain.task.PlanningTask`, with clear errors.

unified-planning does the parsing (after :mod:`vap_bt.domain.dialect` rewrote what Fast
Downward reads and it does not); :mod:`vap_bt.domain.requirements` refuses what vap_bt does not run; this
module translates the problem into :mod:`vap_bt.domain.knowledge`'s form — types,
predicates, action schemas (with :mod:`vap_bt.domain.instances` grounding them through
unified-planning), the initial state and the goal — and turns every parser complaint into one
:class:`~vap_bt.errors.InputError` naming the file and, when the parser knows it, the line.
"""

from __future__ import annotations

import warnings
from pathlib import Path

from vap_bt.domain import dialect, up_engines
from vap_bt.domain.atoms import Literal
from vap_bt.domain.formula import FALSE, TRUE, And
from vap_bt.domain.instances import UPInstances
from vap_bt.domain.knowledge import ActionSchema, DomainKnowledge, EffectTemplate
from vap_bt.domain.requirements import Source, check_costs, check_kind, explain_unreadable
from vap_bt.domain.task import PlanningTask
from vap_bt.errors import InputError


def _reader():
    from unified_planning.io import PDDLReader
    from unified_planning.environment import get_environment  # not .shortcuts: it imports every engine (1 s)

    up_engines.load()  # the environment builds the engine factory: without ConfigSpace's 0.8 s
    env = get_environment()
    env.credits_stream = None  # keep stdout for our own progress and reports
    env.error_used_name = False  # the paper names both an action and a predicate "open"
    warnings.filterwarnings("ignore", message="Name .* already defined", category=UserWarning)
    return PDDLReader()


def _parse_error(path: Path | str, exc: Exception) -> InputError:
    line = getattr(exc, "lineno", None)
    where = f"{path}:{line}" if line else str(path)
    if isinstance(exc, KeyError):  # unified-planning's reader looks a name up that is not declared
        return InputError(where, f"PDDL error: undeclared name {exc.args[0]!r} (a type, predicate or object)")
    msg = getattr(exc, "msg", None) or (str(exc).splitlines() or [type(exc).__name__])[0]
    # one line: unified-planning's message says where on a second line ("Error from line: 30, col 15")
    msg = "; ".join(part.strip() for part in str(msg).splitlines() if part.strip()) or type(exc).__name__
    return InputError(where, f"PDDL error: {msg}")


def load_task(domain_file: str | Path, problem_file: str | Path) -> PlanningTask:
    """Parse a domain and a problem; every failure is an :class:`InputError`."""
    domain_path, problem_path = Path(domain_file), Path(problem_file)
    for p in (domain_path, problem_path):
        if not p.is_file():
            raise InputError(str(p), "no such file")
    return _parse(domain_path, Source.read(problem_path), where=problem_path)


def parse_strings(domain_file: str | Path, problem_text: str, where: str) -> PlanningTask:
    """Parse a domain file with a problem given as text (generated from a task file's scene)."""
    domain_path = Path(domain_file)
    if not domain_path.is_file():
        raise InputError(str(domain_path), "no such file")
    return _parse(domain_path, Source(where, problem_text), where=where)


def _parse(domain_path: Path, problem: Source, where: Path | str) -> PlanningTask:
    """When the domain and the problem do not parse, the domain is parsed alone, so that an error
    in it names the domain file and its line, not the problem (or the task file the problem was
    generated from). Only then: the reader parses the domain first either way, so a domain that
    fails alone fails together with the problem, and parsing it twice cost every command that
    reads PDDL a quarter of its reading (gripper: 0.29 s against 0.22 s)."""
    domain = Source.read(domain_path)
    domain_text = dialect.domain_text(domain)
    reader = _reader()
    try:
        up_problem = reader.parse_problem_string(domain_text, dialect.problem_text(problem.text))
    except Exception as exc:  # the parser raises many kinds; all are bad input here
        try:
            reader.parse_problem_string(domain_text)
        except Exception as domain_exc:
            raise explain_unreadable([domain]) or _parse_error(domain_path, domain_exc) from None
        raise explain_unreadable([problem]) or _parse_error(where, exc) from None
    return from_up(up_problem, source=f"{domain_path} + {where}", where=where,
                   sources=[domain, problem], domain_file=domain_path)


def from_up(problem, source: str, where: Path | str, sources: list[Source] | None = None,
            domain_file: Path | None = None) -> PlanningTask:
    """Translate a unified-planning problem into a :class:`PlanningTask` (refusing what vap_bt
    does not run)."""
    sources = sources or [Source(str(where), "")]
    kind = problem.kind
    check_kind(kind, sources)
    check_costs(problem, sources)
    instances = UPInstances(problem, has_quantifiers=kind.has_existential_conditions()
                            or kind.has_universal_conditions() or kind.has_forall_effects())
    compiled = instances.problem
    parents = {t.name: (t.father.name if t.father is not None else None) for t in problem.user_types}
    predicates = {f.name: tuple(p.type.name if p.type.is_user_type() else "object" for p in f.signature)
                  for f in problem.fluents if f.type.is_bool_type()}
    schemas = {a.name: _schema(a) for a in compiled.actions}
    objects = {o.name: o.type.name for o in problem.all_objects}
    knowledge = DomainKnowledge(name=problem.name, parents=parents, predicates=predicates, schemas=schemas,
                                instances=instances, has_costs=instances.has_costs, domain_file=domain_file)
    init = instances.init  # the compiled problem's initial state is the parsed one's
    goal = _goal(instances, where)
    return PlanningTask(knowledge=knowledge, objects=objects, init=init, goal=goal,
                        name=problem.name, source=source, up_problem=problem)


def _schema(action) -> ActionSchema:
    params = tuple((f"?{p.name}", p.type.name if p.type.is_user_type() else "object") for p in action.parameters)
    effects = tuple(
        EffectTemplate(e.fluent.fluent().name, tuple(_term(a) for a in e.fluent.args), e.value.is_true(),
                       str(e.condition) if e.is_conditional() else "")
        for e in action.effects if e.fluent.type.is_bool_type())
    return ActionSchema(action.name, params, effects)


def _term(node) -> str:
    if node.is_parameter_exp():
        return f"?{node.parameter().name}"
    if node.is_object_exp():
        return node.object().name
    return str(node)


def _goal(instances: UPInstances, where) -> tuple[Literal, ...]:
    try:
        goal = instances.goal()
    except ValueError as exc:
        raise InputError(str(where), f"the goal: {exc}") from None
    if goal == TRUE:
        return ()
    if goal == FALSE:  # ``(or)``, ``(= a b)`` of two objects: said as such, not as a disjunction
        raise InputError(str(where), "the goal can never hold: as written it is false")
    parts = goal.parts if isinstance(goal, And) else (goal,)
    if not all(isinstance(p, Literal) for p in parts):
        raise InputError(str(where), f"the goal {goal} is not a conjunction of literals: disjunctive goals "
                                     "are not supported (the executive checks each goal atom)")
    return tuple(parts)
