"""Natural execution failures: the robot's own action failing by physics alone, noticed by the world.

Table II's situations are failures the world causes on purpose (:mod:`pb_injection`), and it logs
each one. In a physical world the robot's actions also fail with nothing drawn: a grasp whose
fingers miss, an arm that finds no pose to place from, a held cup that the hand loses while it
takes a microwave's handle. Left out of the world's record, such a failure scored the situation
it raised as a perception error (:mod:`vap_bt.sim.situation_truth`: nothing in the log touched
it), though the world was as the plan had it and the action did not do what it should. The world
reads the physics' truth before and after each action (never the executive's belief, never the
skill's report) and logs, beside Table II's rows (:class:`~vap_bt.world.InjectedSituation`):

* ``held_object_dropped`` — an item the hand held as the action began is no longer held when it
  ends, and the action was not one to let go (its effects delete no atom of the hand's ``held``
  role: a place of a thing the robot took for another lets go of what it holds, and that is no drop);
* ``action_failed`` — every precondition of the action held in the world as it began, and some
  effect of it about the things it acts on does not hold when it ends (the robot's own pose and
  view, the roles ``robot_at``, ``robot_in`` and ``in_view``, are left out: whether the camera has
  a thing in view is the wrist image's pixel count, a measure of the view, not an action's outcome).

The predicates are named by role (:mod:`vap_bt.domain.roles`), the household's by default: the
world speaks the household's predicates, as its truth does (tests/test_roles.py says why a world
is not renamed), and the names are spelled in one place, not here.

Neither is logged when Table II already logged a failure of that action (it explains what went
wrong), and neither when the action began in a world that did not allow it (a precondition false:
belief was wrong, and that is a perception error, as the symbolic world's "nothing to act on").
The log marks only what happened, so a situation about an unchanged thing still scores as a
perception error.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import GroundAction
from vap_bt.domain.roles import HOUSEHOLD
from vap_bt.sim.disturbances import KINDS as _DISTURBANCES
from vap_bt.world import InjectedSituation

#: the log's kinds for a failure nobody drew
DROPPED = "held_object_dropped"
FAILED = "action_failed"
KINDS: tuple[str, ...] = (DROPPED, FAILED)


@dataclass(frozen=True)
class _Begun:
    """An action as the world stood when it began: what it grounds to, whether the world allowed
    it, and the item the hand held."""

    action: GroundAction
    step: int
    feasible: bool
    held: str | None


class NaturalFailures:
    """Watches each action's begin and end (the world's hooks) and logs a failure nobody drew.

    ``holds`` answers an atom from the world's truth, ``held`` names the item in the hand (None:
    none), ``ground`` grounds an action by name and arguments (raising ``KeyError`` or
    ``ValueError`` for one the domain does not have)."""

    def __init__(self, holds: Callable[[Atom], bool], held: Callable[[], str | None],
                 ground: Callable[[str, tuple[str, ...]], GroundAction]) -> None:
        self.holds, self.held, self.ground = holds, held, ground
        self._begun: _Begun | None = None

    def begin(self, action: str, args: tuple[str, ...], step: int) -> None:
        """``action(args)``, the world's ``step``-th, begins now (after what a person does before it)."""
        try:
            ga = self.ground(action, tuple(args))
        except (KeyError, ValueError):
            self._begun = None
            return
        feasible = all(self.holds(a) for a in ga.pre_pos) and not any(self.holds(a) for a in ga.pre_neg)
        self._begun = _Begun(ga, step, feasible, self.held())

    def end(self, log: list[InjectedSituation]) -> None:
        """The action begun last has ended (Table II's pending drop already happened): append to
        ``log`` the failure nobody drew, if there was one."""
        b, self._begun = self._begun, None
        if b is None:
            return
        ga = b.action
        if any(e.step == b.step and e.kind not in _DISTURBANCES for e in log):
            return  # Table II failed this action on purpose: its row says what happened
        if b.held is not None and self.held() != b.held and not self._releases(ga):
            log.append(InjectedSituation(ga.name, ga.args, DROPPED, b.step, (b.held,), "natural"))
            return
        if not b.feasible:
            return
        pose = HOUSEHOLD.robot  # where the robot stands and what its camera shows: no outcome on a thing
        missed = [a for a in ga.add if a.predicate not in pose and not self.holds(a)]
        missed += [a for a in ga.delete if a.predicate not in pose and self.holds(a)]
        if missed:
            log.append(InjectedSituation(ga.name, ga.args, FAILED, b.step, ga.args[:1], "natural"))


    def _releases(self, action: GroundAction) -> bool:
        """Whether ``action`` is meant to let go of what the hand holds (it deletes a ``held`` atom)."""
        return any(HOUSEHOLD.is_held(a) for a in action.may_delete)
