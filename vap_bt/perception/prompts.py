"""The paper's prompts and paraphrases, loaded from ``prompts.yaml`` (the one place they live).

Questions are rendered for people and models alike, so object names are spoken: ``coffee_table``
becomes "coffee table". A predicate is *verifiable* when there are paraphrases for it; the others
(``robot_in``, ``in_room``, ``connects``, ...) come from localization and the map, not the camera.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import yaml

from vap_bt.domain.atoms import Atom


@dataclass(frozen=True)
class PromptBook:
    goal_parsing: str
    predicate_query: str
    view_sufficiency: str
    viewpoint_selection: str
    success_vqa: str
    affordance_vqa: str
    paraphrases: dict[str, tuple[str, ...]]
    sources: dict[str, str]  # predicate -> "paper" | "vap_bt"


@lru_cache(maxsize=1)
def book() -> PromptBook:
    raw = yaml.safe_load(resources.files("vap_bt.perception").joinpath("prompts.yaml").read_text())
    para = {k: tuple(v["questions"]) for k, v in raw["paraphrases"].items()}
    return PromptBook(
        goal_parsing=raw["goal_parsing"], predicate_query=raw["predicate_query"],
        view_sufficiency=raw["view_sufficiency"], viewpoint_selection=raw["viewpoint_selection"],
        success_vqa=raw["success_vqa"], affordance_vqa=raw["affordance_vqa"],
        paraphrases=para, sources={k: v["source"] for k, v in raw["paraphrases"].items()},
    )


def spoken(name: str) -> str:
    return name.replace("_", " ")


def verifiable(predicate: str) -> bool:
    return predicate in book().paraphrases


def questions(atom: Atom, n: int = 5) -> list[str]:
    """The first ``n`` paraphrased questions for ``atom`` (paper appendix, N = 5)."""
    names = {k: spoken(a) for k, a in zip(("X", "Y"), atom.args)}
    return [q.format(**names) for q in book().paraphrases[atom.predicate][:n]]


def predicate_query(question: str) -> str:
    return book().predicate_query.format(paraphrased_question=question)


def view_sufficiency(question: str) -> str:
    return book().view_sufficiency.format(predicate_question=question)


def viewpoint_selection(question: str, target: str) -> str:
    return book().viewpoint_selection.format(predicate_question=question, target_object=spoken(target))


def action_phrase(name: str, args: tuple[str, ...]) -> str:
    """``grasp(cup, table, kitchen)`` said as "grasp the cup" for the action-level baselines."""
    return " ".join([name, *(f"the {spoken(a)}" for a in args[:2])])
