"""The wire schema: every message between the executive and the skill servers, versioned.

Each message is one *frame*::

    b"VAPB" | u32 schema | u8 kind | msgpack body                          (most kinds)
    b"VAPB" | u32 schema | u8 kind | u32 body length | msgpack body | arrays   (frame, driver_*)

``schema`` is :data:`SCHEMA`, bumped on any incompatible change; ``kind`` says which message
follows (:data:`KIND_CODES`, all below 123 so that byte 8 is never ``{``, see below). All
integers are little-endian. The prefix is read before the body, so a peer speaking another
schema gets a :class:`SchemaMismatch` naming both versions, never garbage, and a frame of the
wrong kind is refused unread.

The body is MessagePack, written and read by msgspec against the message's type (the type *is*
the schema; msgspec checks every field on the way in). The messages defined here are msgspec
Structs sent as arrays (fields by position, no names on the wire: goal traffic costs a few
microseconds each way); the robot's and the VLM's own dataclasses (:class:`~vap_bt.robot.frame.Frame`,
:class:`~vap_bt.robot.state.RobotState`, :class:`~vap_bt.robot.site_map.SiteMap`,
:class:`~vap_bt.perception.vlm.Answer`, the atoms and hints inside messages) travel as maps of
their fields. Numeric arrays never go element by element, nor through msgpack: in the body a
frame's images and camera pose and a driver call's arrays are msgpack extensions (code
:data:`ARRAY_EXT`: ``u64 offset | u8 len | dtype | u8 ndim | u32 shape...``) and their raw bytes
follow the body, copied once on each side, so a 640x480 RGB-D frame costs its pixels plus a few
hundred bytes. Images are normalised on the way out: rgb ``uint8 (H, W, 3)``, depth
``float32 (H, W)`` metres, instance masks ``int32 (H, W)``, the camera pose ``float64 (4, 4)``.

Plain values (``SkillResult.data``, driver and oracle values, a frame's ``extra``) must be
JSON-friendly: numpy values become numbers and lists, and anything else is sent as its ``str``,
so that a skill's odd return value never breaks the transport. A result whose data is not a dict
is sent as ``{"value": data}``.

Schema history: 1 — ``b"VAPB" | u32 length | JSON header (with "schema" and "kind") | arrays``
for every kind; 2, 3 — a hand-written binary header for goal traffic and a JSON header for the
rest; 4 — the robot interfaces (frames with detections, state, map, viewpoints) and the VLM
service; 5 — goal hints, furniture models in the site map, the robot's drivers, a simulated
world's action hook and oracle; 6 — the msgpack body above, same messages. A schema-1 frame is
still recognised (its byte 8, the start of its JSON header, is ``{``), so an old peer gets a
:class:`SchemaMismatch` naming both versions, not garbage.

A frame from a peer speaking another schema raises :class:`SchemaMismatch`, which says both
versions; anything else undecodable (truncated, garbage, a field of the wrong type) raises
:class:`MessageError` in one line. Neither ever shows a traceback to the user: servers answer
with an error reply, clients turn it into a rejected goal.
"""

from __future__ import annotations

import dataclasses
import json
import math
import struct
import threading
from typing import Any, Callable, TypeVar

import msgspec
import numpy as np

from vap_bt.domain.atoms import Atom
from vap_bt.outcome import Outcome
from vap_bt.perception.vlm import Answer, Query
from vap_bt.robot.camera import Aim, Viewpoint
from vap_bt.robot.frame import Frame
from vap_bt.robot.site_map import SiteMap
from vap_bt.robot.state import RobotState
from vap_bt.skill import Feedback, GoalState, Hint, SkillResult

SCHEMA = 6
MAGIC = b"VAPB"
#: the msgpack extension code of a numpy array
ARRAY_EXT = 1
_PREFIX = struct.Struct("<4sIB")  # magic, schema, kind
_LEGACY_PREFIX = struct.Struct("<4sI")  # schema 1: magic, JSON header length

T = TypeVar("T")


class MessageError(ValueError):
    """A frame that is not a valid message of the expected kind."""


class SchemaMismatch(MessageError):
    """The peer speaks another schema version."""


# -- messages ------------------------------------------------------------------------------------


class _Message(msgspec.Struct, frozen=True, array_like=True):
    """A message of this module: immutable, sent as an array of its fields in order."""


class GoalRequest(_Message):
    """Start ``action(args)``; the client picks ``goal_id`` so it can listen before asking."""

    goal_id: str
    action: str
    args: tuple[str, ...]
    client: str = ""
    hints: tuple[Hint, ...] = ()


class GoalReply(_Message):
    """The server's answer to a GoalRequest: accepted, or rejected with a reason."""

    goal_id: str
    accepted: bool
    reason: str = ""
    server: str = ""


class GoalStatus(_Message):
    """Published on a goal's status key: feedback while ACTIVE, then once with the result."""

    goal_id: str
    state: GoalState
    feedback: Feedback | None = None
    result: SkillResult | None = None
    server: str = ""


class CancelRequest(_Message):
    """Cancel the goal ``goal_id``."""

    goal_id: str


class CaptureRequest(_Message):
    """Aim the camera (None: as it is) and take a frame."""

    aim: Aim | None = None


class ViewRequest(_Message):
    """Go to a viewpoint of an exploration sweep."""

    view: Viewpoint


class MoveViewRequest(_Message):
    """Move the viewpoint ``direction`` relative to ``aim``."""

    aim: Aim
    direction: str


class MoveViewReply(_Message):
    """Whether the moved viewpoint was reachable."""

    reachable: bool


class StateRequest(_Message):
    """Ask for the robot's state (proprioception and localization)."""


class MapRequest(_Message):
    """Ask for the site map."""


class VlmRequest(_Message):
    """Ask the world-side VLM ``query`` about a frame that world's camera took; ``identified``
    is the executive's association of names to the frame's detections (which instance in the
    picture the question's names mean: a set-of-marks prompt's marks)."""

    query: Query
    frame_id: str
    identified: dict[str, int] = msgspec.field(default_factory=dict)


class DriverCall(_Message):
    """A call on a robot's drivers (:mod:`vap_bt.transport.drivers`): ``call`` names it
    (``arm.follow``, ``base.pose``, ...), ``client`` the caller; plain values and numeric arrays."""

    call: str
    client: str = ""
    values: dict[str, Any] = msgspec.field(default_factory=dict)
    arrays: dict[str, np.ndarray] = msgspec.field(default_factory=dict)


class DriverReply(_Message):
    """A driver's answer: plain values and numeric arrays."""

    values: dict[str, Any] = msgspec.field(default_factory=dict)
    arrays: dict[str, np.ndarray] = msgspec.field(default_factory=dict)


class ActionEvent(_Message):
    """Sim only: a goal for ``action(args)`` begins or ends (``phase``), for Table II injection."""

    phase: str  # "begin" | "end"
    action: str
    args: tuple[str, ...] = ()


class OracleQuery(_Message):
    """Sim only, for the runner's report (:mod:`vap_bt.transport.world_services`): ask a simulated
    world ``verb`` (``holds``, ``injected``, ``info``, ``site_map``, ``reset``) about ``atoms``,
    or reset it to ``seed``."""

    verb: str
    atoms: tuple[Atom, ...] = ()
    seed: int | None = None


class OracleReply(_Message):
    """A simulated world's answer to an OracleQuery: plain JSON values."""

    values: dict[str, Any] = msgspec.field(default_factory=dict)


class ErrorReply(_Message):
    """A server could not answer (its world raised); ``reason`` says why."""

    reason: str


# -- numeric arrays: described in the body, their bytes after it ---------------------------------

_IMAGE_DTYPES = {"rgb": np.uint8, "depth": np.float32, "masks": np.int32, "camera_pose": np.float64}
_ARRAY_HEAD = struct.Struct("<QB")  # offset in the frame's tail, length of the dtype's name


class _Tail:
    """The arrays of one frame being written, in the order their bytes follow the body."""

    def __init__(self) -> None:
        self.arrays: list[np.ndarray] = []
        self.size = 0

    def add(self, a: Any, dtype: Any = None) -> msgspec.msgpack.Ext:
        """Queue ``a``'s bytes; what the body says of it (an :data:`ARRAY_EXT` extension)."""
        a = np.ascontiguousarray(a, dtype=dtype)
        kind = a.dtype.str.encode()
        head = _ARRAY_HEAD.pack(self.size, len(kind)) + kind + struct.pack(f"<B{a.ndim}I", a.ndim, *a.shape)
        self.arrays.append(a)
        self.size += a.nbytes
        return msgspec.msgpack.Ext(ARRAY_EXT, head)


class _Reading(threading.local):
    """Per thread: the bytes after the body of the frame being decoded (its arrays)."""

    tail: bytes | memoryview = b""


_reading = _Reading()


def _array_in(ext: msgspec.msgpack.Ext) -> np.ndarray:
    """The array an :data:`ARRAY_EXT` extension describes, a copy of its bytes in the tail."""
    data, tail = ext.data, _reading.tail
    try:
        offset, n = _ARRAY_HEAD.unpack_from(data)
        dtype = np.dtype(data[_ARRAY_HEAD.size:_ARRAY_HEAD.size + n].decode())
        (ndim,) = struct.unpack_from("<B", data, _ARRAY_HEAD.size + n)
        shape = struct.unpack_from(f"<{ndim}I", data, _ARRAY_HEAD.size + n + 1)
    except (TypeError, ValueError, UnicodeDecodeError, struct.error) as exc:
        raise ValueError(f"bad array description: {exc}") from None
    if dtype.hasobject:
        raise ValueError(f"not a numeric array: dtype {dtype}")
    count = math.prod(shape)  # exact: a forged shape cannot wrap around
    if offset + count * dtype.itemsize > len(tail):
        raise ValueError(f"array is truncated ({count * dtype.itemsize} bytes at {offset}, "
                         f"the frame has {len(tail)})")
    return np.frombuffer(tail, dtype, count, offset).reshape(shape).copy()


def _plain(obj: Any) -> Any:
    """A plain value for what msgspec cannot send as it is: numpy values, or their ``str``."""
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    return str(obj)


def _typed_in(kind: type, obj: Any) -> Any:
    """msgspec's hook for the fields it has no decoder of its own for: numpy arrays."""
    if kind is np.ndarray and isinstance(obj, msgspec.msgpack.Ext) and obj.code == ARRAY_EXT:
        return _array_in(obj)
    raise TypeError(f"expected a numeric array, got {type(obj).__name__}")


# -- wire forms: the arrays of a message described, a result's data made plain ------------------


def _frame_out(f: Frame, tail: _Tail) -> Frame:
    return dataclasses.replace(f, **{name: tail.add(getattr(f, name), dtype)
                                     for name, dtype in _IMAGE_DTYPES.items() if getattr(f, name) is not None})


def _driver_out(m: DriverCall | DriverReply, tail: _Tail) -> Any:
    return msgspec.structs.replace(m, arrays={k: tail.add(v) for k, v in m.arrays.items()})


def _status_out(m: GoalStatus) -> GoalStatus:
    """``m`` with its result data a dict of plain values under string keys."""
    data = m.result.data if m.result is not None else {}
    if isinstance(data, dict) and all(type(k) is str for k in data):
        return m
    plain = {str(k): v for k, v in data.items()} if isinstance(data, dict) else {"value": data}
    return msgspec.structs.replace(m, result=dataclasses.replace(m.result, data=plain))


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
    "oracle_query": 25, "oracle_reply": 26,
}

_KIND_OF: dict[type, str] = {
    GoalRequest: "goal_request", GoalReply: "goal_reply", GoalStatus: "goal_status", CancelRequest: "cancel",
    MoveViewRequest: "move_view", MoveViewReply: "move_view_reply", ErrorReply: "error",
    CaptureRequest: "capture", Frame: "frame", ViewRequest: "view", StateRequest: "state_request",
    RobotState: "robot_state", MapRequest: "map_request", SiteMap: "site_map", VlmRequest: "vlm_request",
    Answer: "answer", ActionEvent: "action_event", Outcome: "action_ack", DriverCall: "driver_call",
    DriverReply: "driver_reply", OracleQuery: "oracle_query", OracleReply: "oracle_reply",
}
#: the kinds with numeric arrays, and their wire form (the arrays described, their bytes in the tail)
_ARRAYS: dict[type, Callable[[Any, _Tail], Any]] = {
    Frame: _frame_out, DriverCall: _driver_out, DriverReply: _driver_out,
}
_U32 = struct.Struct("<I")
_ENCODER = msgspec.msgpack.Encoder(enc_hook=_plain)
_PREFIXES = {cls: _PREFIX.pack(MAGIC, SCHEMA, KIND_CODES[kind]) for cls, kind in _KIND_OF.items()}
# kind code -> (kind name, class, its decoder)
_DECODERS = {KIND_CODES[kind]: (kind, cls, msgspec.msgpack.Decoder(cls, dec_hook=_typed_in))
             for cls, kind in _KIND_OF.items()}


def encode(msg: Any) -> bytes:
    """One frame for ``msg`` (any message class above, a Frame, RobotState, SiteMap or Answer)."""
    cls = type(msg)
    prefix = _PREFIXES.get(cls)
    if prefix is None:
        raise TypeError(f"{cls.__name__} is not a transport message")
    if cls is GoalStatus:
        msg = _status_out(msg)
    arrays = _ARRAYS.get(cls)
    if arrays is None:
        return prefix + _ENCODER.encode(msg)
    tail = _Tail()
    body = _ENCODER.encode(arrays(msg, tail))
    return b"".join([prefix, _U32.pack(len(body)), body, *tail.arrays])  # contiguous arrays are buffers


def decode(data: bytes | bytearray | memoryview, expect: type[T]) -> T:
    """The message in ``data``, which must be of type ``expect``."""
    if len(data) < _PREFIX.size:
        raise MessageError("not a vap_bt message (bad magic)")
    magic, schema, code = _PREFIX.unpack_from(data)
    if magic != MAGIC:
        raise MessageError("not a vap_bt message (bad magic)")
    if code == 0x7B:  # "{": a schema-1 frame
        _legacy_schema(data)  # raises
    if schema != SCHEMA:
        raise _mismatch(schema)
    codec = _DECODERS.get(code)
    if codec is None:
        raise MessageError(f"unknown message kind {code!r}")
    kind, cls, decoder = codec
    if cls is not expect:
        raise MessageError(f"expected a {_KIND_OF[expect]} message, got {kind}")
    try:
        if cls not in _ARRAYS:
            return decoder.decode(data[_PREFIX.size:])  # small: a copy costs less than a view
        view = memoryview(data)[_PREFIX.size:]
        (n,) = _U32.unpack_from(view)
        _reading.tail = view[_U32.size + n:]
        try:
            return decoder.decode(view[_U32.size:_U32.size + n])
        finally:
            _reading.tail = b""
    except msgspec.ValidationError as exc:
        raise MessageError(f"malformed {kind} message: {exc}") from None
    except (msgspec.DecodeError, struct.error) as exc:
        raise MessageError(f"unreadable {kind} message: {exc}") from None


def _mismatch(schema: object) -> SchemaMismatch:
    return SchemaMismatch(
        f"peer speaks message schema {schema!r}, this side speaks {SCHEMA}: "
        "run the same vap_bt version on both ends"
    )


def _legacy_schema(data: bytes | bytearray | memoryview) -> None:
    """A schema-1 frame (JSON header right after a u32 length): say which schema it is."""
    _, n = _LEGACY_PREFIX.unpack_from(data)
    try:
        header = json.loads(bytes(data[_LEGACY_PREFIX.size:_LEGACY_PREFIX.size + n]))
    except ValueError as exc:
        raise MessageError(f"unreadable message header: {exc}") from None
    raise _mismatch(header.get("schema") if isinstance(header, dict) else None)
