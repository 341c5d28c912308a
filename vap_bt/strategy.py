"""Verification strategies: which checks a compiled plan's tree makes, and how it asks them.

The paper's predicate-based checks (``both``, and the ablations ``pre`` and ``eff``) ask the VLM
about the atoms an action needs and makes, each with N paraphrases, a vote, the view-sufficiency
question and viewpoint moves within the budget K (:mod:`vap_bt.bt.active_perception`). The
baselines it is compared with (paper, "Comparing verification strategies", and the OK-Robot
baseline of the real-world experiments) ask otherwise, over the same executive loop:

* ``none`` — nothing is asked: the closed world (the paper's Classical-planner / Closed World);
* ``success_vqa`` — after each action one action-level question, "Did the robot successfully
  <action>?" (SuccessVQA); no precondition is checked;
* ``affordance_vqa`` — before each action one, "Is it possible to <action>?" (AffordanceVQA); no
  effect is checked;
* ``suc_aff`` — both of those (Suc.Aff.-QA);
* ``ok_robot`` — the predicate checks of ``both`` made the OK-Robot way: one view, one question
  per atom (the first paraphrase), its answer believed; no vote, no view-sufficiency question, no
  viewpoint move, no second look;
* ``vlm_planner`` — no PDDL planner and no checks: a real VLM names each next action from the
  domain knowledge, the belief and the frame (SayCan-style, :mod:`vap_bt.bt.vlm_planner`); the
  simulated VLM cannot plan, so offline it is refused, never faked.

What the executive does with an action-level "no" is in :mod:`vap_bt.bt.action_check`. This
table is the one place the names are declared: the ``--verify`` setting's choices
(:mod:`vap_bt.settings`) and everything the compiler and the executive do per strategy derive from
it; a new strategy is one more entry. Standard library only: ``vap-bt --help`` reads it.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Strategy:
    """Which checks a compiled tree makes (see the module docstring)."""

    name: str
    #: the precondition atoms the camera judges, before each action
    pre: bool = False
    #: the effect atoms the camera judges, after each action, and the goal's before success is claimed
    eff: bool = False
    #: "Is it possible to <action>?" before each action (AffordanceVQA)
    affordance: bool = False
    #: "Did the robot successfully <action>?" after each action (SuccessVQA)
    success: bool = False
    #: a predicate check is one question about one view, believed as answered (OK-Robot)
    single: bool = False
    #: no planner: the VLM names each next action, and nothing is checked (the VLM-planner)
    vlm_plans: bool = False

    @property
    def asks(self) -> bool:
        """Whether the strategy asks the VLM anything during the plan (it then needs one)."""
        return self.pre or self.eff or self.affordance or self.success

    @classmethod
    def parse(cls, name: str) -> "Strategy":
        """The strategy named ``name`` (:data:`STRATEGIES`); a KeyError for any other name."""
        return STRATEGIES[name]


#: every strategy, by name, in the order ``--help`` lists them
STRATEGIES: dict[str, Strategy] = {s.name: s for s in (
    Strategy("both", pre=True, eff=True),
    Strategy("pre", pre=True),
    Strategy("eff", eff=True),
    Strategy("none"),
    Strategy("success_vqa", success=True),
    Strategy("affordance_vqa", affordance=True),
    Strategy("suc_aff", affordance=True, success=True),
    Strategy("ok_robot", pre=True, eff=True, single=True),
    Strategy("vlm_planner", vlm_plans=True),
)}
#: the strategies' names (the ``--verify`` setting's choices)
NAMES = tuple(STRATEGIES)
