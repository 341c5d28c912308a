"""Plans checked by unified-planning's ``PlanValidator``, independently of our own semantics.

The planner finds plans two ways — Fast Downward, and the in-process search over our grounding —
and the executive reasons about them with :meth:`~vap_bt.domain.knowledge.GroundAction.diff`. A
plan checked only by that same code would only check itself, so every plan a planner produces is
also handed to unified-planning's sequential plan validator on the problem rebuilt for the state
it starts from (:meth:`~vap_bt.domain.task.PlanningTask.to_up`). The validator also evaluates the
action-cost metric, which gives an independent plan cost.

unified-planning recomputes a problem's *kind* (the features an engine must support) on every
read of ``Problem.kind`` — a walk over every action and the goal — and one validation reads it
three times (the validator's checks, its simulator's, its own); at a replan's validation that was
a fifth of a symbolic episode. :func:`with_known_kind` computes it once per task problem and goal
instead (see there why that is the same kind).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import Any

from vap_bt.domain import up_engines
from vap_bt.domain.knowledge import GroundAction
from vap_bt.domain.task import PlanningTask


@dataclass(frozen=True)
class Verdict:
    """unified-planning's judgement of a plan."""

    valid: bool
    reason: str = ""
    cost: float | None = None  # the action-cost metric's value, when the task has one


def up_plan(problem, actions: list[GroundAction]):
    """``actions`` as a unified-planning ``SequentialPlan`` over ``problem``'s actions and objects."""
    from unified_planning.plans import ActionInstance, SequentialPlan

    acts = {a.name: a for a in problem.actions}
    objs = {o.name: o for o in problem.all_objects}
    return SequentialPlan([ActionInstance(acts[a.name], [objs[x] for x in a.args]) for a in actions])


#: the kind of each task problem by (the unified-planning problem it was read from, its goal), with
#: that problem held so that its id is not reused while the entry lives
_KINDS: dict[tuple[int, tuple], tuple[Any, Any]] = {}
#: entries kept at most (one per task and goal: a campaign has nine; tests read hundreds of problems)
_KINDS_MAX = 64
#: the classes :func:`with_known_kind` swaps a problem's class for, by the class it had
_KNOWN_KIND: dict[type, type] = {}


def with_known_kind(task: PlanningTask, problem):
    """``problem`` (``task.to_up()``, not to be changed afterwards) made to answer ``kind`` from a
    cache instead of computing it anew at every read.

    The kind of a problem rebuilt by :meth:`~PlanningTask.to_up` is the kind of the problem for
    the same read problem and goal in any other state: ``to_up`` changes only the truth of
    Boolean initial values, every one of which has a value (a parsed problem's default is false),
    and unified-planning's kind reads the initial state only for values left undefined, and
    Boolean static fluents only through effect values simplified with them — constants in PDDL,
    whose effects assign true or false (tests/test_planner.py checks the cached kind against a
    fresh one over the states of episodes). Each read returns a copy: the validator changes the
    kind it is given."""
    key = (id(task.up_problem), task.goal)
    hit = _KINDS.get(key)
    if hit is None or hit[0] is not task.up_problem:
        if len(_KINDS) >= _KINDS_MAX:
            _KINDS.clear()
        hit = _KINDS[key] = (task.up_problem, problem.kind)
    cls = type(problem)
    if cls not in _KNOWN_KIND:
        # a subclass with no fields of its own, as instances.explicit_initial_state makes
        _KNOWN_KIND[cls] = type(f"KnownKind{cls.__name__}", (cls,),
                                {"__slots__": (), "kind": property(lambda p: p._vap_bt_kind.clone())})
    problem._vap_bt_kind = hit[1]
    problem.__class__ = _KNOWN_KIND[cls]
    return problem


def validate(task: PlanningTask, actions: list[GroundAction]) -> Verdict:
    """Check ``actions`` from ``task.init`` to ``task.goal`` with unified-planning's validator."""
    up_engines.load()
    from unified_planning.engines import ValidationResultStatus
    from unified_planning.environment import get_environment  # not .shortcuts, which imports all of UP

    problem = with_known_kind(task, task.to_up())
    with warnings.catch_warnings():
        # unified-planning cannot tell whether integral ``number`` costs (reals) suit its validator
        warnings.simplefilter("ignore")
        with get_environment().factory.PlanValidator(name="sequential_plan_validator") as v:
            result = v.validate(problem, up_plan(problem, actions))
    if result.status != ValidationResultStatus.VALID:
        return Verdict(False, "; ".join(m.message for m in result.log_messages) or result.status.name)
    costs = list((result.metric_evaluations or {}).values())
    cost = costs[0].constant_value() if costs and hasattr(costs[0], "constant_value") else (costs or [None])[0]
    return Verdict(True, cost=None if cost is None else float(cost))


__all__ = ["Verdict", "up_plan", "validate", "with_known_kind"]
