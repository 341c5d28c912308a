"""The wire schema: every message between the executive and the skill servers, versioned.

Each message is one *frame*::

    b"VAPB" | u32 schema | u8 kind | header | array bytes ...

``schema`` is :data:`SCHEMA`, bumped on any incompatible change; ``kind`` says which message it
is (:data:`KIND_CODES`, all below 123 so that byte 8 is never ``{``, see below). All integers
are little-endian. What the header looks like depends on
the kind:

* **Goal traffic** (``goal_request``, ``goal_reply``, ``goal_status``, ``cancel``) sits on the
  latency-critical path of every goal, so its header is a fixed binary layout that costs a few
  microseconds to pack and unpack (JSON cost ten times that)::

      goal_request     strings[goal_id, action, client, hints, *args]
      goal_reply       u8 accepted | strings[goal_id, reason, server]
      cancel           strings[goal_id]
      goal_status      u8 flags | f64 progress | strings[goal_id, state, server,
                                                         feedback text, result message, result data]

  where ``strings[...]`` is ``u32 count | u32 length of each, in characters | the strings'
  UTF-8 bytes, concatenated`` (one decode for all of them); the status
  ``flags`` are bit 0 "has feedback", bit 1 "has result", bit 2 "result succeeded"; ``state`` is
  the :class:`~vap_bt.skill.GoalState` value; ``result data`` is JSON (empty for ``{}``); a
  request's ``hints`` is a JSON list of :class:`~vap_bt.skill.Hint` objects (empty for none).
* **Everything else** (robot-interface requests and replies: frames, robot state, the site map,
  viewpoints; VLM queries and answers; errors) has
  ``u32 length | UTF-8 JSON object`` with the message's own fields. Numeric arrays never go
  through JSON: the header lists them as ``[name, dtype, shape]`` under ``arrays`` and their raw
  little-endian bytes follow in that order, so a 640x480 RGB-D frame costs its pixels plus a few
  hundred bytes. Images are normalised on the way out: rgb ``uint8 (H, W, 3)``, depth
  ``float32 (H, W)`` metres, instance masks ``int32 (H, W)``; a frame's camera pose travels as a
  ``float64 (4, 4)`` array.

Schema history: 1 — ``b"VAPB" | u32 length | JSON header (with "schema" and "kind") | arrays``
for every kind; 2 — the layout above with string lengths in bytes; 3 — the layout above; 4 — the
robot interfaces (frames with detections, state, map, viewpoints) and the VLM service replace
schema 3's observations and scene snapshots; 5 — goal requests carry the executive's hints, the
site map carries the furniture models (height, cavity, articulation, switch, tap; a door's
articulation), the robot's drivers travel (driver calls and replies), and a simulated world has an
action hook (``action_event``/``action_ack``) and, added later without a bump since nothing
changed, an oracle for the runner's report (``oracle_query``/``oracle_reply``) and an aim's believed
``place`` (a peer without it reads none and sends none). A schema-1 frame is still recognised (its byte 8, the
start of its JSON header, is ``{``), so an old peer gets a :class:`SchemaMismatch` naming both
versions, not garbage.

A frame from a peer speaking another schema raises :class:`SchemaMismatch`, which says both
versions; anything else undecodable raises :class:`MessageError`. Neither ever shows a traceback
to the user: servers answer with an error reply, clients turn it into a rejected goal.

``SkillResult.data`` must be JSON-friendly; numpy values become lists, and anything else is sent
as its ``str`` so that a skill's odd return value never breaks the transport.
"""

from __future__ import annotations

import json
import struct
from dataclasses import dataclass, field, fields
from typing import Any, Callable, TypeVar

import numpy as np

from vap_bt.domain.atoms import Atom
from vap_bt.skill import Feedback, GoalState, Hint, SkillResult
from vap_bt.perception.vlm import Answer, Query
from vap_bt.robot.camera import Aim, Viewpoint
from vap_bt.robot.frame import Detection, Frame
from vap_bt.robot.site_map import Articulation, Cavity, DoorInfo, FurnitureInfo, RoomInfo, SiteMap
from vap_bt.robot.state import RobotState

SCHEMA = 5
MAGIC = b"VAPB"
_PREFIX = struct.Struct("<4sIB")  # magic, schema, kind
_U32 = struct.Struct("<I")
_LEGACY_PREFIX = struct.Struct("<4sI")  # schema 1: magic, JSON header length

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
    hints: tuple[Hint, ...] = ()


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
class CaptureRequest:
    """Aim the camera (None: as it is) and take a frame."""

    aim: Aim | None = None


@dataclass(frozen=True)
class ViewRequest:
    """Go to a viewpoint of an exploration sweep."""

    view: Viewpoint


@dataclass(frozen=True)
class MoveViewRequest:
    """Move the viewpoint ``direction`` relative to ``aim``."""

    aim: Aim
    direction: str


@dataclass(frozen=True)
class StateRequest:
    """Ask for the robot's state (proprioception and localization)."""


@dataclass(frozen=True)
class MapRequest:
    """Ask for the site map."""


@dataclass(frozen=True)
class VlmRequest:
    """Ask the world-side VLM ``query`` about a frame that world's camera took; ``identified``
    is the executive's association of names to the frame's detections (which instance in the
    picture the question's names mean: a set-of-marks prompt's marks)."""

    query: Query
    frame_id: str
    identified: dict = field(default_factory=dict)


@dataclass(frozen=True)
class DriverCall:
    """A call on a robot's drivers (:mod:`vap_bt.transport.drivers`): ``call`` names it
    (``arm.follow``, ``base.pose``, ...), ``client`` the caller; plain values and numeric arrays."""

    call: str
    client: str = ""
    values: dict = field(default_factory=dict)
    arrays: dict = field(default_factory=dict)


@dataclass(frozen=True)
class DriverReply:
    """A driver's answer: plain values and numeric arrays."""

    values: dict = field(default_factory=dict)
    arrays: dict = field(default_factory=dict)


@dataclass(frozen=True)
class ActionEvent:
    """Sim only: a goal for ``action(args)`` begins or ends (``phase``), for Table II injection."""

    phase: str  # "begin" | "end"
    action: str
    args: tuple[str, ...] = ()


@dataclass(frozen=True)
class ActionAck:
    """The simulated world took an ActionEvent (it says nothing of what it drew)."""

    ok: bool
    reason: str = ""


@dataclass(frozen=True)
class OracleQuery:
    """Sim only, for the runner's report (:mod:`vap_bt.transport.world_services`): ask a simulated
    world ``verb`` (``holds``, ``injected``, ``info``, ``site_map``, ``reset``) about ``atoms``,
    or reset it to ``seed``."""

    verb: str
    atoms: tuple[Atom, ...] = ()
    seed: int | None = None


@dataclass(frozen=True)
class OracleReply:
    """A simulated world's answer to an OracleQuery: plain JSON values."""

    values: dict = field(default_factory=dict)


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

_IMAGE_DTYPES = {"rgb": np.uint8, "depth": np.float32, "masks": np.int32}


def _pack_flat(msg: Any) -> tuple[dict[str, Any], Arrays]:
    return {f.name: getattr(msg, f.name) for f in fields(msg)}, {}


def _flat_unpacker(cls: type) -> Unpacker:
    def unpack(d: dict[str, Any], _: Arrays) -> Any:
        return cls(**{k: tuple(v) if isinstance(v, list) else v for k, v in d.items()})

    return unpack


def _atoms_out(atoms) -> list:
    return [[a.predicate, list(a.args)] for a in atoms]


def _atoms_in(rows) -> tuple[Atom, ...]:
    return tuple(Atom(p, tuple(args)) for p, args in rows)


def _tuple_or_none(v):
    return None if v is None else tuple(v)


def _aim_out(a: Aim | None) -> dict | None:
    return None if a is None else {"names": list(a.names), "point": a.point, "place": a.place}


def _aim_in(d: dict | None) -> Aim | None:
    return None if d is None else Aim(tuple(d["names"]), _tuple_or_none(d["point"]), d.get("place"))


def _pack_capture(m: CaptureRequest) -> tuple[dict[str, Any], Arrays]:
    return {"aim": _aim_out(m.aim)}, {}


def _unpack_capture(d: dict[str, Any], _: Arrays) -> CaptureRequest:
    return CaptureRequest(_aim_in(d["aim"]))


def _pack_view(m: ViewRequest) -> tuple[dict[str, Any], Arrays]:
    v = m.view
    return {"room": v.room, "aim": _aim_out(v.aim), "base_pose": v.base_pose, "label": v.label}, {}


def _unpack_view(d: dict[str, Any], _: Arrays) -> ViewRequest:
    return ViewRequest(Viewpoint(d["room"], _aim_in(d["aim"]), _tuple_or_none(d["base_pose"]), d["label"]))


def _pack_move(m: MoveViewRequest) -> tuple[dict[str, Any], Arrays]:
    return {"aim": _aim_out(m.aim), "direction": m.direction}, {}


def _unpack_move(d: dict[str, Any], _: Arrays) -> MoveViewRequest:
    return MoveViewRequest(_aim_in(d["aim"]), d["direction"])


def _pack_frame(f: Frame) -> tuple[dict[str, Any], Arrays]:
    arrays = {name: np.ascontiguousarray(getattr(f, name), dtype=dtype)
              for name, dtype in _IMAGE_DTYPES.items() if getattr(f, name) is not None}
    if f.camera_pose is not None:
        arrays["camera_pose"] = np.ascontiguousarray(f.camera_pose, dtype=np.float64)
    dets = [{"name": d.name, "label": d.label, "pixels": d.pixels, "mask_id": d.mask_id, "score": d.score,
             "relations": _atoms_out(d.relations)} for d in f.detections]
    return {"frame_id": f.frame_id, "stamp": f.stamp, "detections": dets, "intrinsics": f.intrinsics,
            "aim": list(f.aim), "extra": f.extra, "stand": f.stand}, arrays


def _unpack_frame(d: dict[str, Any], arrays: Arrays) -> Frame:
    dets = tuple(Detection(x["label"], int(x["pixels"]), int(x["mask_id"]), float(x["score"]),
                           _atoms_in(x["relations"]), name=x["name"]) for x in d["detections"])
    return Frame(d["frame_id"], float(d["stamp"]), dets, rgb=arrays.get("rgb"), depth=arrays.get("depth"),
                 masks=arrays.get("masks"), intrinsics=_tuple_or_none(d["intrinsics"]),
                 camera_pose=arrays.get("camera_pose"), aim=tuple(d["aim"]), extra=dict(d["extra"]),
                 stand=d.get("stand"))


def _unpack_state(d: dict[str, Any], _: Arrays) -> RobotState:
    return RobotState(float(d["stamp"]), d["room"], _tuple_or_none(d["base_pose"]), tuple(d["joints"]),
                      _tuple_or_none(d["tcp_pose"]), d["gripper_width"], d["gripper_holding"])


def _articulation_out(a: Articulation | None) -> dict | None:
    return None if a is None else {f.name: getattr(a, f.name) for f in fields(a)}


def _articulation_in(d: dict | None) -> Articulation | None:
    return None if d is None else Articulation(**{k: tuple(v) if isinstance(v, list) else v for k, v in d.items()})


def _cavity_out(c: Cavity | None) -> list | None:
    return None if c is None else [list(c.z), c.wall, c.open]


def _cavity_in(v: list | None) -> Cavity | None:
    return None if v is None else Cavity(tuple(v[0]), float(v[1]), v[2])


def _pack_map(m: SiteMap) -> tuple[dict[str, Any], Arrays]:
    return {"rooms": [[r.name, r.floor, r.bounds] for r in m.rooms],
            "doors": [[x.name, list(x.rooms), x.pose, x.width, _articulation_out(x.articulation)] for x in m.doors],
            "furniture": [[f.name, f.label, f.type, f.room, f.pose, f.footprint, f.height, _cavity_out(f.cavity),
                           _articulation_out(f.articulation), f.switch, f.tap] for f in m.furniture],
            "facts": _atoms_out(sorted(m.facts))}, {}


def _unpack_map(d: dict[str, Any], _: Arrays) -> SiteMap:
    return SiteMap(
        rooms=tuple(RoomInfo(n, fl, _tuple_or_none(b)) for n, fl, b in d["rooms"]),
        doors=tuple(DoorInfo(n, tuple(r), _tuple_or_none(p), w, _articulation_in(a)) for n, r, p, w, a in d["doors"]),
        furniture=tuple(FurnitureInfo(n, lb, t, r, _tuple_or_none(p), _tuple_or_none(fp), h, _cavity_in(c),
                                      _articulation_in(a), _tuple_or_none(sw), _tuple_or_none(tap))
                        for n, lb, t, r, p, fp, h, c, a, sw, tap in d["furniture"]),
        facts=frozenset(_atoms_in(d["facts"])))


def _pack_driver(m) -> tuple[dict[str, Any], Arrays]:
    body = {f.name: getattr(m, f.name) for f in fields(m) if f.name != "arrays"}
    return body, {k: np.ascontiguousarray(v) for k, v in m.arrays.items()}


def _driver_unpacker(cls: type) -> Unpacker:
    def unpack(d: dict[str, Any], arrays: Arrays) -> Any:
        return cls(**d, arrays=dict(arrays))

    return unpack


def _pack_vlm(m: VlmRequest) -> tuple[dict[str, Any], Arrays]:
    q = m.query
    return {"frame_id": m.frame_id, "prompt": q.prompt, "kind": q.kind, "purpose": q.purpose,
            "about": _atoms_out(q.about), "objects": list(q.objects), "options": list(q.options),
            "identified": {str(k): int(v) for k, v in m.identified.items()}}, {}


def _unpack_vlm(d: dict[str, Any], _: Arrays) -> VlmRequest:
    q = Query(d["prompt"], d["kind"], d["purpose"], _atoms_in(d["about"]), tuple(d["objects"]), tuple(d["options"]))
    return VlmRequest(q, d["frame_id"], {str(k): int(v) for k, v in d.get("identified", {}).items()})


def _pack_oracle(m: OracleQuery) -> tuple[dict[str, Any], Arrays]:
    return {"verb": m.verb, "atoms": _atoms_out(m.atoms), "seed": m.seed}, {}


def _unpack_oracle(d: dict[str, Any], _: Arrays) -> OracleQuery:
    return OracleQuery(d["verb"], _atoms_in(d["atoms"]), d.get("seed"))


# -- goal traffic: binary headers ------------------------------------------------------------


def _pack_strings(*items: str) -> bytes:
    return (struct.pack(f"<{len(items) + 1}I", len(items), *map(len, items))
            + "".join(items).encode())


def _unpack_strings(data: bytes, offset: int) -> list[str]:
    """The strings at ``offset``, which must run exactly to the end of ``data``."""
    (n,) = _U32.unpack_from(data, offset)
    offset += 4
    if n * 4 > len(data) - offset:
        raise MessageError("unreadable message header: string table is truncated")
    lengths = struct.unpack_from(f"<{n}I", data, offset)
    text = data[offset + 4 * n:].decode()  # one decode for all of them
    if sum(lengths) != len(text):
        raise MessageError("unreadable message header: strings do not match their lengths")
    out, start = [], 0
    for length in lengths:
        out.append(text[start:start + length])
        start += length
    return out


def _enc_request(m: GoalRequest) -> bytes:
    hints = json.dumps([h.to_json() for h in m.hints], separators=(",", ":")) if m.hints else ""
    return _pack_strings(m.goal_id, m.action, m.client, hints, *m.args)


def _dec_request(data: bytes, offset: int) -> GoalRequest:
    fields_ = _unpack_strings(data, offset)
    if len(fields_) < 4:
        raise MessageError("unreadable message header: a goal request needs id, action, client and hints")
    goal_id, action, client, hints, *args = fields_
    try:
        parsed = tuple(Hint.from_json(h) for h in json.loads(hints)) if hints else ()
    except (ValueError, KeyError, TypeError) as exc:
        raise MessageError(f"unreadable goal hints: {exc}") from exc
    return GoalRequest(goal_id, action, tuple(args), client, parsed)


def _enc_reply(m: GoalReply) -> bytes:
    return (b"\x01" if m.accepted else b"\x00") + _pack_strings(m.goal_id, m.reason, m.server)


def _dec_reply(data: bytes, offset: int) -> GoalReply:
    accepted = data[offset]
    goal_id, reason, server = _unpack_strings(data, offset + 1)
    return GoalReply(goal_id, accepted == 1, reason, server)


def _enc_cancel(m: CancelRequest) -> bytes:
    return _pack_strings(m.goal_id)


def _dec_cancel(data: bytes, offset: int) -> CancelRequest:
    (goal_id,) = _unpack_strings(data, offset)
    return CancelRequest(goal_id)


_STATUS_HEAD = struct.Struct("<Bd")  # flags, feedback progress
_HAS_FEEDBACK, _HAS_RESULT, _SUCCESS = 1, 2, 4


def _enc_status(m: GoalStatus) -> bytes:
    flags, progress, text, message, data = 0, 0.0, "", "", ""
    if m.feedback is not None:
        flags |= _HAS_FEEDBACK
        progress, text = float(m.feedback.progress), m.feedback.text
    if m.result is not None:
        flags |= _HAS_RESULT | (_SUCCESS if m.result.success else 0)
        message = m.result.message
        if m.result.data:
            value = m.result.data if isinstance(m.result.data, dict) else {"value": m.result.data}
            data = json.dumps(value, separators=(",", ":"), default=_json_default)
    return _STATUS_HEAD.pack(flags, progress) + _pack_strings(
        m.goal_id, m.state.value, m.server, text, message, data)


def _dec_status(data: bytes, offset: int) -> GoalStatus:
    flags, progress = _STATUS_HEAD.unpack_from(data, offset)
    goal_id, state, server, text, message, blob = _unpack_strings(data, offset + _STATUS_HEAD.size)
    result = None
    if flags & _HAS_RESULT:
        payload = json.loads(blob) if blob else {}
        if not isinstance(payload, dict):
            raise MessageError("malformed goal_status message: result data is not an object")
        result = SkillResult(bool(flags & _SUCCESS), message, payload)
    return GoalStatus(
        goal_id=goal_id,
        state=GoalState(state),
        feedback=Feedback(progress, text) if flags & _HAS_FEEDBACK else None,
        result=result,
        server=server,
    )


# -- the kind table ------------------------------------------------------------------------------

#: kind name -> the u8 that names it on the wire (never reuse a code; add new ones at the end)
KIND_CODES = {
    "goal_request": 1, "goal_reply": 2, "goal_status": 3, "cancel": 4,
    "move_view": 7, "move_view_reply": 8, "error": 9,
    # schema 4: the robot interfaces and the world-side VLM (5, 6, 10, 11 were schema 3's
    # observe/survey/observation/scene_snapshot: retired, never reused)
    "capture": 12, "frame": 13, "view": 14, "state_request": 15, "robot_state": 16, "map_request": 17,
    "site_map": 18, "vlm_request": 19, "answer": 20,
    # schema 5: a simulated world's action hook, the robot's drivers (vap_bt.transport.drivers)
    "action_event": 21, "action_ack": 22, "driver_call": 23, "driver_reply": 24,
    # added in schema 5 (new kinds only, nothing changed): a simulated world's oracle for the report
    "oracle_query": 25, "oracle_reply": 26,
}

Encoder = Callable[[Any], bytes]
Decoder = Callable[[bytes, int], Any]

# kinds with a binary header: (class, encoder, decoder)
_BINARY: dict[str, tuple[type, Encoder, Decoder]] = {
    "goal_request": (GoalRequest, _enc_request, _dec_request),
    "goal_reply": (GoalReply, _enc_reply, _dec_reply),
    "goal_status": (GoalStatus, _enc_status, _dec_status),
    "cancel": (CancelRequest, _enc_cancel, _dec_cancel),
}
# kinds with a JSON header: (class, packer, unpacker)
_JSON: dict[str, tuple[type, Packer, Unpacker]] = {
    "move_view": (MoveViewRequest, _pack_move, _unpack_move),
    "move_view_reply": (MoveViewReply, _pack_flat, _flat_unpacker(MoveViewReply)),
    "error": (ErrorReply, _pack_flat, _flat_unpacker(ErrorReply)),
    "capture": (CaptureRequest, _pack_capture, _unpack_capture),
    "frame": (Frame, _pack_frame, _unpack_frame),
    "view": (ViewRequest, _pack_view, _unpack_view),
    "state_request": (StateRequest, _pack_flat, _flat_unpacker(StateRequest)),
    "robot_state": (RobotState, _pack_flat, _unpack_state),
    "map_request": (MapRequest, _pack_flat, _flat_unpacker(MapRequest)),
    "site_map": (SiteMap, _pack_map, _unpack_map),
    "vlm_request": (VlmRequest, _pack_vlm, _unpack_vlm),
    "answer": (Answer, _pack_flat, _flat_unpacker(Answer)),
    "action_event": (ActionEvent, _pack_flat, _flat_unpacker(ActionEvent)),
    "action_ack": (ActionAck, _pack_flat, _flat_unpacker(ActionAck)),
    "driver_call": (DriverCall, _pack_driver, _driver_unpacker(DriverCall)),
    "driver_reply": (DriverReply, _pack_driver, _driver_unpacker(DriverReply)),
    "oracle_query": (OracleQuery, _pack_oracle, _unpack_oracle),
    "oracle_reply": (OracleReply, _pack_flat, _flat_unpacker(OracleReply)),
}
_KIND_OF = {cls: kind for kind, (cls, _, _) in [*_BINARY.items(), *_JSON.items()]}
# class -> its frame prefix and encoder (binary kinds) or packer (JSON kinds)
_ENCODERS: dict[type, tuple[bytes, bool, Callable[[Any], Any]]] = {
    cls: (_PREFIX.pack(MAGIC, SCHEMA, KIND_CODES[kind]), kind in _BINARY,
          (_BINARY[kind] if kind in _BINARY else _JSON[kind])[1])
    for cls, kind in _KIND_OF.items()
}
# code -> (kind name, class, binary decoder or None, JSON unpacker or None)
_DECODERS: dict[int, tuple[str, type, Decoder | None, Unpacker | None]] = {
    KIND_CODES[kind]: (kind, cls, _BINARY[kind][2] if kind in _BINARY else None,
                       _JSON[kind][2] if kind in _JSON else None)
    for cls, kind in _KIND_OF.items()
}


def encode(msg: Any) -> bytes:
    """One frame for ``msg`` (any message class above, a Frame, RobotState, SiteMap or Answer)."""
    codec = _ENCODERS.get(type(msg))
    if codec is None:
        raise TypeError(f"{type(msg).__name__} is not a transport message")
    prefix, binary, enc = codec
    if binary:
        return prefix + enc(msg)
    body, arrays = enc(msg)
    header = {**body, "arrays": [[n, a.dtype.str, list(a.shape)] for n, a in arrays.items()]}
    head = json.dumps(header, separators=(",", ":"), default=_json_default).encode()
    return b"".join([prefix, _U32.pack(len(head)), head, *(a.tobytes() for a in arrays.values())])


def decode(data: bytes | bytearray | memoryview, expect: type[T]) -> T:
    """The message in ``data``, which must be of type ``expect``."""
    if type(data) is not bytes:
        data = bytes(data)
    if len(data) < _PREFIX.size or not data.startswith(MAGIC):
        raise MessageError("not a vap_bt message (bad magic)")
    if data[8] == 0x7B:  # "{": a schema-1 frame
        _legacy_schema(data)  # raises
    _, schema, code = _PREFIX.unpack_from(data)
    if schema != SCHEMA:
        raise _mismatch(schema)
    codec = _DECODERS.get(code)
    if codec is None:
        raise MessageError(f"unknown message kind {code!r}")
    kind, cls, binary, unpack = codec
    if cls is not expect:
        raise MessageError(f"expected a {_KIND_OF[expect]} message, got {kind}")
    try:
        if binary is not None:
            return binary(data, _PREFIX.size)
        header, arrays = _read_json(data, _PREFIX.size)
        return unpack(header, arrays)  # type: ignore[misc]
    except struct.error:
        raise MessageError(f"unreadable message header: {kind} message is truncated") from None
    except UnicodeDecodeError as exc:
        raise MessageError(f"unreadable message header: {exc}") from None
    except (KeyError, TypeError, ValueError, IndexError) as exc:
        if isinstance(exc, MessageError):
            raise
        raise MessageError(f"malformed {kind} message: {type(exc).__name__}: {exc}") from None


def _mismatch(schema: object) -> SchemaMismatch:
    return SchemaMismatch(
        f"peer speaks message schema {schema!r}, this side speaks {SCHEMA}: "
        "run the same vap_bt version on both ends"
    )


def _legacy_schema(data: bytes) -> None:
    """A schema-1 frame (JSON header right after a u32 length): say which schema it is."""
    _, n = _LEGACY_PREFIX.unpack_from(data)
    try:
        header = json.loads(data[_LEGACY_PREFIX.size:_LEGACY_PREFIX.size + n])
    except ValueError as exc:
        raise MessageError(f"unreadable message header: {exc}") from None
    raise _mismatch(header.get("schema") if isinstance(header, dict) else None)


def _read_json(data: bytes, offset: int) -> tuple[dict[str, Any], Arrays]:
    (n,) = _U32.unpack_from(data, offset)
    offset += _U32.size
    if offset + n > len(data):
        raise MessageError("unreadable message header: truncated")
    try:
        header = json.loads(data[offset:offset + n])
    except ValueError as exc:
        raise MessageError(f"unreadable message header: {exc}") from None
    if not isinstance(header, dict):
        raise MessageError("message header is not an object")
    return header, _read_arrays(data, offset + n, header.pop("arrays", []))


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


def _json_default(obj: Any) -> Any:
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, (set, frozenset)):
        return sorted(obj, key=str)
    return str(obj)
