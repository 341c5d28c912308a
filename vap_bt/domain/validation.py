"""Plans checked by unified-planning's ``PlanValidator``, independently of our own semantics.

The planner finds plans two ways — Fast Downward, and the in-process search over our grounding —
and the executive reasons about them with :meth:`~vap_bt.domain.knowledge.GroundAction.diff`. A
plan checked only by that same code would only check itself, so every plan a planner produces is
also handed to unified-planning's sequential plan validator on the problem rebuilt for the state
it starts from (:meth:`~vap_bt.domain.task.PlanningTask.to_up`). The validator also evaluates the
action-cost metric, which gives an independent plan cost.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

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


def validate(task: PlanningTask, actions: list[GroundAction]) -> Verdict:
    """Check ``actions`` from ``task.init`` to ``task.goal`` with unified-planning's validator."""
    up_engines.load()
    from unified_planning.engines import ValidationResultStatus
    from unified_planning.environment import get_environment  # not .shortcuts, which imports all of UP

    problem = task.to_up()
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


__all__ = ["Verdict", "up_plan", "validate"]
