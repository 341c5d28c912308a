"""Outcome: how something asked of a robot, a skill's motion or a world ended.

A driver's trajectory, a skill's own motion, a simulated world's action and a world's answer to
an action hook all end the same way: done, or not and why. One type says it everywhere, so a
reason reads the same from the driver up to the skill's result (``message``), and the wire
carries it as it is. ``completed`` is the doer's own view: a grasp that closed on nothing still
*completed*; that it failed is for perception to find out.

A motion that looked for the thing it was to act on where belief put it, and did not see it
there, says which thing (``missing``): the failure is then news about belief, not about the
motion, and the executive's diagnosis reads it so (:mod:`vap_bt.bt.diagnosis`). One that found a
precondition of its action false where it looked (a fridge it was to take a pie out of, seen shut)
says which (``unmet``), for the same reason.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Outcome:
    """``completed``, or not and why (``message``: ``"blocked: …"``, ``"refused: …"``, ``"cancelled"``)."""

    completed: bool
    message: str = ""
    #: the thing the motion did not see where belief put it (None: the failure was the motion's own)
    missing: str | None = None
    #: the precondition of the action the motion found false where it looked, as an atom's text
    #: (``"open(fridge)"``; None: it found none)
    unmet: str | None = None
