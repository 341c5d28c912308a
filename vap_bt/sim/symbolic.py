"""The symbolic world: the domain's actions over ground facts, with Table II's situations.

It is the fast world — thousands of episodes a minute — for the executive's logic, fault
campaigns and quick ablations. The truth is a set of atoms. An action whose preconditions hold
in the truth has its effects, unless :class:`~vap_bt.sim.situations.SituationModel` draws a
situation for it; an action whose preconditions do not hold fails (the motion finds nothing to
act on). Any typed STRIPS domain runs; Table II's rows apply to the household's action names.

Its camera has no pixels. An observation says, for each object, which fraction of it the current
view shows: zero for what is neither near where the robot stands nor something it was asked to
look at in its room (other rooms and closed containers are never seen into), otherwise a seeded
draw in [0.3, 1] per view,
redrawn whenever the viewpoint moves. (In a domain without ``robot_in``/``robot_at`` the whole
scene is in view.) Things lying on the floor of the robot's room count as
near (that is where dropped things land, and the camera sweeps the floor). That is what the simulated VLM's accuracy depends on.
"""

from __future__ import annotations

import random

from vap_bt.domain.atoms import Atom
from vap_bt.domain.task import PlanningTask
from vap_bt.scene.graph import LOCATION_PREDICATES
from vap_bt.scene.layout import floor_of
from vap_bt.sim.situations import SituationModel, SituationSpec
from vap_bt.world import (ActionOutcome, GoalContext, InjectedSituation, ObjectInfo, Observation,
                          SceneSnapshot)

#: visibility of an object in view is drawn uniformly from [VISIBILITY_LOW, 1]
VISIBILITY_LOW = 0.3


class SymbolicWorld:
    name = "symbolic"

    def __init__(self, task: PlanningTask, situations: SituationModel | None = None, seed: int = 0) -> None:
        self.task = task
        self._situated = {"robot_in", "robot_at"} <= set(task.knowledge.predicates)
        self.situations = situations or SituationModel(enabled=False)
        self.reset(seed)

    # -- World protocol ---------------------------------------------------------------------

    def reset(self, seed: int) -> None:
        self.seed = seed
        self.state: set[Atom] = set(self.task.init)
        self.situations.reseed(seed)
        self._view_rng = random.Random(seed ^ 0x5EED)
        self._view = 0
        self._visibility: dict[tuple[str, bool], float] = {}
        self._step = 0
        self._injected: list[InjectedSituation] = []

    def survey(self) -> SceneSnapshot:
        objs = [ObjectInfo(name=o, label=t, room=self._room_of(o)) for o, t in sorted(self.task.objects.items())]
        return SceneSnapshot(objects=objs, facts={a for a in self.state if self.holds(a)})

    def perform(self, action: str, args: tuple[str, ...], ctx: GoalContext) -> ActionOutcome:
        try:
            ga = self.task.knowledge.ground(action, tuple(args))
        except (KeyError, ValueError) as exc:
            return ActionOutcome(False, str(exc))
        self._step += 1
        spec = self.situations.draw(action)  # drawn for every action, so the stream stays aligned
        ctx.feedback(0.0, f"{ga} started")
        if ctx.cancelled():
            return ActionOutcome(False, "cancelled")
        truth = {a for a in self.state if self.holds(a)}
        if not ga.applicable(truth):
            self._new_view()
            return ActionOutcome(False, f"{ga}: nothing to act on")
        if spec is not None and self._inject(spec, ga):
            self._injected.append(InjectedSituation(action, tuple(args), spec.kind, self._step))
        else:
            self.state = set(ga.apply(frozenset(self.state)))
        self._new_view()
        ctx.feedback(1.0, f"{ga} done")
        return ActionOutcome(True)

    def observe(self, targets: tuple[str, ...]) -> Observation:
        vis = {o: self._visibility_of(o, o in targets) for o in self.task.objects}
        rel = frozenset(a for a in self.state if a.predicate in LOCATION_PREDICATES
                        and a.args and a.args[0] in targets and vis.get(a.args[0], 0) > 0)
        return Observation(view_index=self._view, targets=tuple(targets), visibility=vis, relations=rel)

    def move_view(self, target: str, direction: str) -> bool:
        self._new_view()
        return True

    def holds(self, atom: Atom) -> bool:
        if atom.predicate == "inview":
            return atom in self.state and not self._enclosed(atom.args[0])
        return atom in self.state

    def injected(self) -> list[InjectedSituation]:
        return list(self._injected)

    def close(self) -> None:
        pass

    # -- situations -----------------------------------------------------------------------

    def _inject(self, spec: SituationSpec, ga) -> bool:
        """Make ``spec`` so; False when it cannot apply here (nothing held to drop)."""
        room = self._robot_room()
        obj = self._held() if spec.drops == "held" else (ga.args[spec.drops] if spec.drops is not None else None)
        if spec.drops is not None and (obj is None or room is None or floor_of(room) not in self.task.objects):
            return False
        if spec.drops is not None:
            self._drop(obj, room)
        if spec.effect:
            self.state = set(ga.apply(frozenset(self.state)))
        return True

    def _drop(self, obj: str, room: str) -> None:
        was_held = Atom("holding", (obj,)) in self.state
        self.state -= {a for a in self.state if a.predicate in LOCATION_PREDICATES and a.args[0] == obj}
        self.state |= {Atom("on", (obj, floor_of(room))), Atom("in_room", (obj, room)), Atom("reachable", (obj,))}
        self.state -= {a for a in self.state if a.predicate == "blocking" and obj in a.args}
        if was_held:
            self.state.add(Atom("hand_empty"))

    # -- views ----------------------------------------------------------------------------

    def _new_view(self) -> None:
        self._view += 1
        self._visibility.clear()

    def _visibility_of(self, obj: str, targeted: bool) -> float:
        key = (obj, targeted)
        if key not in self._visibility:
            seen = self._in_view(obj) or (targeted and self._in_room_with_robot(obj))
            self._visibility[key] = self._view_rng.uniform(VISIBILITY_LOW, 1.0) if seen else 0.0
        return self._visibility[key]

    def _in_room_with_robot(self, obj: str) -> bool:
        # the camera turns toward what it is asked about: anything in the robot's room, not shut away
        return not self._enclosed(obj) and self._robot_room() in self._rooms_of(obj)

    def _in_view(self, obj: str) -> bool:
        if not self._situated:
            return True  # a domain without a robot position (blocksworld): the whole scene is in view
        if self.task.objects.get(obj) == "room":
            return obj == self._robot_room()
        if Atom("holding", (obj,)) in self.state:
            return True
        if self._enclosed(obj) or self._robot_room() not in self._rooms_of(obj):
            return False
        focus = self._focus()
        if focus is None:
            return False
        near = {focus} | self._supports(focus) | self._supported_by(focus)
        for s in self._supports(focus):
            near |= self._supported_by(s)  # things beside the focus on the same furniture
        near |= self._supported_by(floor_of(self._robot_room()))  # things lying about nearby
        return obj in near

    def _focus(self) -> str | None:
        return next((a.args[0] for a in self.state if a.predicate == "robot_at"), None)

    def _supports(self, obj: str) -> set[str]:
        return {a.args[1] for a in self.state if a.predicate in ("on", "inside") and a.args[0] == obj}

    def _supported_by(self, obj: str) -> set[str]:
        return {a.args[0] for a in self.state if a.predicate in ("on", "inside") and a.args[1] == obj
                and not self._enclosed(a.args[0])}

    def _enclosed(self, obj: str) -> bool:
        return any(a.predicate == "inside" and a.args[0] == obj and Atom("closed", (a.args[1],)) in self.state
                   for a in self.state)

    def _robot_room(self) -> str | None:
        return next((a.args[0] for a in self.state if a.predicate == "robot_in"), None)

    def _rooms_of(self, obj: str) -> set[str]:
        return {a.args[1] for a in self.state if a.predicate == "in_room" and a.args[0] == obj}

    def _room_of(self, obj: str) -> str | None:
        rooms = sorted(self._rooms_of(obj))
        return rooms[0] if rooms else None

    def _held(self) -> str | None:
        return next((a.args[0] for a in self.state if a.predicate == "holding"), None)
