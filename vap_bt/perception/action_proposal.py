"""The VLM-planner's question: which action next? (the paper's VLM-planner baseline, Sec. V-B).

The baseline has no PDDL planner: the VLM writes the plan itself, one action at a time, as SayCan
does, given the domain knowledge in the prompt ("we provide domain knowledge in prompts for fair
comparison"). Each step it is shown the current camera frame and asked, in ``prompts.yaml``
``vlm_planner`` (our prompt: the paper quotes none), with

* the instruction and the goal (the task's PDDL goal, or the goal parsed from words),
* every action of the domain with its parameters, preconditions and effects
  (:func:`action_list`, rendered from the task's PDDL through unified-planning), the predicates
  (as goal parsing lists them: :func:`~vap_bt.perception.goal_parsing.predicate_list`) and the
  objects the robot knows (the scene graph's),
* what the robot believes holds now — the scene graph's facts, from its survey and the effects of
  the actions it has done since (it perceives; it is never told),
* the actions done so far, each with what its skill reported.

The reply must be one action in PDDL form, ``(grasp cup coffee_table living_room)``, or ``done``
(:func:`read_action`: strict; only a code fence, backticks, a leading ``Next action:`` and a final
full stop are taken off). The action must be one of the domain's, with its arity, over objects the
robot knows, of the types its parameters take (:func:`action_errors`, grounding through the
domain: :meth:`~vap_bt.domain.knowledge.DomainKnowledge.ground`). A reply that fails is asked
again **once**, the error stated (``vlm_planner_reask``); a second failure, or no reply at all (the
backend has already retried what a retry can cure), ends the episode with that reason. Nothing
here checks whether the action's preconditions hold: the baseline verifies nothing.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Iterable

from vap_bt.domain.atoms import Atom, AtomSyntaxError
from vap_bt.domain.knowledge import GroundAction
from vap_bt.domain.task import PlanningTask
from vap_bt.perception.goal_parsing import predicate_list
from vap_bt.perception.prompts import book
from vap_bt.perception.vlm import Attempt, Completion

#: the reply that says the goal is reached (the episode then claims success)
DONE = "done"
#: the answer format, said back to the model in a re-ask's error
FORMAT = "(action object1 object2 ...)"
_FENCE = re.compile(r"^```[\w-]*\s*\n?(.*?)\n?\s*```$", re.S)
_LABEL = re.compile(r"^(?:next\s+)?action\s*:\s*", re.I)


class ActionSyntaxError(ValueError):
    """A reply that is not one action in PDDL form nor ``done``."""


def action_list(task: PlanningTask) -> str:
    """Each action of the task's domain on its own lines: its typed parameters, its precondition
    and its effects, as unified-planning reads them from the PDDL::

        grasp(?o - item, ?s - surface, ?r - room)
          precondition: inview(o) and hand_empty and reachable(o) and on(o, s) and in_room(o, r)
          effect: holding(o), not hand_empty, not on(o, s), not in_room(o, r)
    """
    if task.up_problem is None:
        raise ValueError("this task was not read from PDDL: no domain to describe")
    return "\n".join(_action_text(a) for a in task.up_problem.actions)


def _action_text(action) -> str:
    params = ", ".join(f"?{p.name} - {p.type.name}" for p in action.parameters)
    pre = " and ".join(_unbracketed(str(c)) for c in action.preconditions) or "none"
    effects = ", ".join(_effect_text(e) for e in action.effects) or "none"
    return f"{action.name}({params})\n  precondition: {pre}\n  effect: {effects}"


def _effect_text(effect) -> str:
    said = str(effect.fluent) if effect.value.is_true() else f"not {effect.fluent}"
    if effect.is_conditional():
        said = f"when {_unbracketed(str(effect.condition))}: {said}"
    if effect.is_forall():
        said = f"for all {', '.join(v.name for v in effect.forall)}: {said}"
    return said


def _unbracketed(text: str) -> str:
    """unified-planning's ``(a and b)`` without its outer brackets (a precondition per line needs none)."""
    return text[1:-1] if text.startswith("(") and text.endswith(")") else text


def next_action_prompt(instruction: str, task: PlanningTask, objects: Iterable[str], facts: Iterable[Atom],
                       history: Iterable[str]) -> str:
    """The ``vlm_planner`` prompt, filled in: the task's words and goal, the domain's actions and
    predicates, the objects the robot knows, what it believes now and what it has done."""
    done = list(history)
    return book().vlm_planner.format(
        instruction=instruction or "(none given: reach the goal)",
        goal=", ".join(map(str, task.goal)), actions=action_list(task),
        predicate_list=predicate_list(task.knowledge), object_list=", ".join(objects),
        facts="\n".join(str(a) for a in sorted(facts)) or "(nothing)",
        history="\n".join(f"{i}. {line}" for i, line in enumerate(done, 1)) or "(none yet)")


def reask(prompt: str, reply: str, error: str) -> str:
    """The one re-ask: the prompt as it was, the previous reply and what was wrong with it."""
    return book().vlm_planner_reask.format(prompt=prompt, reply=reply.strip() or "(nothing)",
                                           error=error.rstrip("."))


def read_action(text: str) -> Atom | None:
    """The action a reply names, as an atom ``grasp(cup, coffee_table, living_room)``, or None for
    ``done``. Strict: only unambiguous wrapping is taken off (surrounding whitespace, a Markdown
    code fence or backticks, one leading ``Next action:`` label, a final full stop); what remains
    must be ``done`` or one action in PDDL form on one line — prose, two actions or the paper's
    ``grasp(cup, ...)`` notation are an :class:`ActionSyntaxError`."""
    body = text.strip()
    fenced = _FENCE.match(body)
    body = _LABEL.sub("", (fenced.group(1) if fenced else body).strip(), count=1).strip()
    body = (body[:-1] if body.endswith(".") else body).strip().strip("`").strip()
    if body.lower() == DONE:
        return None
    if not body:
        raise ActionSyntaxError("the reply holds no action")
    if "\n" in body or not body.startswith("("):
        raise ActionSyntaxError(f"the reply is not one action in the form {FORMAT}, nor {DONE}")
    try:
        return Atom.parse(body)
    except AtomSyntaxError:
        raise ActionSyntaxError(f"the reply is not one action in the form {FORMAT}, nor {DONE}") from None


def action_errors(action: Atom, task: PlanningTask, objects: Iterable[str]) -> str | None:
    """Why ``action`` is not an action the robot can be told to do here (None: it is one): an
    action the domain does not have, a wrong number of objects, an object the robot does not
    know, an object of the wrong type. Whether it can succeed now is not asked."""
    unknown = [a for a in action.args if a not in set(objects)]
    schema = task.knowledge.schemas.get(action.predicate)
    if schema is not None and len(schema.parameters) == len(action.args) and unknown:
        return f"unknown object {unknown[0]!r} in {action.pddl()} (not among the available objects)"
    try:
        task.knowledge.ground(action.predicate, action.args)
    except KeyError as exc:
        return f"{exc.args[0]}"
    except ValueError as exc:
        return str(exc)
    return None


@dataclass
class Proposal:
    """One step of the VLM-planner: its requests and what came of them — an action, ``done``, or
    neither (``error`` says why)."""

    step: int
    attempts: list[Attempt] = field(default_factory=list)
    action: GroundAction | None = None
    done: bool = False
    #: what its skill reported, once the action has been executed ("succeeded", "failed: ...")
    result: str | None = None

    @property
    def settled(self) -> bool:
        """Whether the model named an action or said done."""
        return self.done or self.action is not None

    @property
    def reasked(self) -> bool:
        """Whether the first reply was not usable and the model was asked again."""
        return len(self.attempts) > 1

    @property
    def error(self) -> str | None:
        """Why the step has no action (the last attempt's error), or None."""
        return None if self.settled or not self.attempts else self.attempts[-1].error

    def to_json(self) -> dict:
        return {"step": self.step, "action": None if self.action is None else str(self.action),
                "done": self.done, "result": self.result, "reasked": self.reasked, "error": self.error,
                "attempts": [a.to_json() for a in self.attempts]}


def judge(reply: Completion, task: PlanningTask, objects: Iterable[str]) -> tuple[GroundAction | None, str | None]:
    """What a reply proposes and None (an action, or None for ``done``), or None and why it is not
    usable."""
    if reply.text is None:
        return None, f"{reply.outcome}: {reply.error}"
    try:
        atom = read_action(reply.text)
    except ActionSyntaxError as exc:
        return None, str(exc)
    if atom is None:
        return None, None
    why = action_errors(atom, task, objects)
    if why is not None:
        return None, why
    return task.knowledge.ground(atom.predicate, atom.args), None
