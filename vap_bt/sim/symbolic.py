"""The symbolic world: the domain's actions over ground facts, with Table II's situations.

It is the fast world — thousands of episodes a minute — for the executive's logic, fault
campaigns and quick ablations. The truth is a set of atoms, readable only through its
:class:`~vap_bt.sim.oracle.Oracle`. An action whose preconditions hold in the truth has its
effects, unless :class:`~vap_bt.sim.situations.SituationModel` draws a situation for it; an action
whose preconditions do not hold fails (the motion finds nothing to act on). Any typed STRIPS
domain runs; Table II's rows apply to the household's action names.

Its robot interfaces are the same as a pixel world's, without the pixels:

* **camera** — which objects a view shows: what is near where the robot stands (the thing it is
  at, what is on or in it, what shares its support, what lies on the floor of its room), and the
  same near the *place* the camera is turned to, if that is in the robot's room. The camera turns
  to the place an :class:`~vap_bt.robot.camera.Aim` names — where the executive's belief puts
  what it wants to see (the support or container it believes a thing on or in; a piece of
  furniture, door or floor is its own place) — never to where the thing truly is: a thing that
  is not where belief puts it is not in the picture, unless it happens to be near the robot.
  Other rooms and closed containers are never seen into. (In a domain without
  ``robot_in``/``robot_at`` the whole scene is in view.) Each object in view gets a visible
  fraction, and what its relations need (:class:`~vap_bt.sim.captures.ObjectView`: contact,
  inside, leaf, top; the fingers) a share, drawn in [0.3, 1] per view — a view is a pose and a
  place looked at, and moving either makes a new one; that is what the simulated VLM's accuracy
  depends on. A frame's detections come from the :class:`~vap_bt.sim.detector.DetectorModel`:
  objects in view, each missed at its miss rate (one draw per object and view), each with its
  class label and no name, with the relations (:mod:`vap_bt.sim.relation_reports`) where it rests,
  what blocks it and whether it can be reached, each wrong by model vlm-2's rule over how this
  view shows it, the same for the same view — naming the detected thing ``""``, the frame's other
  detections ``"#k"`` and the map's things by name (:mod:`vap_bt.robot.frame`); which object each
  detection is stays in the capture record. The world's actions take names, and a name means the
  object of that name;
* **viewpoints** — going to a viewpoint stands the robot at its aim's place (it stands at it and
  sees it; the pybullet camera drives to the view's base pose), in any room the open doors lead
  to; a view whose aim belief places nowhere cannot be reached (a frame has no pixels, unless
  ``frame_cards`` is set: then each carries a tiny picture of its own id,
  :func:`~vap_bt.sim.captures.frame_card`, so that a model served over HTTP, which is shown only
  images, can tell the frames apart);
* **actions** — ``find`` goes where the goal's hints (the executive's belief, as the pybullet
  ``find`` skill is given them) put its target: a thing believed on or in a place that it is not
  on or in leaves the robot standing at that place, not at the thing (and a thing believed on or
  in nothing, at the floor of its room); other actions, and ``find`` without hints, act on the
  world as it is: an executed action is the world acting, not the camera;
* **body** — the room the robot is in and whether the gripper holds something;
* **site map** — rooms, floors, doors, furniture and the rigid facts of the task.
"""

from __future__ import annotations

import random

from vap_bt.domain.atoms import Atom
from vap_bt.domain.roles import HOUSEHOLD
from vap_bt.domain.task import PlanningTask
from vap_bt.robot.camera import Aim, Viewpoint
from vap_bt.robot.frame import SELF, Detection, Frame, reference
from vap_bt.robot.labels import class_of, label_of
from vap_bt.robot.site_map import DoorInfo, FurnitureInfo, RoomInfo, SiteMap
from vap_bt.robot.state import RobotState
from vap_bt.scene.layout import floor_of
from vap_bt.perception.backends.image import rgb_sha1
from vap_bt.sim.captures import CaptureLog, CaptureRecord, ObjectView, frame_card
from vap_bt.sim.detector import DetectorModel
from vap_bt.sim.disturbances import MOVED, SHUT, Disturbance, DisturbanceModel
from vap_bt.sim.oracle import FunctionOracle
from vap_bt.sim.relation_reports import RelationDetector
from vap_bt.sim.situations import SituationModel, SituationSpec
from vap_bt.outcome import Outcome
from vap_bt.world import GoalContext, InjectedSituation

#: visibility of an object in view is drawn uniformly from [VISIBILITY_LOW, 1]
VISIBILITY_LOW = 0.3
#: where objects are (what a drop takes away)
LOCATIONS = frozenset({"on", "inside", "in_room", "holding"})
FURNITURE_TYPES = ("surface", "container", "sink")


class SymbolicWorld:
    """The world over ground facts described in the module docstring."""

    name = "symbolic"

    def __init__(self, task: PlanningTask, situations: SituationModel | None = None, seed: int = 0,
                 detector: DetectorModel | None = None, disturbances: DisturbanceModel | None = None) -> None:
        self.task = task
        self.knowledge = task.knowledge
        self._situated = {"robot_in", "robot_at"} <= set(task.knowledge.predicates)
        self.situations = situations or SituationModel(enabled=False)
        self.detector = detector or DetectorModel()
        self.relation_detector = RelationDetector(self.detector, task.knowledge, task.objects, seed)
        self.captures = CaptureLog()
        self.frame_cards = False  # frames carry a picture of their id (for the sim VLM served over HTTP)
        self.oracle = FunctionOracle(self._holds, self.injected)
        self._map = _site_map(task)
        #: draws each episode's disturbances on reset; without one, :attr:`disturbances` is a script
        #: that stays across resets (as the pybullet world's)
        self.disturbance_model = disturbances
        self.disturbances: list[Disturbance] = []
        self.reset(seed)

    # -- life cycle ------------------------------------------------------------------------

    def reset(self, seed: int) -> None:
        self.seed = seed
        self.relation_detector.seed = seed
        self.atoms: set[Atom] = set(self.task.init)
        self.situations.reseed(seed)
        self._view_rng = random.Random(seed ^ 0x5EED)
        self._view = 0
        self._tick = 0  # bumps on every change of the world or the viewpoint
        self._frames = 0
        self._aim: tuple[str, ...] = ()
        self._look: str | None = None  # the place the camera is turned to (None: what the robot stands at)
        self._record: CaptureRecord | None = None  # the frame being taken
        self._visibility: dict[tuple, float] = {}
        self._step = 0
        self._injected: list[InjectedSituation] = []
        if self.disturbance_model is not None:
            self.disturbances = self.disturbance_model.draw(self.task, seed)
        self.captures.clear()

    def close(self) -> None:
        pass

    # -- actions ---------------------------------------------------------------------------

    def perform(self, action: str, args: tuple[str, ...], ctx: GoalContext) -> Outcome:
        step = self._step
        outcome = self._act(action, args, ctx)
        if self._step > step:  # an action ran (or failed): what a person does after it happens now
            self._disturb(action, tuple(args))
        return outcome

    def _act(self, action: str, args: tuple[str, ...], ctx: GoalContext) -> Outcome:
        try:
            ga = self.knowledge.ground(action, tuple(args))
        except (KeyError, ValueError) as exc:
            return Outcome(False, str(exc))
        self._step += 1
        spec = self.situations.draw(action)  # drawn for every action, so the stream stays aligned
        ctx.feedback(0.0, f"{ga} started")
        if ctx.cancelled():
            return Outcome(False, "cancelled")
        truth = {a for a in self.atoms if self._holds(a)}
        starts = self._starts_from(ga)
        if starts:  # a base drives from wherever it stands: the motion starts where the action says,
            # and goes where belief (the goal's hints) puts its target, whatever room that truly is
            truth = (truth - {a for a in truth if a.predicate == "robot_at"}) | starts
            truth |= {l.atom for l in ga.preconditions if l.positive and l.atom.predicate == "in_room"}
        if not ga.applicable(truth):
            self._new_view()
            return Outcome(False, f"{ga}: nothing to act on", missing=_missing(ga, truth))
        if starts:
            self.atoms = (self.atoms - {a for a in self.atoms if a.predicate == "robot_at"}) | starts
        intended = self._effects(ga, self.atoms, ctx)
        affected = self._affected(spec, ga) if spec is not None else ()  # before anything falls
        if spec is not None and self._inject(spec, ga, ctx):
            # a failure that leaves the world as success would (an open door "fails to open") is
            # no situation: there is nothing to detect, so the oracle does not count it
            if self.atoms != intended:
                self._injected.append(InjectedSituation(action, tuple(args), spec.kind, self._step, affected))
        else:
            self.atoms = intended
        self._look = None  # the skill moved the arm: the camera looks at what the robot stands at
        self._new_view()
        ctx.feedback(1.0, f"{ga} done")
        return Outcome(True)

    def injected(self) -> list[InjectedSituation]:
        """The situations the world caused this episode (Table II or a disturbance script), in order."""
        return list(self._injected)

    def _starts_from(self, ga) -> set[Atom]:
        """The ``robot_at`` an action that moves the base (it deletes where the robot stands)
        starts from: a real base drives from wherever it is, so where belief thought the robot
        stood does not make the motion fail, nor does a target that is truly in another room than
        belief says (the robot drives to the believed place, and perception finds the thing
        missing); the world's own position is what changes. Empty for every other action (a grasp
        needs the robot truly at the thing)."""
        pre = {l.atom for l in ga.preconditions if l.positive and l.atom.predicate == "robot_at"}
        moves = any(a.predicate == "robot_at" for a in ga.diff(frozenset(self.atoms | pre)).deleted)
        floors = self._map.floors()  # a floor is in its room, though no in_room says so
        rooms = {r for a in pre for r in (*self._rooms_of(a.args[0]), floors.get(a.args[0])) if r is not None}
        return pre if moves and (not rooms or self._robot_room() in rooms) else set()

    def _effects(self, ga, atoms: set[Atom], ctx: GoalContext) -> set[Atom]:
        """The world after ``ga`` from ``atoms``: its effects, except that a move to stand at a thing
        goes where the goal's hints believe it (see the module docstring)."""
        after = set(ga.apply(frozenset(atoms)))
        hints = getattr(ctx, "hints", None) or {}
        if not self._situated:
            return after
        for a in sorted(after - atoms):
            thing = a.args[0] if a.predicate == "robot_at" else None
            if thing is None or thing not in hints or thing in self._map.static_names() \
                    or Atom("holding", (thing,)) in after:
                continue  # the map's things do not move, and what the hand holds goes with the robot
            place = self._believed_place(hints[thing], after)
            rests = {b.args[1] for b in after if b.predicate in ("on", "inside") and b.args[0] == thing}
            if place is not None and place not in rests:
                after -= {a, Atom("inview", (thing,))}
                after |= {Atom("robot_at", (place,)), Atom("inview", (place,))}
        return after

    def _believed_place(self, hint, after: set[Atom]) -> str | None:
        """Where a hint puts its thing: what it is believed in or on, else the floor of the room the
        robot stands in (where a look round begins)."""
        place = hint.inside or hint.on
        if place in self.task.objects:
            return place
        room = next((a.args[0] for a in after if a.predicate == "robot_in"), None)
        return floor_of(room) if room is not None and floor_of(room) in self.task.objects else None

    # -- the truth (through self.oracle only) ------------------------------------------------

    def _holds(self, atom: Atom) -> bool:
        if atom.predicate == "inview":
            return atom in self.atoms and not self._enclosed(atom.args[0])
        return atom in self.atoms

    # -- robot interfaces: camera ------------------------------------------------------------

    def capture(self, aim: Aim | None = None) -> Frame:
        if aim is not None:
            self._turn_to(aim)
        vis = {o: v for o in self.task.objects if (v := self._visibility_of(o)) > 0.0}
        self._frames += 1
        frame_id = f"sym-{self.seed}-{self._frames}"
        card = frame_card(frame_id) if self.frame_cards else None
        # a miss is drawn once per object and view: the same view gives the same detections
        shown = [o for o in sorted(vis) if self._detectable(o) and not self.detector.missed(self._key(o))]
        self._record = CaptureRecord(frame_id, self._tick, vis, self.oracle, lambda: self._tick,
                                     image_sha1=rgb_sha1(card) if card is not None else None,
                                     instances=tuple(shown), views={o: self._object_view(o) for o in vis},
                                     fingers=self._fingers(), picture=f"sym-view-{self._view}",
                                     labels={o: class_of(o) for o in vis})
        self.captures.add(self._record)
        # how a detection names the others (the frame's "#k", the map's things by name), and the
        # truth its relations are read from: both built once per frame, not once per detection
        refs = {o: reference(k) for k, o in enumerate(shown)} | {o: o for o in self._map.static_names()}
        truth = frozenset(self.atoms)
        return Frame(frame_id, float(self._tick), tuple(self._detect(o, refs, truth) for o in shown), rgb=card, aim=self._aim,
                     stand=f"view-{self._view}")

    def goto_view(self, view: Viewpoint) -> bool:
        """Stand at the view's place — what its aim names, where belief puts it — if the open doors
        lead to its room; never at a thing's true place (see the module docstring)."""
        place = self._place(view.aim)
        if not self._situated:
            self._new_view()
            return bool(view.aim.names)
        room = self._robot_room()
        if place is None or view.room not in self._rooms_of(place) \
                or view.room != room and view.room not in self._reachable_rooms(room):
            return False
        self.atoms -= {a for a in self.atoms if a.predicate in ("robot_at", "inview", "robot_in")}
        self.atoms |= {Atom("robot_in", (view.room,)), Atom("robot_at", (place,)), Atom("inview", (place,))}
        self._aim, self._look = tuple(view.aim.names), place
        self._new_view()
        return True

    def move_view(self, aim: Aim, direction: str) -> bool:
        self._aim, self._look = tuple(aim.names), self._place(aim) or self._look
        self._new_view()
        return True

    def _turn_to(self, aim: Aim) -> None:
        """Turn the camera to ``aim``'s place (a new view when that is another place); an aim
        belief places nowhere leaves the camera as it is."""
        self._aim = tuple(aim.names)
        place = self._place(aim)
        if place is not None and place != self._look:
            self._look = place
            self._new_view()

    def _place(self, aim: Aim) -> str | None:
        """The place ``aim`` turns the camera to: the believed place it carries, else the first
        thing it names that the map fixes (furniture, a door, a floor); a room is its floor."""
        static = self._map.static_names()
        place = aim.place if aim.place in self.task.objects else next((n for n in aim.names if n in static), None)
        if place is not None and self.task.objects.get(place) == "room":
            floor = floor_of(place)
            return floor if floor in self.task.objects else None
        return place

    def _detectable(self, obj: str) -> bool:
        # rooms and floors are the map's, not detections
        return self.task.objects.get(obj) != "room" and obj not in self._map.floors()

    def _key(self, obj: str) -> str:
        """Seeds a detector draw about ``obj`` in the current view."""
        return f"{self.seed}|{self._view}|{obj}"

    def _detect(self, obj: str, refs: dict[str, str], truth: frozenset[Atom]) -> Detection:
        """``obj`` as a robot's detector reports it: its class (:mod:`vap_bt.robot.labels`) and
        where it is — naming itself ``""``, the frame's other detections ``"#k"``, and the map's
        things (rooms, floors, furniture, doors) by name; what it could name in no such way, it
        does not report. Furniture and doors report the rooms the map has them in."""
        piece, door = self._map.piece(obj), self._map.door(obj)
        if piece is not None or door is not None:
            rel = tuple(Atom("in_room", (obj, r)) for r in ((piece.room,) if piece else door.rooms))
        else:
            rel = self._report(obj, truth)

        def ref(x: str) -> str | None:
            return SELF if x == obj else refs.get(x)

        return Detection(label_of(obj, self._map),
                         relations=tuple(Atom(a.predicate, tuple(ref(x) for x in a.args)) for a in rel
                                         if all(ref(x) is not None for x in a.args)))

    def _report(self, obj: str, truth: frozenset[Atom]) -> tuple[Atom, ...]:
        """What the relation detector says of an item in the frame being taken (its errors:
        :mod:`vap_bt.sim.relation_reports`)."""
        return self.relation_detector.report(self._record, obj, truth, self._robot_room())

    # -- robot interfaces: body and map ----------------------------------------------------------

    def state(self) -> RobotState:
        return RobotState(float(self._tick), self._robot_room(), gripper_holding=self._held() is not None)

    def site_map(self) -> SiteMap:
        return self._map

    # -- situations -------------------------------------------------------------------------

    def _inject(self, spec: SituationSpec, ga, ctx: GoalContext) -> bool:
        """Make ``spec`` so; False when it cannot apply here (nothing held to drop)."""
        room = self._robot_room()
        obj = self._held() if spec.drops == "held" else (ga.args[spec.drops] if spec.drops is not None else None)
        if spec.drops is not None and (obj is None or room is None or floor_of(room) not in self.task.objects):
            return False
        if spec.drops is not None:
            self._drop(obj, room)
        if spec.effect:
            self.atoms = self._effects(ga, self.atoms, ctx)
        return True

    def _affected(self, spec: SituationSpec, ga) -> tuple[str, ...]:
        """What ``spec`` will change, for the report: what falls (what is held, or the argument it
        names), else the thing the action is about (its first argument)."""
        held = self._held()
        if spec.drops == "held" and held is not None:
            return (held,)
        return (ga.args[spec.drops],) if isinstance(spec.drops, int) else ga.args[:1]

    def _drop(self, obj: str, room: str) -> None:
        self._set_down(obj, floor_of(room), room)

    def _set_down(self, obj: str, place: str, room: str) -> None:
        was_held = Atom("holding", (obj,)) in self.atoms
        self.atoms -= {a for a in self.atoms if a.predicate in LOCATIONS and a.args[0] == obj}
        self.atoms |= {Atom("on", (obj, place)), Atom("in_room", (obj, room)), Atom("reachable", (obj,))}
        self.atoms -= {a for a in self.atoms if a.predicate == "blocking" and obj in a.args}
        if was_held:
            self.atoms.add(Atom("hand_empty"))

    # -- disturbances (vap_bt.sim.disturbances) ---------------------------------------------

    def _disturb(self, action: str, args: tuple[str, ...]) -> None:
        """What a person does after the action just run (index ``self._step - 1``), recorded with
        Table II's situations when it changed the world."""
        for d in self.disturbances:
            if d.after == self._step - 1 and self._apply(d):
                self._injected.append(InjectedSituation(action, args, d.kind, self._step, (d.target,), "disturbance"))
                self._new_view()

    def _apply(self, d: Disturbance) -> bool:
        """Make ``d`` so; whether the world changed."""
        before = set(self.atoms)
        if d.kind == MOVED:
            self._moved_by_person(d.target, d.to)
        else:  # a leaf pushed shut, or half shut: ajar, neither open nor closed (the domain's note)
            self.atoms -= {Atom("open", (d.target,)), Atom("closed", (d.target,))}
            if d.kind == SHUT:
                self.atoms.add(Atom("closed", (d.target,)))
        return self.atoms != before

    def _moved_by_person(self, obj: str, place: str | None) -> None:
        """``obj`` put down on ``place`` — unless the robot holds it. A robot standing at it is
        left standing where it was (its support), without it in view."""
        room = self._map.floors().get(place) or next(iter(sorted(self._rooms_of(place or ""))), None)
        if room is None or obj == self._held():
            return
        was = sorted(self._supports(obj))
        if Atom("robot_at", (obj,)) in self.atoms and was:
            self.atoms -= {Atom("robot_at", (obj,))}
            self.atoms |= {Atom("robot_at", (was[0],)), Atom("inview", (was[0],))}
        self.atoms.discard(Atom("inview", (obj,)))
        self._set_down(obj, place, room)

    # -- views ------------------------------------------------------------------------------

    def _new_view(self) -> None:
        self._view += 1
        self._tick += 1
        self._visibility.clear()

    def _visibility_of(self, obj: str) -> float:
        key = (obj,)
        if key not in self._visibility:
            self._visibility[key] = self._view_rng.uniform(VISIBILITY_LOW, 1.0) if self._in_view(obj) else 0.0
        return self._visibility[key]

    def _object_view(self, obj: str) -> ObjectView:
        """What the relations about ``obj`` need from this view, drawn like its visibility (once per
        view): an item's contact with its support, a container's inside (nothing of it through a
        shut door), a leaf, a surface's top."""
        t = self.task.objects.get(obj, "")
        k = self.knowledge
        kind = lambda *types: any(k.is_subtype(t, x) for x in types if x in k.parents)  # noqa: E731
        draw = lambda what: self._draw((obj, what))  # noqa: E731
        closed = Atom("closed", (obj,)) in self.atoms
        return ObjectView(contact=draw("contact") if kind("item") else None,
                          interior=(0.0 if closed else draw("interior")) if kind("container", "sink") else None,
                          leaf=draw("leaf") if Atom("openable", (obj,)) in self.atoms or kind("door") else None,
                          top=draw("top") if kind("surface", "room") else None)

    def _fingers(self) -> float:
        return self._draw(("fingers",), low=0.6)

    def _draw(self, key: tuple, low: float = VISIBILITY_LOW) -> float:
        """A share drawn uniformly in [low, 1] once per view (as :meth:`_visibility_of`)."""
        if key not in self._visibility:
            self._visibility[key] = self._view_rng.uniform(low, 1.0)
        return self._visibility[key]

    def _in_view(self, obj: str) -> bool:
        if not self._situated:
            return True  # a domain without a robot position (blocksworld): the whole scene is in view
        if self.task.objects.get(obj) == "room":
            return obj == self._robot_room()
        if Atom("holding", (obj,)) in self.atoms:
            return True
        room = self._robot_room()
        if self._enclosed(obj) or room not in self._rooms_of(obj):
            return False
        focus = self._focus()
        if focus is None:
            return False
        looked_at = [focus, *([self._look] if self._look is not None and room in self._rooms_of(self._look) else [])]
        near = self._supported_by(floor_of(room))  # things lying about nearby
        for thing in looked_at:
            near |= {thing} | self._supports(thing) | self._supported_by(thing)
            for s in self._supports(thing):
                near |= self._supported_by(s)  # things beside it on the same furniture
        return obj in near

    def _focus(self) -> str | None:
        return next((a.args[0] for a in self.atoms if a.predicate == "robot_at"), None)

    def _supports(self, obj: str) -> set[str]:
        return {a.args[1] for a in self.atoms if a.predicate in ("on", "inside") and a.args[0] == obj}

    def _supported_by(self, obj: str) -> set[str]:
        return {a.args[0] for a in self.atoms if a.predicate in ("on", "inside") and a.args[1] == obj
                and not self._enclosed(a.args[0])}

    def _enclosed(self, obj: str) -> bool:
        return any(a.predicate == "inside" and a.args[0] == obj and Atom("closed", (a.args[1],)) in self.atoms
                   for a in self.atoms)

    def _robot_room(self) -> str | None:
        return next((a.args[0] for a in self.atoms if a.predicate == "robot_in"), None)

    def _reachable_rooms(self, start: str | None) -> set[str]:
        """Rooms the robot can drive to through open doors."""
        seen, todo = set(), [start]
        while todo:
            r = todo.pop()
            for a in self.atoms:
                if a.predicate == "connects" and a.args[1] == r and Atom("open", (a.args[0],)) in self.atoms \
                        and a.args[2] not in seen:
                    seen.add(a.args[2])
                    todo.append(a.args[2])
        return seen

    def _rooms_of(self, obj: str) -> set[str]:
        return {a.args[1] for a in self.atoms if a.predicate == "in_room" and a.args[0] == obj}

    def _held(self) -> str | None:
        return next((a.args[0] for a in self.atoms if a.predicate == "holding"), None)


def _site_map(task: PlanningTask) -> SiteMap:
    """The map of a symbolic task: names and rigid facts, no geometry."""
    k, objs = task.knowledge, task.objects
    rooms = sorted(o for o, t in objs.items() if t == "room")
    room_of = {a.args[0]: a.args[1] for a in sorted(task.init) if a.predicate == "in_room"}
    doors = []
    for d in sorted(o for o, t in objs.items() if t == "door"):
        joined = sorted({a.args[1] for a in task.init if a.predicate == "connects" and a.args[0] == d})
        if len(joined) == 2:
            doors.append(DoorInfo(d, (joined[0], joined[1])))
    floors = {floor_of(r) for r in rooms}
    furniture = tuple(FurnitureInfo(o, class_of(o), t, room_of[o]) for o, t in sorted(objs.items())
                      if o not in floors and o in room_of and any(k.is_subtype(t, f) for f in FURNITURE_TYPES)
                      and "furniture" in k.parents)
    return SiteMap(rooms=tuple(RoomInfo(r, floor_of(r)) for r in rooms), doors=tuple(doors), furniture=furniture,
                   facts=frozenset(a for a in task.init if k.is_rigid(a.predicate)))


def _missing(ga, truth: set[Atom]) -> str | None:
    """The thing a motion would not find where the action has it: the first whose place, a
    precondition on or in something, is not so in ``truth`` (None: another precondition failed,
    and the motion found its thing). The household's support predicates, as the world speaks them."""
    for lit in ga.preconditions:
        if lit.positive and lit.atom.predicate in HOUSEHOLD.support and lit.atom not in truth:
            return lit.atom.args[0]
    return None
