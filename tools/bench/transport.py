"""Transport benchmark: goal-accept round trip over Zenoh on loopback, and BT tick overhead.

    .venv/bin/python tools/bench/transport.py [--goals 1000] [--nodes 100] [--ticks 1000] [--rounds 10]

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


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--goals", type=int, default=1000)
    parser.add_argument("--nodes", type=int, default=100)
    parser.add_argument("--ticks", type=int, default=1000)
    parser.add_argument("--rounds", type=int, default=10,
                        help="blocks in which goals and bare queries alternate (default 10)")
    args = parser.parse_args()

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
