"""Verification protocols: the paper's, and a lean one that asks less for the same answers.

``paper`` is Alg. 2 as written: the N paraphrases asked one after the other, every one of them,
then the view-sufficiency question, for every check. ``lean`` changes only how much is asked:

* **early stop** — stop asking a round once no remaining answer could change its vote or its
  consistency (4 of 5 agreeing: the fifth cannot undo it);
* **concurrent** — a round's questions are in flight at once (they are about one frame);
* **reuse** — an atom verified earlier is not asked again while no executed action could have
  changed it (none named one of its objects or could add or delete its predicate; the hand's
  atoms are re-asked after every action, as the hand can lose things on any move);
* **logprobs** — where the backend reports token probabilities, one question stands for the N
  votes when its answer is confident (the probability it states for its answer at least
  ``confident``: 0.95, as strong a statement as a unanimous vote and above what the simulated model
  states for a guess, 0.87 on average); otherwise the remaining paraphrases are asked and voted
  as usual;
* **detector** — the view-sufficiency question is not asked when the frame's detector already
  answers it: every object the atom names (rooms and floors aside) is found whole — its mask
  clear of the image's edges — and not tiny (at least ``whole_share`` of the image). Where the
  detector cannot tell (an object cut by the edge, small, or a frame without masks) the model is
  asked as in the paper; where it finds an object missing, the view is insufficient in every
  protocol, and lean asks nothing about it (answers about a view that does not show the thing
  vote nothing in the verdict).
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
    detector: bool = False
    whole_share: float = 0.005

    @classmethod
    def parse(cls, name: str) -> "Protocol":
        try:
            return PROTOCOLS[name]
        except KeyError:
            raise ValueError(f"unknown verification protocol {name!r} ({', '.join(PROTOCOLS)})") from None

    def describe(self) -> dict:
        return asdict(self)


PROTOCOLS = {"paper": Protocol("paper"), "lean": Protocol("lean", early_stop=True, concurrent=True, reuse=True,
                                                               logprobs=True, detector=True)}
