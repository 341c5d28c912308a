"""Zenoh key expressions: every key the executive and the skill servers use, in one place.

All keys live under ``vap/<robot>/`` so that two robots on one Zenoh network never see each
other's goals (a client subscribes to its robots' namespaces only)::

    vap/<robot>/skill/<action>        queryable: start a goal (GoalRequest -> GoalReply)
    vap/<robot>/goal/<id>/status      published: feedback and the final result (GoalStatus)
    vap/<robot>/goal/<id>/cancel      published: ask the server to cancel (CancelRequest)
    vap/<robot>/camera/capture        queryable: CaptureRequest -> Frame
    vap/<robot>/camera/view           queryable: ViewRequest -> MoveViewReply (go to a viewpoint)
    vap/<robot>/camera/move           queryable: MoveViewRequest -> MoveViewReply
    vap/<robot>/body/state            queryable: StateRequest -> RobotState
    vap/<robot>/body/map              queryable: MapRequest -> SiteMap
    vap/<robot>/vlm/ask               queryable: VlmRequest -> Answer (a world-side VLM)
    vap/<robot>/world/action          queryable: ActionEvent -> Outcome (sim only: which action
                                      a goal is, for Table II injection; see world_hooks)
    vap/<robot>/alive/<server>        liveliness token of a running skill server
    vap/<robot>/alive/<server>/goal/<action>/<id>
                                      liveliness token of a goal that server runs: declared when
                                      it starts, withdrawn when its result is out (``vap-bt parts``)
    vap/part/<kind>/<name>            liveliness token of a part that is no one robot's: the sim
                                      (``sim``), an executive run with ``--connect`` (``executive``)
    vap/world/oracle/<verb>           queryable: OracleQuery -> OracleReply (sim only: the truth
                                      the runner scores its report by; see world_services)

Robot, action, server and goal names are single key chunks: no ``/`` and none of Zenoh's
wildcard or reserved characters, checked here once so that a bad name is one clear error. The
robot names ``world`` and ``part`` are taken by the keys above. A goal's token nests under its
server's, one chunk deeper than ``alive/*``, so a client watching its robots' servers never sees
goals come and go.
"""

from __future__ import annotations

import os
import re

ROOT = "vap"
_CHUNK = re.compile(r"^[A-Za-z0-9_.\-]+$")
#: every key of the project: what ``vap-bt parts`` asks the liveliness tokens of
EVERYTHING = f"{ROOT}/**"


def chunk(kind: str, name: str) -> str:
    """``name`` if it can be one key chunk, else ValueError naming ``kind``."""
    if not isinstance(name, str) or not _CHUNK.match(name):
        raise ValueError(f"bad {kind} name {name!r}: use letters, digits, '_', '-', '.'")
    return name


def skill(robot: str, action: str) -> str:
    """The queryable that starts a goal of ``action`` on ``robot``."""
    return f"{ROOT}/{chunk('robot', robot)}/skill/{chunk('action', action)}"


def goal_status(robot: str, goal_id: str) -> str:
    """Where goal ``goal_id``'s feedback and result are published."""
    return f"{ROOT}/{chunk('robot', robot)}/goal/{chunk('goal', goal_id)}/status"


def goal_cancel(robot: str, goal_id: str) -> str:
    """Where a cancel of goal ``goal_id`` is published."""
    return f"{ROOT}/{chunk('robot', robot)}/goal/{chunk('goal', goal_id)}/cancel"


def all_goal_status(robot: str) -> str:
    """Every goal's status key on ``robot`` (a client's one subscription)."""
    return f"{ROOT}/{chunk('robot', robot)}/goal/*/status"


def all_goal_cancel(robot: str) -> str:
    """Every goal's cancel key on ``robot`` (a server's one subscription)."""
    return f"{ROOT}/{chunk('robot', robot)}/goal/*/cancel"


def camera(robot: str, verb: str) -> str:
    """``verb`` is one of capture, view, move."""
    return f"{ROOT}/{chunk('robot', robot)}/camera/{chunk('camera verb', verb)}"


def body(robot: str, verb: str) -> str:
    """``verb`` is one of state, map."""
    return f"{ROOT}/{chunk('robot', robot)}/body/{chunk('body verb', verb)}"


def vlm(robot: str) -> str:
    """The queryable of ``robot``'s world-side VLM."""
    return f"{ROOT}/{chunk('robot', robot)}/vlm/ask"


def world_action(robot: str) -> str:
    """A simulated world's hook: the skill server says which action a goal is (sim only)."""
    return f"{ROOT}/{chunk('robot', robot)}/world/action"


def oracle(verb: str) -> str:
    """A simulated world's oracle, for the runner's report only (one world per Zenoh network)."""
    return f"{ROOT}/world/oracle/{chunk('oracle verb', verb)}"


def alive(robot: str, server: str) -> str:
    """The liveliness token of skill server ``server`` on ``robot``."""
    return f"{ROOT}/{chunk('robot', robot)}/alive/{chunk('server', server)}"


def all_alive(robot: str) -> str:
    """Every skill server's token on ``robot`` (not their goals', one chunk deeper)."""
    return f"{ROOT}/{chunk('robot', robot)}/alive/*"


def goal_alive(robot: str, server: str, action: str, goal_id: str) -> str:
    """The liveliness token of a goal in flight on ``server``."""
    return f"{alive(robot, server)}/goal/{chunk('action', action)}/{chunk('goal', goal_id)}"


def part(kind: str, name: str) -> str:
    """The liveliness token of a part that is no one robot's (``sim``, ``executive``)."""
    return f"{ROOT}/part/{chunk('part kind', kind)}/{chunk('part', name)}"


def instance(label: str, zid: object) -> str:
    """A name for this process's part, unique on the network: ``label-pid-zid`` (the first 8
    characters of the Zenoh session's id tell apart two machines' equal pids); what ``label``
    has that a key chunk cannot hold becomes ``_``."""
    return f"{re.sub(r'[^A-Za-z0-9_.-]', '_', label) or 'part'}-{os.getpid()}-{str(zid)[:8]}"


def last_chunks(key: str, n: int) -> list[str]:
    """The last ``n`` chunks of a concrete key (goal id, server name)."""
    return str(key).rsplit("/", n)[1:]
