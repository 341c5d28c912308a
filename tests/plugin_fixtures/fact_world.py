"""A small, honest World over a set of ground facts, for transport and plugin tests only.

It is not shipped as a world. A handful of actions have real preconditions and effects; every
action takes ``duration`` seconds, split into ``steps`` steps, reporting feedback after each and
stopping early when the goal is cancelled, so tests can see feedback, cancel and busy resources
over a real Zenoh transport. Frames carry tiny but real rgb/depth/mask arrays and a camera pose so
the binary path of the wire format is exercised.
"""

from __future__ import annotations

import time

import numpy as np

from vap_bt.domain.atoms import Atom
from vap_bt.robot.camera import VIEW_DIRECTIONS, Aim, Viewpoint
from vap_bt.robot.frame import Detection, Frame
from vap_bt.robot.site_map import RoomInfo, SiteMap
from vap_bt.robot.state import RobotState
from vap_bt.sim.oracle import FunctionOracle
from vap_bt.outcome import Outcome
from vap_bt.world import GoalContext

# action -> (preconditions, added, deleted) over argument positions ?0, ?1
_SCHEMAS: dict[str, tuple[list[str], list[str], list[str]]] = {
    "navigate": (["robot_in ?0"], ["robot_in ?1"], ["robot_in ?0"]),
    "find": ([], ["inview ?0"], []),
    "grasp": (["on ?0 ?1", "hand_empty"], ["holding ?0"], ["on ?0 ?1", "hand_empty"]),
    "placeon": (["holding ?0"], ["on ?0 ?1", "hand_empty"], ["holding ?0"]),
    "open": ([], ["opened ?0"], []),
    "close": (["opened ?0"], [], ["opened ?0"]),
}

INITIAL = {"robot_in kitchen", "hand_empty", "on cup table"}
OBJECTS = {"cup": "cup", "table": "table", "kitchen": "room", "hall": "room"}


def _atom(template: str, args: tuple[str, ...]) -> Atom:
    pred, *params = template.split()
    return Atom(pred, tuple(args[int(p[1:])] for p in params))


class FactWorld:
    name = "facts"

    def __init__(self, duration: float | str = 0.0, steps: int | str = 5) -> None:
        self.duration = float(duration)
        self.steps = max(1, int(steps))
        self.oracle = FunctionOracle(lambda a: a in self.facts, lambda: [])
        self.reset(0)

    def reset(self, seed: int) -> None:
        self.facts = {Atom(t.split()[0], tuple(t.split()[1:])) for t in INITIAL}
        self.view = 0
        self.performed: list[tuple[str, tuple[str, ...]]] = []

    def perform(self, action: str, args: tuple[str, ...], ctx: GoalContext) -> Outcome:
        schema = _SCHEMAS.get(action)
        if schema is None:
            return Outcome(False, f"facts world cannot {action}")
        pre, add, delete = schema
        try:
            needed = [_atom(t, args) for t in pre]
        except (IndexError, ValueError):
            return Outcome(False, f"{action}{args}: wrong number of arguments")
        if not all(a in self.facts for a in needed):
            return Outcome(False, f"{action}{args}: preconditions do not hold")
        for i in range(self.steps):
            if ctx.cancelled():
                return Outcome(False, f"{action} stopped by cancel")
            time.sleep(self.duration / self.steps)
            ctx.feedback((i + 1) / self.steps, f"{action} step {i + 1}/{self.steps}")
        self.facts -= {_atom(t, args) for t in delete}
        self.facts |= {_atom(t, args) for t in add}
        self.performed.append((action, tuple(args)))
        return Outcome(True, f"{action} done")

    def capture(self, aim: Aim | None = None) -> Frame:
        h, w = 4, 6
        masks = np.full((h, w), -1, np.int32)
        masks[1:3, 2:4] = 7
        self.view += 1
        return Frame(
            frame_id=f"facts-{self.view}", stamp=float(self.view),
            detections=(Detection("cup", pixels=4, mask_id=7),),
            rgb=np.arange(h * w * 3, dtype=np.uint8).reshape(h, w, 3),
            depth=np.linspace(0.5, 2.0, h * w, dtype=np.float32).reshape(h, w),
            masks=masks, intrinsics=(500.0, 500.0, 3.0, 2.0), camera_pose=np.eye(4),
            aim=aim.names if aim else ())

    def goto_view(self, view: Viewpoint) -> bool:
        self.view += 1
        return view.room in OBJECTS

    def move_view(self, aim: Aim, direction: str) -> bool:
        if not set(aim.names) <= set(OBJECTS) or direction not in VIEW_DIRECTIONS:
            return False
        self.view += 1
        return True

    def state(self) -> RobotState:
        room = next((a.args[0] for a in self.facts if a.predicate == "robot_in"), None)
        return RobotState(float(self.view), room, gripper_holding=any(a.predicate == "holding" for a in self.facts))

    def site_map(self) -> SiteMap:
        return SiteMap(rooms=tuple(RoomInfo(n, f"floor_{n}") for n, t in OBJECTS.items() if t == "room"))

    def close(self) -> None:
        pass
