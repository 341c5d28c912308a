"""The wire schema: every message between the executive and the skill servers, versioned.

Each message is one *frame*::

    b"VAPB" | u32 little-endian header length | header (UTF-8 JSON) | array bytes ...

The header always carries ``schema`` (:data:`SCHEMA`, bumped on any incompatible change) and
``kind`` (which message it is), then the message's own fields. Numeric arrays never go through
JSON: the header lists them as ``[name, dtype, shape]`` and their raw little-endian bytes follow
in that order, so a 640x480 RGB-D frame costs its pixels plus a few hundred bytes. Images are
normalised on the way out: rgb ``uint8 (H, W, 3)``, depth ``float32 (H, W)`` metres,
segmentation ``int32 (H, W)``.

A frame from a peer speaking another schema raises :class:`SchemaMismatch`, which says both
versions; anything else undecodable raises :class:`MessageError`. Neither ever shows a traceback
to the user: servers answer with an error reply, clients turn it into a rejected goal.

``SkillResult.data`` must be JSON-friendly; numpy values become lists, and anything else is sent
as its ``str`` so that a skill's odd return value never breaks the transport.
"""

from __future__ import annotations

import json
import struct
from dataclasses import dataclass, fields
from typing import Any, Callable, TypeVar

import numpy as np

from vap_bt.domain.atoms import Atom
from vap_bt.skill import Feedback, GoalState, SkillResult
from vap_bt.world import ObjectInfo, Observation, SceneSnapshot

SCHEMA = 1
MAGIC = b"VAPB"
_PREFIX = struct.Struct("<4sI")

T = TypeVar("T")


class MessageError(ValueError):
    """A frame that is not a valid message of the expected kind."""


class SchemaMismatch(MessageError):
    """The peer speaks another schema version."""


# -- messages ------------------------------------------------------------------------------------


@dataclass(frozen=True)
class GoalRequest:
    """Start ``action(args)``; the client picks ``goal_id`` so it can listen before asking."""

    goal_id: str
    action: str
    args: tuple[str, ...]
    client: str = ""


@dataclass(frozen=True)
class GoalReply:
    """The server's answer to a GoalRequest: accepted, or rejected with a reason."""

    goal_id: str
    accepted: bool
    reason: str = ""
    server: str = ""


@dataclass(frozen=True)
class GoalStatus:
    """Published on a goal's status key: feedback while ACTIVE, then once with the result."""

    goal_id: str
    state: GoalState
    feedback: Feedback | None = None
    result: SkillResult | None = None
    server: str = ""


@dataclass(frozen=True)
class CancelRequest:
    goal_id: str


@dataclass(frozen=True)
class ObserveRequest:
    targets: tuple[str, ...]


@dataclass(frozen=True)
class SurveyRequest:
    pass


@dataclass(frozen=True)
class MoveViewRequest:
    target: str
    direction: str


@dataclass(frozen=True)
class MoveViewReply:
    reachable: bool


@dataclass(frozen=True)
class ErrorReply:
    """A server could not answer (its world raised); ``reason`` says why."""

    reason: str


# -- codec ---------------------------------------------------------------------------------------

Arrays = dict[str, np.ndarray]
Packer = Callable[[Any], tuple[dict[str, Any], Arrays]]
Unpacker = Callable[[dict[str, Any], Arrays], Any]

_IMAGE_DTYPES = {"rgb": np.uint8, "depth": np.float32, "segmentation": np.int32}


def _pack_flat(msg: Any) -> tuple[dict[str, Any], Arrays]:
    return {f.name: getattr(msg, f.name) for f in fields(msg)}, {}


def _flat_unpacker(cls: type) -> Unpacker:
    def unpack(d: dict[str, Any], _: Arrays) -> Any:
        return cls(**{k: tuple(v) if isinstance(v, list) else v for k, v in d.items()})

    return unpack


def _pack_status(m: GoalStatus) -> tuple[dict[str, Any], Arrays]:
    fb = None if m.feedback is None else [m.feedback.progress, m.feedback.text]
    res = None
    if m.result is not None:
        res = [m.result.success, m.result.message, _jsonable(m.result.data) if m.result.data else {}]
    return {"goal_id": m.goal_id, "state": m.state.value, "feedback": fb, "result": res,
            "server": m.server}, {}


def _unpack_status(d: dict[str, Any], _: Arrays) -> GoalStatus:
    fb, res = d["feedback"], d["result"]
    return GoalStatus(
        goal_id=d["goal_id"],
        state=GoalState(d["state"]),
        feedback=None if fb is None else Feedback(float(fb[0]), str(fb[1])),
        result=None if res is None else SkillResult(bool(res[0]), str(res[1]), dict(res[2])),
        server=d.get("server", ""),
    )


def _pack_observation(o: Observation) -> tuple[dict[str, Any], Arrays]:
    arrays = {
        name: np.ascontiguousarray(getattr(o, name), dtype=dtype)
        for name, dtype in _IMAGE_DTYPES.items()
        if getattr(o, name) is not None
    }
    return {
        "view_index": o.view_index,
        "targets": list(o.targets),
        "visibility": o.visibility,
        "segment_names": {str(k): v for k, v in o.segment_names.items()},
        "intrinsics": o.intrinsics,
        "camera_pose": o.camera_pose,
        "stamp": o.stamp,
    }, arrays


def _unpack_observation(d: dict[str, Any], arrays: Arrays) -> Observation:
    return Observation(
        view_index=int(d["view_index"]),
        targets=tuple(d["targets"]),
        visibility={k: float(v) for k, v in d["visibility"].items()},
        rgb=arrays.get("rgb"),
        depth=arrays.get("depth"),
        segmentation=arrays.get("segmentation"),
        segment_names={int(k): v for k, v in d["segment_names"].items()},
        intrinsics=None if d["intrinsics"] is None else tuple(d["intrinsics"]),
        camera_pose=None if d["camera_pose"] is None else tuple(d["camera_pose"]),
        stamp=float(d["stamp"]),
    )


def _pack_snapshot(s: SceneSnapshot) -> tuple[dict[str, Any], Arrays]:
    objects = [{f.name: getattr(o, f.name) for f in fields(o)} for o in s.objects]
    facts = sorted([a.predicate, list(a.args)] for a in s.facts)
    return {"objects": objects, "facts": facts}, {}


def _unpack_snapshot(d: dict[str, Any], _: Arrays) -> SceneSnapshot:
    def obj(o: dict[str, Any]) -> ObjectInfo:
        return ObjectInfo(**{k: tuple(v) if isinstance(v, list) else v for k, v in o.items()})

    return SceneSnapshot(
        objects=[obj(o) for o in d["objects"]],
        facts={Atom(p, tuple(args)) for p, args in d["facts"]},
    )


_CODECS: dict[str, tuple[type, Packer, Unpacker]] = {
    "goal_request": (GoalRequest, _pack_flat, _flat_unpacker(GoalRequest)),
    "goal_reply": (GoalReply, _pack_flat, _flat_unpacker(GoalReply)),
    "goal_status": (GoalStatus, _pack_status, _unpack_status),
    "cancel": (CancelRequest, _pack_flat, _flat_unpacker(CancelRequest)),
    "observe": (ObserveRequest, _pack_flat, _flat_unpacker(ObserveRequest)),
    "survey": (SurveyRequest, _pack_flat, _flat_unpacker(SurveyRequest)),
    "move_view": (MoveViewRequest, _pack_flat, _flat_unpacker(MoveViewRequest)),
    "move_view_reply": (MoveViewReply, _pack_flat, _flat_unpacker(MoveViewReply)),
    "error": (ErrorReply, _pack_flat, _flat_unpacker(ErrorReply)),
    "observation": (Observation, _pack_observation, _unpack_observation),
    "scene_snapshot": (SceneSnapshot, _pack_snapshot, _unpack_snapshot),
}
_KIND_OF = {cls: kind for kind, (cls, _, _) in _CODECS.items()}


def encode(msg: Any) -> bytes:
    """One frame for ``msg`` (any message class above, Observation or SceneSnapshot)."""
    kind = _KIND_OF.get(type(msg))
    if kind is None:
        raise TypeError(f"{type(msg).__name__} is not a transport message")
    body, arrays = _CODECS[kind][1](msg)
    header = {"schema": SCHEMA, "kind": kind, **body,
              "arrays": [[n, a.dtype.str, list(a.shape)] for n, a in arrays.items()]}
    head = json.dumps(header, separators=(",", ":"), default=_json_default).encode()
    return b"".join([_PREFIX.pack(MAGIC, len(head)), head, *(a.tobytes() for a in arrays.values())])


def decode(data: bytes | bytearray | memoryview, expect: type[T]) -> T:
    """The message in ``data``, which must be of type ``expect``."""
    header, arrays = _read_frame(bytes(data))
    kind = header.pop("kind", None)
    codec = _CODECS.get(kind)  # type: ignore[arg-type]
    if codec is None:
        raise MessageError(f"unknown message kind {kind!r}")
    cls, _, unpack = codec
    if cls is not expect:
        raise MessageError(f"expected a {_KIND_OF[expect]} message, got {kind}")
    try:
        return unpack(header, arrays)
    except (KeyError, TypeError, ValueError, IndexError) as exc:
        raise MessageError(f"malformed {kind} message: {type(exc).__name__}: {exc}") from None


def _read_frame(data: bytes) -> tuple[dict[str, Any], Arrays]:
    if len(data) < _PREFIX.size or data[:4] != MAGIC:
        raise MessageError("not a vap_bt message (bad magic)")
    _, n = _PREFIX.unpack_from(data)
    try:
        header = json.loads(data[_PREFIX.size:_PREFIX.size + n])
    except ValueError as exc:
        raise MessageError(f"unreadable message header: {exc}") from None
    if not isinstance(header, dict):
        raise MessageError("message header is not an object")
    schema = header.pop("schema", None)
    if schema != SCHEMA:
        raise SchemaMismatch(
            f"peer speaks message schema {schema!r}, this side speaks {SCHEMA}: "
            "run the same vap_bt version on both ends"
        )
    return header, _read_arrays(data, _PREFIX.size + n, header.pop("arrays", []))


def _read_arrays(data: bytes, offset: int, specs: list) -> Arrays:
    arrays: Arrays = {}
    for spec in specs:
        try:
            name, dtype, shape = spec
            dt = np.dtype(dtype)
            count = int(np.prod(shape, dtype=np.int64))
        except (TypeError, ValueError) as exc:
            raise MessageError(f"bad array description {spec!r}: {exc}") from None
        end = offset + count * dt.itemsize
        if end > len(data):
            raise MessageError(f"array {name!r} is truncated")
        arrays[name] = np.frombuffer(data, dt, count, offset).reshape(shape).copy()
        offset = end
    return arrays


def _jsonable(value: Any) -> Any:
    """``value`` with numpy types and tuples made JSON-friendly; unknown objects as str."""
    return json.loads(json.dumps(value, default=_json_default))


def _json_default(obj: Any) -> Any:
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, (set, frozenset)):
        return sorted(obj, key=str)
    return str(obj)
