"""The paper's prompt templates, loaded from ``prompts.yaml`` (the one place they live).

Questions are rendered for people and models alike, so object names are spoken: ``coffee_table``
becomes "coffee table". The paraphrased questions per predicate belong to a domain and live in its
perception profile (:mod:`vap_bt.perception.profile`), which also says which predicates are asked
of the camera at all.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import yaml

from vap_bt.perception.paraphrase import listing


@dataclass(frozen=True)
class PromptBook:
    """The appendix's prompt templates (and the baselines' two questions), as ``str.format`` text;
    beside them the VLM-planner baseline's two prompts, which are ours (the paper quotes none)."""

    goal_parsing: str
    predicate_query: str
    view_sufficiency: str
    viewpoint_selection: str
    success_vqa: str
    affordance_vqa: str
    vlm_planner: str
    vlm_planner_reask: str


@lru_cache(maxsize=1)
def book() -> PromptBook:
    """The templates of ``prompts.yaml``, read once."""
    raw = yaml.safe_load(resources.files("vap_bt.perception").joinpath("prompts.yaml").read_text())
    return PromptBook(**{name: raw[name] for name in PromptBook.__dataclass_fields__})


def spoken(name: str) -> str:
    """An object's name as said in a question: ``coffee_table`` -> "coffee table"."""
    return name.replace("_", " ")


def predicate_query(question: str) -> str:
    """The predicate-query prompt around one paraphrased question."""
    return book().predicate_query.format(paraphrased_question=question)


def view_sufficiency(question: str) -> str:
    """The view-sufficiency prompt: does the picture show enough to answer ``question``?"""
    return book().view_sufficiency.format(predicate_question=question)


def viewpoint_selection(question: str, target: str) -> str:
    """The viewpoint-selection prompt: which way to move to answer ``question`` about ``target`` (spoken)."""
    return book().viewpoint_selection.format(predicate_question=question, target_object=spoken(target))


def action_phrase(name: str, args: tuple[str, ...]) -> str:
    """An action said plainly when its domain's perception profile has no phrase for it:
    ``drive_truck(t1, c1, c2)`` -> "drive truck the t1, the c1 and the c2" (every argument named:
    a question that leaves one out may be about another action)."""
    named = listing([f"the {spoken(a)}" for a in args]) if args else ""
    return " ".join(filter(None, [spoken(name), named]))
