"""Transport benchmark: the wire codec, goal-accept round trip over Zenoh on loopback, BT tick overhead.

    .venv/bin/python tools/bench/transport.py [--goals 1000] [--nodes 100] [--ticks 1000] [--rounds 10]
                                              [--against OLD/messages.py] [--codec-only]

0. **Wire codec.** Encode + decode of one message of each kind (goal traffic, robot state, a site
   map, a 640x480 RGB-D frame, a frame without images, a VLM request, a driver call with a
   trajectory), per message, and each frame's size. ``--against`` names another version of
   ``vap_bt/transport/messages.py`` (e.g. ``git show <commit>:vap_bt/transport/messages.py``
   saved to a file): both codecs then run on the same messages in the same process, alternating
   in ``--rounds`` blocks, and the figure of each is the median over the blocks.

1. **Goal accept round trip.** A skill server runs in its own process (spawned, so the two sides
   do not share a GIL) and hosts a no-op skill; the client sends ``--goals`` goals one after the
   other over TCP on 127.0.0.1 and times ``send_goal`` -> the server's "accepted" reply (what a
   behaviour waits for before it reports RUNNING), and separately send -> final result.
   **Baseline**, in the same run, over the same link and session configuration: the bare Zenoh
   query round trip — a queryable in the server process that answers at once with a few bytes
   (on Zenoh's receiving thread, express, as the skill server does), asked through a querier
   until its reply is in the client's hands — and the ratio of the two. Goals and bare queries
   alternate in ``--rounds`` blocks so that both see the same machine load.
2. **BT tick overhead.** A py_trees parallel of ``--nodes`` ExecuteSkill behaviours, each with a
   goal in flight on that server that does nothing until cancelled ("all skills idle"); the time
   of one tick of the whole tree, i.e. what the executive pays per tick for polling the goals.

Figures are wall-clock on this machine; run it on an otherwise idle machine for stable numbers.
"""

from __future__ import annotations

import argparse
import importlib.util
import multiprocessing
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from vap_bt.skill import Skill, SkillResult  # noqa: E402
from vap_bt.transport.config import TransportSettings, open_session  # noqa: E402

ROBOT = "bench"
BASELINE_KEY = "vapbench/echo"


class Noop(Skill):
    action = "noop"
    robot = ROBOT
    resource = "noop"

    def execute(self, args, ctx):
        return SkillResult(True)


def idle_skill(i: int) -> type[Skill]:
    """A skill on its own resource that holds its goal until cancelled."""

    def execute(self, args, ctx):
        while not ctx.cancelled():
            time.sleep(0.01)
        return SkillResult(False, "cancelled")

    return type(f"Idle{i}", (Skill,), {"action": f"idle{i}", "robot": ROBOT,
                                        "resource": f"slot{i}", "execute": execute})


def serve(endpoint: str, nodes: int, ready) -> None:
    import zenoh

    from vap_bt.transport.server import SkillServer

    session = open_session(TransportSettings(listen=(endpoint,)))
    skills = {"noop": Noop(None)}
    skills.update({f"idle{i}": idle_skill(i)(None) for i in range(nodes)})
    server = SkillServer(session, ROBOT, skills, name="bench").start()
    # the baseline: answer at once, on Zenoh's receiving thread, as the skill server does
    echo = session.declare_queryable(BASELINE_KEY, zenoh.handlers.Callback(
        lambda q: q.reply(q.key_expr, b"accepted", express=True), indirect=False))
    ready.set()
    try:
        while True:
            time.sleep(1)
    finally:
        echo.undeclare()
        server.close()
        session.close()


def percentile(samples: list[float], q: float) -> float:
    ordered = sorted(samples)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def bench_goals(client, n: int) -> tuple[list[float], list[float]]:
    accept, full = [], []
    for _ in range(n):
        t0 = time.perf_counter()
        handle = client.send_goal("noop", ())
        handle.wait_answered(5)
        t1 = time.perf_counter()
        handle.wait(5)
        t2 = time.perf_counter()
        assert handle.state().value == "succeeded", handle.result()
        accept.append(t1 - t0)
        full.append(t2 - t0)
    return accept, full


def bench_bare(querier, n: int) -> list[float]:
    """Bare Zenoh query round trips: ``get`` until the first reply is received."""
    samples = []
    for _ in range(n):
        t0 = time.perf_counter()
        reply = querier.get(payload=b"0123456789abcdef").recv()
        samples.append(time.perf_counter() - t0)
        assert reply.ok is not None
    return samples


def bench_ticks(client, nodes: int, ticks: int) -> list[float] | str:
    try:
        import py_trees

        from vap_bt.bt.context import ExecutionContext
        from vap_bt.bt.execute_skill import ExecuteSkill
        from vap_bt.domain.knowledge import GroundAction
    except ImportError as exc:  # the BT room may not be there yet
        return f"skipped: {exc}"
    ctx = ExecutionContext(graph=None, vlm=None, camera=None, skills=client)
    children = [ExecuteSkill(ctx, GroundAction(f"idle{i}", (), (), frozenset(), frozenset()), i)
                for i in range(nodes)]
    root = py_trees.composites.Parallel(
        "idle", policy=py_trees.common.ParallelPolicy.SuccessOnAll(synchronise=False),
        children=children)
    tree = py_trees.trees.BehaviourTree(root)
    tree.tick()  # first tick sends the goals
    for child in children:
        child.handle.wait_answered(5)
    assert all(c.handle.state().value == "active" for c in children)
    samples = []
    for _ in range(ticks):
        t0 = time.perf_counter()
        tree.tick()
        samples.append(time.perf_counter() - t0)
    root.stop(py_trees.common.Status.INVALID)  # cancels every goal
    return samples


def load_codec(path: str):
    """Another version of the messages module, from a file, beside the current one."""
    spec = importlib.util.spec_from_file_location("wire_against", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def codec_samples(m) -> dict[str, object]:
    """One message of each kind that matters, built with codec module ``m``'s message classes."""
    import numpy as np

    from vap_bt.domain.atoms import Atom
    from vap_bt.perception.vlm import Query
    from vap_bt.robot.camera import Aim
    from vap_bt.robot.frame import Detection, Frame
    from vap_bt.robot.site_map import Articulation, Cavity, DoorInfo, FurnitureInfo, RoomInfo, SiteMap
    from vap_bt.robot.state import RobotState
    from vap_bt.skill import Feedback, GoalState, Hint

    rng = np.random.default_rng(0)
    leaf = Articulation(False, (4.0, 1.4, 0.0), (0.0, 0.0, 1.0), (4.06, 2.2, 0.95), (1.0, 0.0, 0.0), (0.0, 0.0, 1.0),
                        -1.57, -1.62, 1.62, (4.0, 2.0, 0.53), (0.02, 0.6, 0.5), other_side=0.125)
    rooms = tuple(RoomInfo(f"room{i}", f"floor{i}", (4.0 * i, 0.0, 4.0 * i + 4, 4.0)) for i in range(5))
    doors = tuple(DoorInfo(f"door{i}", (f"room{i}", f"room{i + 1}"), (4.0 * i + 4, 2.0, 0.0), 1.2, leaf)
                  for i in range(4))
    furniture = tuple(FurnitureInfo(f"f{i}", "cabinet", "container", f"room{i % 5}", (1.0 * i, 3.0, -1.57), (0.6, 0.5),
                                    0.9, Cavity((0.1, 0.8), 0.02, "front"), leaf) for i in range(25))
    facts = frozenset(Atom("connects", (f"room{i}", f"room{i + 1}", f"door{i}")) for i in range(4))
    dets = tuple(Detection(f"thing{i}", 900, i, 0.9, (Atom("on", ("", f"f{i}")),), name=f"thing{i}") for i in range(10))
    return {
        "goal_request": m.GoalRequest("client-1-42", "grasp", ("cup", "table"), "client-1",
                                      (Hint("cup", (1.0, 2.5, 0.78), on="table", radius=0.05), Hint("table"))),
        "goal_reply": m.GoalReply("client-1-42", True, "", "ur5e"),
        "goal_status (feedback)": m.GoalStatus("client-1-42", GoalState.ACTIVE, Feedback(0.5, "approaching"), None,
                                               "ur5e"),
        "goal_status (result)": m.GoalStatus("client-1-42", GoalState.SUCCEEDED, Feedback(1.0, "done"),
                                             SkillResult(True, "grasped", {"grip": 0.04, "pose": [0.1, 0.2, 0.3]}),
                                             "ur5e"),
        "cancel": m.CancelRequest("client-1-42"),
        "robot_state": RobotState(12.5, "kitchen", (1.0, 2.0, 0.3), (0.1,) * 6, (0.5, 0.1, 0.9, 0.0, 0.0, 0.0, 1.0),
                                  0.08, False),
        "site_map (5 rooms, 25 furniture)": SiteMap(rooms, doors, furniture, facts),
        "frame, symbolic (10 detections)": Frame("f-1", 3.0, dets, aim=("cup",), stand="view-3"),
        "frame, 640x480 RGB-D + masks": Frame(
            "f-2", 3.0, dets, rgb=rng.integers(0, 255, (480, 640, 3), np.uint8),
            depth=rng.random((480, 640), np.float32), masks=rng.integers(-1, 10, (480, 640)).astype(np.int32),
            intrinsics=(554.0, 554.0, 320.0, 240.0), camera_pose=np.eye(4), aim=("cup",)),
        "vlm_request": m.VlmRequest(Query("Is the cup on the table?", about=(Atom("on", ("cup", "table")),),
                                          objects=("cup", "table")), "f-2", {"cup": 0, "table": 3}),
        "capture": m.CaptureRequest(Aim(("cup",), (1.0, 2.5, 0.8))),
        "driver_call (7x200 trajectory)": m.DriverCall(
            "arm.follow", "client-1", {"joints": [f"j{i}" for i in range(7)]},
            {"times": np.linspace(0, 4, 200), "positions": rng.random((200, 7))}),
    }


def bench_codec(codecs: dict[str, object], rounds: int) -> None:
    """Encode and decode time per message and frame sizes, codecs alternating in ``rounds`` blocks.

    Encoding and decoding are timed apart (in a robot they run in two processes): ``n`` encodes,
    then ``n`` decodes of the last frame, ``n`` chosen so that a block of one kind takes ~50 ms."""
    samples = {name: codec_samples(m) for name, m in codecs.items()}
    times: dict[tuple[str, str], list[tuple[float, float]]] = {}
    for _ in range(rounds):
        for name, m in codecs.items():
            for kind, msg in samples[name].items():
                t0 = time.perf_counter()
                data = m.encode(msg)
                assert type(m.decode(data, type(msg))) is type(msg)
                n = max(10, min(2000, int(0.05 / (time.perf_counter() - t0))))
                t0 = time.perf_counter()
                for _ in range(n):
                    data = m.encode(msg)
                t1 = time.perf_counter()
                for _ in range(n):
                    m.decode(data, type(msg))
                times.setdefault((name, kind), []).append(((t1 - t0) / n, (time.perf_counter() - t1) / n))
    names = list(codecs)
    print(f"wire codec, per message: encode + decode = total (median of {rounds} alternating blocks), frame bytes")
    print(f"  {'message':34s}" + "".join(f"{n:>36s}" for n in names) + ("   ratio" if len(names) == 2 else ""))
    for kind in samples[names[0]]:
        cells, totals = [], []
        for name in names:
            enc, dec = (statistics.median(t[i] for t in times[(name, kind)]) * 1e6 for i in (0, 1))
            totals.append(enc + dec)
            size = len(codecs[name].encode(samples[name][kind]))
            cells.append(f"{enc:8.1f} +{dec:8.1f} ={enc + dec:8.1f} us {size:>8d} B")
        ratio = f"   x{totals[1] / totals[0]:.2f}" if len(totals) == 2 else ""
        print(f"  {kind:34s}" + "".join(cells) + ratio)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--goals", type=int, default=1000)
    parser.add_argument("--nodes", type=int, default=100)
    parser.add_argument("--ticks", type=int, default=1000)
    parser.add_argument("--rounds", type=int, default=10,
                        help="blocks in which goals and bare queries alternate (default 10)")
    parser.add_argument("--against", metavar="MESSAGES_PY",
                        help="another version of vap_bt/transport/messages.py to compare the codec with")
    parser.add_argument("--codec-only", action="store_true", help="measure the wire codec only")
    args = parser.parse_args()

    from vap_bt.transport import messages

    codecs = {"current": messages}
    if args.against:
        codecs = {"against": load_codec(args.against), **codecs}
    bench_codec(codecs, args.rounds)
    if args.codec_only:
        return 0

    endpoint = f"tcp/127.0.0.1:{free_port()}"
    spawn = multiprocessing.get_context("spawn")
    ready = spawn.Event()
    server = spawn.Process(target=serve, args=(endpoint, args.nodes, ready), daemon=True)
    server.start()
    try:
        if not ready.wait(60):
            print("server did not start", file=sys.stderr)
            return 1
        from vap_bt.transport.client import ZenohSkillClient

        session = open_session(TransportSettings(connect=(endpoint,)))
        routes = {"noop": ROBOT, **{f"idle{i}": ROBOT for i in range(args.nodes)}}
        client = ZenohSkillClient(session, routes, owns_session=True)
        while not client._alive[ROBOT]:
            time.sleep(0.01)
        import zenoh

        bare_querier = session.declare_querier(
            BASELINE_KEY, consolidation=zenoh.ConsolidationMode.NONE, timeout=5,
            congestion_control=zenoh.CongestionControl.BLOCK, express=True)
        bench_goals(client, 50)  # warm-up: queriers declared, caches hot
        bench_bare(bare_querier, 50)
        accept, full, bare = [], [], []
        rounds = max(1, min(args.rounds, args.goals))
        for r in range(rounds):  # interleaved, so both see the same load
            k = args.goals // rounds + (r < args.goals % rounds)
            a, f = bench_goals(client, k)
            accept += a
            full += f
            bare += bench_bare(bare_querier, k)
        bare_querier.undeclare()
        ms = lambda x: f"{x * 1e3:.3f} ms"  # noqa: E731
        print(f"goal accept round trip ({args.goals} goals, tcp loopback, server in its own process): "
              f"p50 {ms(statistics.median(accept))}  p99 {ms(percentile(accept, 0.99))}")
        print(f"bare zenoh query round trip ({len(bare)} queries, same link and config): "
              f"p50 {ms(statistics.median(bare))}  p99 {ms(percentile(bare, 0.99))}")
        print(f"goal accept / bare query: p50 x{statistics.median(accept) / statistics.median(bare):.2f}  "
              f"p99 x{percentile(accept, 0.99) / percentile(bare, 0.99):.2f}")
        print(f"goal send -> result ({args.goals} goals, no-op skill): "
              f"p50 {ms(statistics.median(full))}  p99 {ms(percentile(full, 0.99))}")
        ticks = bench_ticks(client, args.nodes, args.ticks)
        if isinstance(ticks, str):
            print(f"BT tick overhead: {ticks}")
        else:
            print(f"BT tick, {args.nodes} ExecuteSkill nodes with idle goals in flight ({args.ticks} ticks): "
                  f"p50 {ms(statistics.median(ticks))}  p99 {ms(percentile(ticks, 0.99))}")
        client.close()
    finally:
        server.terminate()
        server.join(10)
    return 0


def free_port() -> int:
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


if __name__ == "__main__":
    sys.exit(main())
