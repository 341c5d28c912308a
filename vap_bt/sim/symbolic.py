"""The symbolic world: the domain's actions over ground facts, with Table II's situations.

It is the fast world — thousands of episodes a minute — for the executive's logic, fault
campaigns and quick ablations. The truth is a set of atoms, readable only through its
:class:`~vap_bt.sim.oracle.Oracle`. An action whose preconditions hold in the truth has its
effects, unless :class:`~vap_bt.sim.situations.SituationModel` draws a situation for it; an action
whose preconditions do not hold fails (the motion finds nothing to act on). Any typed STRIPS
domain runs; Table II's rows apply to the household's action names.

Its robot interfaces are the same as a pixel world's, without the pixels:

* **camera** — which objects a view shows: what is near where the robot stands (the thing it is
  at, what is on or in it, what shares its support, what lies on the floor of its room), plus
  what it was aimed at in its room; other rooms and closed containers are never seen into. (In a
  domain without ``robot_in``/``robot_at`` the whole scene is in view.) Each object in view gets
  a visible fraction drawn in [0.3, 1] per view, redrawn whenever the viewpoint moves — that is
  what the simulated VLM's accuracy depends on. A frame's detections come from the
  :class:`~vap_bt.sim.detector.DetectorModel`: objects in view, each missed at its miss rate (one
  draw per object and view), each with its class label and no name, with the location relations
  its relation detector reports (wrong support at its error rate), naming the detected thing
  ``""``, the frame's other detections ``"#k"`` and the map's things by name
  (:mod:`vap_bt.robot.frame`); which object each detection is stays in the capture record. The
  world's actions take names, and a name means the object of that name;
* **viewpoints** — going to look at a thing moves the robot there (it stands at it and sees it),
  in any room the open doors lead to (a frame has no pixels, unless ``frame_cards`` is set: then
  each carries a tiny picture of its own id, :func:`~vap_bt.sim.captures.frame_card`, so that a
  model served over HTTP, which is shown only images, can tell the frames apart);
* **body** — the room the robot is in and whether the gripper holds something;
* **site map** — rooms, floors, doors, furniture and the rigid facts of the task.
"""

from __future__ import annotations

import random

from vap_bt.domain.atoms import Atom
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
from vap_bt.sim.oracle import FunctionOracle
from vap_bt.sim.situations import SituationModel, SituationSpec
from vap_bt.world import ActionOutcome, GoalContext, InjectedSituation

#: visibility of an object in view is drawn uniformly from [VISIBILITY_LOW, 1]
VISIBILITY_LOW = 0.3
#: where objects are: the relations the symbolic relation detector reports about an item in view
LOCATIONS = frozenset({"on", "inside", "in_room", "holding"})
REPORTED = LOCATIONS | {"blocking", "reachable"}
FURNITURE_TYPES = ("surface", "container", "sink")


class SymbolicWorld:
    """The world over ground facts described in the module docstring."""

    name = "symbolic"

    def __init__(self, task: PlanningTask, situations: SituationModel | None = None, seed: int = 0,
                 detector: DetectorModel | None = None) -> None:
        self.task = task
        self.knowledge = task.knowledge
        self._situated = {"robot_in", "robot_at"} <= set(task.knowledge.predicates)
        self.situations = situations or SituationModel(enabled=False)
        self.detector = detector or DetectorModel()
        self.captures = CaptureLog()
        self.frame_cards = False  # frames carry a picture of their id (for the sim VLM served over HTTP)
        self.oracle = FunctionOracle(self._holds, self.injected)
        self._map = _site_map(task)
        self.reset(seed)

    # -- life cycle ------------------------------------------------------------------------

    def reset(self, seed: int) -> None:
        self.seed = seed
        self.atoms: set[Atom] = set(self.task.init)
        self.situations.reseed(seed)
        self._view_rng = random.Random(seed ^ 0x5EED)
        self._view = 0
        self._tick = 0  # bumps on every change of the world or the viewpoint
        self._frames = 0
        self._aim: tuple[str, ...] = ()
        self._visibility: dict[tuple, float] = {}
        self._step = 0
        self._injected: list[InjectedSituation] = []
        self.captures.clear()

    def close(self) -> None:
        pass

    # -- actions ---------------------------------------------------------------------------

    def perform(self, action: str, args: tuple[str, ...], ctx: GoalContext) -> ActionOutcome:
        try:
            ga = self.knowledge.ground(action, tuple(args))
        except (KeyError, ValueError) as exc:
            return ActionOutcome(False, str(exc))
        self._step += 1
        spec = self.situations.draw(action)  # drawn for every action, so the stream stays aligned
        ctx.feedback(0.0, f"{ga} started")
        if ctx.cancelled():
            return ActionOutcome(False, "cancelled")
        truth = {a for a in self.atoms if self._holds(a)}
        if not ga.applicable(truth):
            self._new_view()
            return ActionOutcome(False, f"{ga}: nothing to act on")
        intended = set(ga.apply(frozenset(self.atoms)))
        if spec is not None and self._inject(spec, ga):
            # a failure that leaves the world as success would (an open door "fails to open") is
            # no situation: there is nothing to detect, so the oracle does not count it
            if self.atoms != intended:
                self._injected.append(InjectedSituation(action, tuple(args), spec.kind, self._step))
        else:
            self.atoms = intended
        self._new_view()
        ctx.feedback(1.0, f"{ga} done")
        return ActionOutcome(True)

    def injected(self) -> list[InjectedSituation]:
        return list(self._injected)

    # -- the truth (through self.oracle only) ------------------------------------------------

    def _holds(self, atom: Atom) -> bool:
        if atom.predicate == "inview":
            return atom in self.atoms and not self._enclosed(atom.args[0])
        return atom in self.atoms

    # -- robot interfaces: camera ------------------------------------------------------------

    def capture(self, aim: Aim | None = None) -> Frame:
        if aim is not None and aim.names != self._aim:
            self._aim = tuple(aim.names)
        targets = set(self._aim)
        vis = {o: v for o in self.task.objects if (v := self._visibility_of(o, o in targets)) > 0.0}
        self._frames += 1
        frame_id = f"sym-{self.seed}-{self._frames}"
        card = frame_card(frame_id) if self.frame_cards else None
        # a miss is drawn once per object and view: the same view gives the same detections
        shown = [o for o in sorted(vis) if self._detectable(o) and not self.detector.missed(self._key(o))]
        self.captures.add(CaptureRecord(frame_id, self._tick, vis, self.oracle, lambda: self._tick,
                                        image_sha1=rgb_sha1(card) if card is not None else None,
                                        instances=tuple(shown), views={o: self._object_view(o) for o in vis},
                                        fingers=self._fingers(), picture=f"sym-view-{self._view}",
                                        labels={o: class_of(o) for o in vis}))
        return Frame(frame_id, float(self._tick), tuple(self._detect(o, shown) for o in shown), rgb=card, aim=self._aim)

    def goto_view(self, view: Viewpoint) -> bool:
        """Stand at the viewed thing (as ``find`` does), if the open doors lead to its room."""
        target = view.aim.names[0] if view.aim.names else None
        if not self._situated or target is None or target not in self.task.objects:
            self._new_view()
            return target is not None
        room = self._robot_room()
        if view.room != room and view.room not in self._reachable_rooms(room):
            return False
        self.atoms -= {a for a in self.atoms if a.predicate in ("robot_at", "inview", "robot_in")}
        self.atoms |= {Atom("robot_in", (view.room,)), Atom("robot_at", (target,)), Atom("inview", (target,))}
        self._aim = (target,)
        self._new_view()
        return True

    def move_view(self, aim: Aim, direction: str) -> bool:
        self._aim = tuple(aim.names)
        self._new_view()
        return True

    def _detectable(self, obj: str) -> bool:
        # rooms and floors are the map's, not detections
        return self.task.objects.get(obj) != "room" and obj not in self._map.floors()

    def _key(self, obj: str) -> str:
        """Seeds a detector draw about ``obj`` in the current view."""
        return f"{self.seed}|{self._view}|{obj}"

    def _detect(self, obj: str, shown: list[str]) -> Detection:
        """``obj`` as a robot's detector reports it: its class (:mod:`vap_bt.robot.labels`) and
        where it is — naming itself ``""``, the frame's other detections ``"#k"``, and the map's
        things (rooms, floors, furniture, doors) by name; what it could name in no such way, it
        does not report. Furniture and doors report the rooms the map has them in."""
        piece, door = self._map.piece(obj), self._map.door(obj)
        if piece is not None or door is not None:
            rel = tuple(Atom("in_room", (obj, r)) for r in ((piece.room,) if piece else door.rooms))
        else:
            rel = self._report(obj)
        mapped = self._map.static_names()
        refs = {o: reference(k) for k, o in enumerate(shown)}
        refs.update({o: o for o in mapped})
        refs[obj] = SELF
        return Detection(label_of(obj, self._map),
                         relations=tuple(Atom(a.predicate, tuple(refs[x] for x in a.args)) for a in rel
                                         if all(x in refs for x in a.args)))

    def _report(self, obj: str) -> tuple[Atom, ...]:
        """What the relation detector says of an item: its location, its support sometimes wrong."""
        out = []
        for a in sorted(self.atoms):
            if a.predicate not in REPORTED or obj not in a.args or not self._holds(a):
                continue
            if a.predicate in ("on", "inside") and len(a.args) == 2 and a.args[0] == obj \
                    and (rng := self.detector.misreports(f"{self._key(obj)}|{a}")) is not None:
                a = Atom(a.predicate, (obj, self._wrong_support(a, rng)))
            out.append(a)
        return tuple(out)

    def _wrong_support(self, a: Atom, rng: random.Random) -> str:
        true = a.args[1]
        want = self.knowledge.predicates[a.predicate][1]
        room = self._room_of(true) or self._robot_room()
        others = [f.name for f in self._map.furniture if f.room == room and f.name != true
                  and self.knowledge.is_subtype(f.type, want)]
        if a.predicate == "on" and room is not None and floor_of(room) != true and floor_of(room) in self.task.objects:
            others.append(floor_of(room))
        return rng.choice(sorted(others)) if others else true

    # -- robot interfaces: body and map ----------------------------------------------------------

    def state(self) -> RobotState:
        return RobotState(float(self._tick), self._robot_room(), gripper_holding=self._held() is not None)

    def site_map(self) -> SiteMap:
        return self._map

    # -- situations -------------------------------------------------------------------------

    def _inject(self, spec: SituationSpec, ga) -> bool:
        """Make ``spec`` so; False when it cannot apply here (nothing held to drop)."""
        room = self._robot_room()
        obj = self._held() if spec.drops == "held" else (ga.args[spec.drops] if spec.drops is not None else None)
        if spec.drops is not None and (obj is None or room is None or floor_of(room) not in self.task.objects):
            return False
        if spec.drops is not None:
            self._drop(obj, room)
        if spec.effect:
            self.atoms = set(ga.apply(frozenset(self.atoms)))
        return True

    def _drop(self, obj: str, room: str) -> None:
        was_held = Atom("holding", (obj,)) in self.atoms
        self.atoms -= {a for a in self.atoms if a.predicate in LOCATIONS and a.args[0] == obj}
        self.atoms |= {Atom("on", (obj, floor_of(room))), Atom("in_room", (obj, room)), Atom("reachable", (obj,))}
        self.atoms -= {a for a in self.atoms if a.predicate == "blocking" and obj in a.args}
        if was_held:
            self.atoms.add(Atom("hand_empty"))

    # -- views ------------------------------------------------------------------------------

    def _new_view(self) -> None:
        self._view += 1
        self._tick += 1
        self._visibility.clear()

    def _visibility_of(self, obj: str, targeted: bool) -> float:
        key = (obj, targeted)
        if key not in self._visibility:
            seen = self._in_view(obj) or (targeted and self._in_room_with_robot(obj))
            self._visibility[key] = self._view_rng.uniform(VISIBILITY_LOW, 1.0) if seen else 0.0
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

    def _in_room_with_robot(self, obj: str) -> bool:
        # the camera turns toward what it is asked about: anything in the robot's room, not shut away
        return not self._enclosed(obj) and self._robot_room() in self._rooms_of(obj)

    def _in_view(self, obj: str) -> bool:
        if not self._situated:
            return True  # a domain without a robot position (blocksworld): the whole scene is in view
        if self.task.objects.get(obj) == "room":
            return obj == self._robot_room()
        if Atom("holding", (obj,)) in self.atoms:
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

    def _room_of(self, obj: str) -> str | None:
        rooms = sorted(self._rooms_of(obj))
        return rooms[0] if rooms else None

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
