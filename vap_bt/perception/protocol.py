"""Verification protocols: the paper's, and a lean one that asks less for the same answers.

``paper`` is Alg. 2 as written: the N paraphrases asked one after the other, every one of them,
then the view-sufficiency question, for every check. ``lean`` changes only how much is asked:

* **early stop** — stop asking a round once no remaining answer could change its vote or its
  consistency (4 of 5 agreeing: the fifth cannot undo it);
* **concurrent** — a round's questions are in flight at once (they are about one frame);
* **reuse** — an atom verified earlier is not asked again while no executed action could have
  changed it (none named one of its objects or could add or delete its predicate; the hand's
  atoms are re-asked after every action, as the hand can lose things on any move) — before an
  action only: the goal's check, on which success is claimed, always looks. A reused value is
  reported as such (outcome and basis ``reused``) and never counted as verified;
* **logprobs** — where the backend reports token probabilities, one question stands for the N
  votes when its answer is confident (the probability it states for its answer at least
  ``confident``: 0.95, as strong a statement as a unanimous vote and above what the simulated model
  states for a guess, 0.87 on average) and confirms what the plan expects; otherwise more
  paraphrases are asked and voted as usual;
* **unanimous** — a round settles once ``unanimous`` (3) paraphrases all agree on what the plan
  expects, without asking the other two. Paraphrases about one picture are not independent (a
  real model's errors belong to the picture: docs/perception.md), so three agreeing answers are
  less evidence than three independent ones; what this costs in accuracy is measured
  (tools/bench/perception.py), not assumed. A surprise — a value against the plan, which would correct
  belief and make the robot replan — is always put to the paper's full vote (4 of 5 agreeing),
  with or without logprobs, so that asking less never buys a wrong correction;
* **detector** — the view-sufficiency question is not asked when the frame's detector already
  answers it: every object the atom names (rooms and floors aside) is found plainly in view —
  whole (its mask clear of the image's edges) and not tiny (at least ``whole_share`` of the
  image), or large (at least ``large_share`` of the image, a table top or a floor filling the
  view however much of it the edges cut off). Where the detector cannot tell (an object cut by
  the edge and not large, small, or a frame without masks) the model is asked as in the paper;
  where it finds an object missing, the view is insufficient in every protocol, and lean asks
  nothing about it (answers about a view that does not show the thing vote nothing in the
  verdict);
* **no sufficiency question** (``sufficiency`` False: no named protocol; the OK-Robot baseline's
  checks, :mod:`vap_bt.strategy`) — every view the detector does not find wanting is taken as
  sufficient without asking: a round's answers alone settle it;
* **sufficiency in the first wave** — where the detector cannot answer it, the view-sufficiency
  question goes out with the round's first questions instead of after their answers (it is
  about the same frame): one round trip of waiting, not two, at the cost of a question wasted on
  a round whose answers then disagree.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass


@dataclass(frozen=True)
class Protocol:
    """How a check asks its questions (see the module docstring)."""

    name: str
    early_stop: bool = False
    concurrent: bool = False
    reuse: bool = False
    logprobs: bool = False
    confident: float = 0.95
    unanimous: int = 0  # 0: a round needs the paper's agreement share of all N answers
    detector: bool = False
    whole_share: float = 0.005
    large_share: float = 1.0  # 1.0: no object is large enough to count without being whole
    sufficiency: bool = True  # False: the view-sufficiency question is never asked (taken as yes)

    @classmethod
    def parse(cls, name: str) -> "Protocol":
        """The protocol named ``name`` (:data:`PROTOCOLS`); a ValueError that lists the known ones for any
        other."""
        try:
            return PROTOCOLS[name]
        except KeyError:
            raise ValueError(f"unknown verification protocol {name!r} ({', '.join(PROTOCOLS)})") from None

    def describe(self) -> dict:
        """Every setting of the protocol, for the report."""
        return asdict(self)


PROTOCOLS = {"paper": Protocol("paper"), "lean": Protocol("lean", early_stop=True, concurrent=True, reuse=True,
                                                               logprobs=True, detector=True, large_share=0.1,
                                                               unanimous=3)}
