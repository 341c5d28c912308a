"""The wire schema: round trips, compact images, and one clear error for every bad frame."""

from __future__ import annotations

import json
import struct

import msgspec
import numpy as np
import pytest

from vap_bt.domain.atoms import Atom
from vap_bt.skill import Feedback, GoalState, Hint, SkillResult
from vap_bt.transport.config import TransportSettings, build_config, settings_from_args
from vap_bt.outcome import Outcome
from vap_bt.transport.messages import (ARRAY_EXT, KIND_CODES, SCHEMA, ActionEvent, CancelRequest,
                                       GoalReply, GoalRequest, GoalStatus, MessageError, SchemaMismatch, decode, encode)
from vap_bt.perception.vlm import Answer, Query
from vap_bt.robot.camera import Aim, Viewpoint
from vap_bt.robot.frame import Detection, Frame
from vap_bt.robot.site_map import Articulation, Cavity, DoorInfo, FurnitureInfo, RoomInfo, SiteMap
from vap_bt.robot.state import RobotState
from vap_bt.transport.messages import CaptureRequest, DriverCall, DriverReply, ViewRequest, VlmRequest


def test_messages_round_trip():
    status = GoalStatus("g-1", GoalState.SUCCEEDED, Feedback(1.0, "done"),
                        SkillResult(True, "ok", {"n": np.int64(3), "v": np.arange(2.0)}), "arm")
    back = decode(encode(status), GoalStatus)
    assert back.result.data == {"n": 3, "v": [0.0, 1.0]} and back.state is GoalState.SUCCEEDED
    # a skill that did not see its thing where belief put it says which, through the wire
    missed = GoalStatus("g-1", GoalState.SUCCEEDED, None,
                        SkillResult.of(Outcome(False, "cup is not where it was believed to be", missing="cup"), "grasp"))
    assert decode(encode(missed), GoalStatus).result.missing == "cup"
    assert SkillResult.of(Outcome(False, ""), "grasp(cup)") == SkillResult(False, "grasp(cup)")
    assert SkillResult(False, "", {"missing": 3}).missing is None  # a skill's odd data names nothing
    # and one that found a precondition false where it looked says which
    shut = GoalStatus("g-1", GoalState.SUCCEEDED, None,
                      SkillResult.of(Outcome(False, "fridge is shut", unmet="open(fridge)"), "takeout"))
    back = decode(encode(shut), GoalStatus).result
    assert back.unmet == "open(fridge)" and back.missing is None
    req = GoalRequest("g-2", "grasp", ("cup", "table"), "c")
    assert decode(encode(req), GoalRequest) == req
    # the executive's hints ride with the goal: where belief puts each object, on or in what
    hinted = GoalRequest("g-2", "grasp", ("cup", "table"), "c",
                         (Hint("cup", (1.0, 2.5, 0.78), on="table"), Hint("table")))
    assert decode(encode(hinted), GoalRequest) == hinted
    # goal traffic has a binary header: non-ASCII text, empty strings and feedback-only status
    for msg in (GoalReply("g-3", False, "busy: tête à tête ✓", "arm"), GoalRequest("g-4", "say", ("", "ü"), ""),
                CancelRequest("g-5"), GoalStatus("g-6", GoalState.ACTIVE, Feedback(0.25, "¼ done"), None, "arm")):
        assert decode(encode(msg), type(msg)) == msg
    leaf = Articulation(False, (4.0, 1.4, 0.0), (0.0, 0.0, 1.0), (4.06, 2.2, 0.95), (1.0, 0.0, 0.0), (0.0, 0.0, 1.0),
                        -1.57, -1.62, 1.62, (4.0, 2.0, 0.53), (0.02, 0.6, 0.5), other_side=0.125)
    drawer = Articulation(True, (1.0, 2.75, 0.68), (0.0, -1.0, 0.0), (1.0, 2.68, 0.76), (0.0, -1.0, 0.0),
                          (-1.0, 0.0, 0.0), 0.34, -0.02, 0.36, (1.0, 3.0, 0.76), (0.3, 0.27, 0.09))
    site = SiteMap((RoomInfo("kitchen", "floor_kitchen", (0.0, 0.0, 4.0, 4.0)),),
                   (DoorInfo("d", ("kitchen", "hall"), (4.0, 2.0, 0.0), 1.2, leaf),),
                   (FurnitureInfo("t", "table", "surface", "kitchen", (1.0, 3.0, 3.14), (1.1, 0.7)),
                    FurnitureInfo("dr", "drawer", "container", "kitchen", (1.0, 3.0, -1.57), (0.6, 0.5), 0.9,
                                  Cavity((0.7, 0.86), 0.02, "top"), drawer),
                    FurnitureInfo("mw", "microwave", "appliance", "kitchen", (2.0, 3.0, -1.57), (0.55, 0.42), 1.12,
                                  Cavity((0.85, 1.08), 0.03, "front"), switch=(2.2, 2.76, 0.89)),
                    FurnitureInfo("s", "sink", "sink", "kitchen", (3.0, 3.0, -1.57), (0.8, 0.6), 0.9, tap=(3.0, 3.1, 1.12))),
                   frozenset({Atom("clear", ("t",))}))
    state = RobotState(1.5, "kitchen", (1.0, 2.0, 0.3), (0.1,) * 6, (1.0,) * 7, 0.08, False)
    view = ViewRequest(Viewpoint("kitchen", Aim(("t",), (1.0, 3.0, 0.7)), (1.0, 1.5, 1.57), "t from the front"))
    ask = VlmRequest(Query("Is the cup on the t?", about=(Atom("on", ("cup", "t")),), objects=("cup", "t")), "f-1", {"cup": 0})
    for msg in (site, state, view, ask, CaptureRequest(None), CaptureRequest(Aim(("cup",))), Answer("yes", True),
                ActionEvent("begin", "grasp", ("cup", "table")), ActionEvent("end", "grasp"), Outcome(True),
                Outcome(False, "no action open")):
        assert decode(encode(msg), type(msg)) == msg


def test_images_travel_as_raw_bytes_not_json():
    rgb = np.zeros((480, 640, 3), np.uint8)
    obs = Frame("f", 0.0, (Detection("cup", 10, 3, relations=(Atom("on", ("", "t")),), name="cup"),), rgb=rgb,
                depth=np.ones((480, 640), np.float64), masks=np.zeros((480, 640), np.int64), camera_pose=np.eye(4))
    frame = encode(obs)
    assert len(frame) < rgb.nbytes + 480 * 640 * 8 + 128 + 1024  # pixels plus a small header
    back = decode(frame, Frame)
    assert back.depth.dtype == np.float32 and back.rgb.shape == (480, 640, 3) and back.masks.dtype == np.int32
    assert back.detections == obs.detections and np.array_equal(back.camera_pose, np.eye(4))
    # a world without camera poses names the stand instead (the same while the robot has not moved)
    assert decode(encode(Frame("g", 1.0, stand="view-3")), Frame).stand == "view-3"


def _body(kind: str, value, tail: bytes | None = None) -> bytes:
    """A frame of ``kind`` whose msgpack body is ``value``, whatever it holds; a kind with arrays
    (``tail`` given) has the body's length before it and the arrays' bytes after it."""
    body = msgspec.msgpack.encode(value)
    prefix = struct.pack("<4sIB", b"VAPB", SCHEMA, KIND_CODES[kind])
    return prefix + body if tail is None else prefix + struct.pack("<I", len(body)) + body + tail


def _parts(frame: bytes) -> tuple[dict, bytes]:
    """The body and the tail of a frame with arrays."""
    (n,) = struct.unpack_from("<I", frame, 9)
    return msgspec.msgpack.decode(frame[13:13 + n]), frame[13 + n:]


@pytest.mark.parametrize("frame, message", [
    (b"", "not a vap_bt message \\(bad magic\\)"),
    (b"VAPB\x05\x00\x00\x00{nope", "unreadable message header"),  # a schema-1 frame, cut short
    (encode(GoalReply("g", True))[:-3], "unreadable goal_reply message: Input data was truncated"),
    (encode(GoalReply("g", True)) + b"\x00", "unreadable goal_reply message: .*trailing characters"),
    (encode(GoalReply("g", True))[:9] + b"\xc1\xc1", "unreadable goal_reply message: MessagePack data is malformed"),
    (_body("goal_reply", ["g", "yes"]), r"malformed goal_reply message: Expected `bool`, got `str` - at `\$\[1\]`"),
    (_body("goal_reply", []), "malformed goal_reply message: Expected `array` of at least length 2"),
    (_body("frame", {"frame_id": "f", "stamp": 0.0, "rgb": [1, 2]}, b""),
     r"malformed frame message: expected a numeric array, got list - at `\$.rgb`"),
])
def test_bad_frames_are_one_message_error(frame, message):
    with pytest.raises(MessageError, match=message) as err:
        decode(frame, Frame if message.startswith("malformed frame") else GoalReply)
    assert "\n" not in str(err.value) and err.value.__cause__ is None  # one line, no chained traceback


def test_wrong_kind_truncated_arrays_and_foreign_schema():
    with pytest.raises(MessageError, match="expected a goal_reply message, got goal_request"):
        decode(encode(GoalRequest("g", "a", ())), GoalReply)
    rgb = np.arange(12, dtype=np.uint8).reshape(2, 2, 3)
    body, tail = _parts(encode(Frame("f", 0.0, rgb=rgb)))
    assert body["rgb"].code == ARRAY_EXT and tail == rgb.tobytes()  # described in the body, raw after it
    with pytest.raises(MessageError, match=r"malformed frame message: array is truncated \(12 bytes at 0, "
                                           r"the frame has 11\) - at `\$.rgb`"):
        decode(_body("frame", body, tail[:-1]), Frame)
    forged = struct.pack("<QB", 0, 3) + b"|u1" + struct.pack("<B4I", 4, *(2**32 - 1,) * 4)  # ~3e38 bytes
    with pytest.raises(MessageError, match=r"array is truncated \(340282366\d+ bytes at 0, the frame has 12\)"):
        decode(_body("frame", {**body, "rgb": msgspec.msgpack.Ext(ARRAY_EXT, forged)}, tail), Frame)
    objects = struct.pack("<QB", 0, 2) + b"|O" + struct.pack("<BI", 1, 1)  # a pickled object is never read
    with pytest.raises(MessageError, match="not a numeric array: dtype object - at `\\$.rgb`"):
        decode(_body("frame", {**body, "rgb": msgspec.msgpack.Ext(ARRAY_EXT, objects)}, bytes(8)), Frame)
    frame = encode(GoalReply("g", True))
    foreign = frame[:4] + struct.pack("<I", 2) + frame[8:]  # the schema field
    with pytest.raises(SchemaMismatch, match=f"peer speaks message schema 2, this side speaks {SCHEMA}"):
        decode(foreign, GoalReply)
    # a schema-1 peer (JSON header for every kind) is recognised as such
    head = json.dumps({"schema": 1, "kind": "goal_reply", "goal_id": "g", "accepted": True}).encode()
    with pytest.raises(SchemaMismatch, match=f"peer speaks message schema 1, this side speaks {SCHEMA}"):
        decode(b"VAPB" + struct.pack("<I", len(head)) + head, GoalReply)


def test_driver_arrays_round_trip_raw_and_values_stay_plain():
    arrays = {"times": np.linspace(0.0, 1.0, 5), "positions": np.arange(35.0).reshape(5, 7)[:, ::2],
              "none": np.zeros((0, 3), np.float32)}
    call = DriverCall("arm.follow", "c", {"joints": ["a", "b"], "speed": np.float64(0.5)}, arrays)
    back = decode(encode(call), DriverCall)
    assert back.values == {"joints": ["a", "b"], "speed": 0.5} and back.arrays.keys() == arrays.keys()
    for name, a in arrays.items():  # a strided view arrives as its values, dtype and shape kept
        assert back.arrays[name].dtype == a.dtype and np.array_equal(back.arrays[name], a)
        assert back.arrays[name].flags.writeable
    assert decode(encode(DriverReply({"ok": True})), DriverReply) == DriverReply({"ok": True}, {})


def test_odd_result_data_travels_as_plain_values():
    """A skill's result data that is not a dict of plain values still arrives, made plain."""
    class Odd:
        def __str__(self):
            return "odd"

    for data, plain in (([1, 2], {"value": [1, 2]}),
                        ({3: Odd(), "a": {"b": np.float32(0.5)}}, {"3": "odd", "a": {"b": 0.5}}),
                        ({"m": np.eye(2, dtype=np.int32)}, {"m": [[1, 0], [0, 1]]})):
        status = GoalStatus("g", GoalState.SUCCEEDED, None, SkillResult(True, "", data))
        assert decode(encode(status), GoalStatus).result.data == plain


def test_default_configuration_is_loopback_only():
    import argparse

    from vap_bt.app.arguments import add_settings
    from vap_bt.settings import Zenoh

    p = argparse.ArgumentParser()
    add_settings(p, "serve", Zenoh)
    conf = build_config(settings_from_args(p.parse_args([]), default_listen=True))
    assert json.loads(conf.get_json("listen/endpoints")) == ["tcp/127.0.0.1:7448"]
    assert json.loads(conf.get_json("connect/endpoints")) == []
    assert json.loads(conf.get_json("scouting/multicast/enabled")) is False
    assert json.loads(conf.get_json("transport/link/tx/lease")) == 2000
    client = build_config(TransportSettings(connect=("tcp/127.0.0.1:7448",)))
    assert json.loads(client.get_json("listen/endpoints")) == []


def test_the_executives_waits_are_options_of_run_only_and_must_be_positive(capsys):
    import argparse

    from vap_bt.app.arguments import add_settings
    from vap_bt.settings import Zenoh
    from vap_bt.transport.config import CAMERA_TIMEOUT_S, REJOIN_TIMEOUT_S, part_settings

    run = argparse.ArgumentParser()
    add_settings(run, "run", Zenoh)
    s = part_settings(run.parse_args(["--rejoin-timeout", "2.5", "--camera-timeout", "12"]))
    assert (s.rejoin_timeout, s.camera_timeout) == (2.5, 12.0)
    defaults = part_settings(run.parse_args([]))
    assert (defaults.rejoin_timeout, defaults.camera_timeout) == (REJOIN_TIMEOUT_S, CAMERA_TIMEOUT_S)
    for bad in ("0", "-1", "nan", "inf", "soon"):
        with pytest.raises(SystemExit) as exit_:
            run.parse_args(["--rejoin-timeout", bad])
        assert exit_.value.code == 2
        assert f"argument --rejoin-timeout: {bad!r} is not a number of seconds above 0" in capsys.readouterr().err
    serve = argparse.ArgumentParser()  # a server has no such waits: its settings keep the defaults
    add_settings(serve, "serve", Zenoh)
    assert part_settings(serve.parse_args([])).rejoin_timeout == REJOIN_TIMEOUT_S
