"""Goals in words (paper Alg. 1 line 2, ParseGoal): a VLM turns an instruction into goal atoms.

After its survey (BuildSceneGraph) the executive knows the scene graph's objects; with the
domain's predicates they fill the appendix's goal-parsing prompt (``prompts.yaml``
``goal_parsing``, verbatim)::

    Instruction: put the cup in the cabinet
    Available objects: cabinet, cup, kitchen, table
    Available predicates: on(X,Y), inside(X,Y), holding(X), hand_empty, ...

The model is asked with no image (:meth:`~vap_bt.perception.vlm.TextModel.complete`). Its reply
is read strictly (:func:`read_goal`) and validated (:func:`goal_errors`): every atom must name a
domain predicate with its arity, objects of the graph, and objects of the types the predicate
takes (:meth:`~vap_bt.domain.task.PlanningTask.check_atom`). A reply that fails is asked again
**once**, with the error appended after the appendix text, which itself stays as it is
(:func:`follow_up`)::

    <the goal-parsing prompt, filled in, verbatim>

    Your previous answer was: <the reply>
    It is not a valid goal: <what is wrong>.
    Answer again with the goal only, in the format above, using only the available objects and predicates.

A second failure, or no reply at all (a timeout, an unreachable or overloaded server, an HTTP
error: the backend has already retried what a retry can cure within its deadline, and a re-ask
would only double the wait), is a
:class:`GoalParseError` — bad input, exit code 2, one line. Every prompt, raw reply and error is
kept in :class:`GoalParse` for the report's ``goal_parsing`` section.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Iterable

from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.knowledge import DomainKnowledge
from vap_bt.domain.task import PlanningTask
from vap_bt.errors import InputError
from vap_bt.perception.prompts import book
from vap_bt.perception.vlm import Attempt, Completion, TextModel

#: the answer format the appendix asks for, said back to the model and to the user
FORMAT = "predicate(object1, object2), predicate(object), ..."
_NAME = r"[A-Za-z][\w-]*"
_ATOM = rf"{_NAME}(?:\s*\(\s*(?:[\w-]+(?:\s*,\s*[\w-]+)*)?\s*\))?"
_GOAL = re.compile(rf"{_ATOM}(?:\s*,\s*{_ATOM})*")
_LABEL = re.compile(r"^(?:goal|output)\s*:\s*", re.I)
_FENCE = re.compile(r"^```[\w-]*\s*\n?(.*?)\n?\s*```$", re.S)
_VARIABLES = "XYZ"


class GoalSyntaxError(ValueError):
    """A reply that is not a list of atoms in the appendix's format."""


class GoalParseError(InputError):
    """The VLM gave no usable goal for the instruction, even when asked again (exit code 2)."""

    def __init__(self, where: str, message: str, record: "GoalParse") -> None:
        super().__init__(where, message)
        self.record = record


@dataclass
class GoalParse:
    """Everything goal parsing did, for the report: the inputs, each attempt and the goal."""

    instruction: str
    source: str  # where the words came from: "--goal" or "instruction" (the task file's)
    backend: str
    objects: tuple[str, ...] = ()
    predicates: str = ""
    attempts: list[Attempt] = field(default_factory=list)
    goal: tuple[Literal, ...] | None = None  # None: not (yet) parsed

    @property
    def reasked(self) -> bool:
        """Whether the first reply was not a valid goal and the model was asked again."""
        return len(self.attempts) > 1

    @property
    def error(self) -> str | None:
        """Why there is no goal (the last attempt's error), or None."""
        return None if self.goal is not None or not self.attempts else self.attempts[-1].error

    def to_json(self) -> dict:
        return {"instruction": self.instruction, "source": self.source, "backend": self.backend,
                "objects": list(self.objects), "predicates": self.predicates,
                "goal": None if self.goal is None else [str(l) for l in self.goal],
                "reasked": self.reasked, "error": self.error,
                "attempts": [a.to_json() for a in self.attempts]}


def predicate_list(knowledge: DomainKnowledge) -> str:
    """The domain's predicates in the appendix's notation: ``on(X,Y), holding(X), hand_empty``."""
    return ", ".join(_signature(name, len(sig)) for name, sig in knowledge.predicates.items())


def _signature(name: str, arity: int) -> str:
    if arity == 0:
        return name
    names = _VARIABLES[:arity] if arity <= len(_VARIABLES) else [f"X{i}" for i in range(1, arity + 1)]
    return f"{name}({','.join(names)})"


def goal_prompt(instruction: str, objects: Iterable[str], knowledge: DomainKnowledge) -> str:
    """The appendix's goal-parsing prompt, filled in (object names as the domain spells them)."""
    return book().goal_parsing.format(instruction=instruction, object_list=", ".join(objects),
                                      predicate_list=predicate_list(knowledge))


def follow_up(prompt: str, reply: str, error: str) -> str:
    """The re-ask: the prompt as it was, then the previous reply and what was wrong with it."""
    return (f"{prompt}\n\nYour previous answer was: {reply.strip() or '(nothing)'}\n"
            f"It is not a valid goal: {error.rstrip('.')}.\n"
            "Answer again with the goal only, in the format above, using only the available objects and predicates.")


def read_goal(text: str) -> tuple[Atom, ...]:
    """The atoms of a reply in the appendix's format ``on(cup, table), open(cabinet)``.

    Strict: only unambiguous wrapping is taken off — surrounding whitespace, a Markdown code
    fence or backticks, one leading ``Goal:`` or ``Output:`` label (the prompt's own words), one
    pair of enclosing brackets and a final full stop. What remains must be atoms separated by
    commas, nothing else: prose, negations, "and" or bullet lists are a :class:`GoalSyntaxError`.
    Repeated atoms count once.
    """
    body = text.strip()
    fenced = _FENCE.match(body)
    body = (fenced.group(1) if fenced else body).strip().strip("`").strip()
    body = _LABEL.sub("", body, count=1).strip()
    if body.startswith("[") and body.endswith("]"):
        body = body[1:-1].strip()
    body = body[:-1].rstrip() if body.endswith(".") else body
    if not body:
        raise GoalSyntaxError("the reply holds no goal")
    if not _GOAL.fullmatch(body):
        raise GoalSyntaxError(f"the reply is not a list of predicates in the format {FORMAT}")
    atoms = [Atom.parse(m.group(0)) for m in re.finditer(_ATOM, body)]  # the grammar admits only atoms
    return tuple(dict.fromkeys(atoms))


def goal_errors(atoms: Iterable[Atom], objects: Iterable[str], task: PlanningTask) -> list[str]:
    """Why each atom is not a goal the robot can pursue here (empty: all are)."""
    known = set(objects)
    errors = []
    for atom in atoms:
        sig = task.knowledge.predicates.get(atom.predicate)
        unknown = [a for a in atom.args if a not in known]
        if unknown and sig is not None and len(sig) == len(atom.args):
            errors.append(f"unknown object {unknown[0]!r} in {atom} (not among the available objects)")
        elif why := task.check_atom(atom):
            errors.append(why)
    return errors


class GoalParser:
    """ParseGoal: ask ``model`` for the goal of ``instruction`` over the objects the robot knows.

    ``where`` names the input at fault in the error (``--goal``, or the task file's
    ``instruction`` field). Call it once per episode, after the survey, with the scene graph's
    objects; ``record`` then holds what happened.
    """

    def __init__(self, model: TextModel, task: PlanningTask, instruction: str, where: str,
                 source: str = "--goal") -> None:
        self.model, self.task, self.instruction, self.where, self.source = model, task, instruction, where, source
        self.record: GoalParse | None = None

    def __call__(self, objects: Iterable[str]) -> tuple[Literal, ...]:
        objects = tuple(objects)
        rec = self.record = GoalParse(self.instruction, self.source, self.model.name, objects,
                                      predicate_list(self.task.knowledge))
        prompt = first = goal_prompt(self.instruction, objects, self.task.knowledge)
        for _ in range(2):  # the question, and once more with the error
            reply = self.model.complete(prompt, "goal")
            goal, error = self._judge(reply, objects)
            rec.attempts.append(Attempt(prompt, reply.text, reply.outcome, error, reply.latency_s))
            if error is None:
                rec.goal = goal
                return goal
            if not reply.replied:
                break
            prompt = follow_up(first, reply.text or "", error)
        asked = "asked again" if rec.reasked else "asked once"
        raise GoalParseError(self.where, f"the {self.model.name} VLM gave no usable goal for "
                                         f"{_quoted(self.instruction)} ({asked}): {_one_line(rec.error or '')}", rec)

    def _judge(self, reply: Completion, objects: tuple[str, ...]) -> tuple[tuple[Literal, ...] | None, str | None]:
        """The goal a reply gives and None, or None and why not."""
        if reply.text is None:
            return None, f"{reply.outcome}: {reply.error}"
        try:
            atoms = read_goal(reply.text)
        except GoalSyntaxError as exc:
            return None, str(exc)
        errors = goal_errors(atoms, objects, self.task)
        if errors:
            return None, "; ".join(errors)
        return tuple(Literal(a) for a in atoms), None


def _quoted(text: str, limit: int = 80) -> str:
    text = _one_line(text)
    return repr(text if len(text) <= limit else text[: limit - 1] + "…")


def _one_line(text: str) -> str:
    return " ".join(text.split())
