"""The rerun view (vap_bt/viz): real episodes recorded to real .rrd files, read back with rerun.

The recordings are read with rerun's own chunk reader (``rerun.chunk.RrdReader``) and checked
with the ``rerun`` CLI (``rrd verify``, ``rrd print``): the tree graph and its status colours per
tick, the verification text, situations, belief, and (pybullet) the camera images of each round.
"""

from __future__ import annotations

import os
import re
import socket
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

import pytest
from py_trees.common import Status

from conftest import ROOT, TREES

rr = pytest.importorskip("rerun")

from vap_bt.viz import SinkSpec, TreeRecorder, ViewerError  # noqa: E402
from vap_bt.viz.tree_graph import STATUS_COLOURS  # noqa: E402
from web_viewer import listeners  # noqa: E402

RERUN = Path(sys.executable).parent / "rerun"
#: a symbolic collect-cup episode with an effect situation and one replan (vlm_noise 0)
SEED_WITH_REPLAN = 8


def session(world: str = "symbolic"):
    from vap_bt import taskfile
    from vap_bt.app.runner import RunConfig, Session

    task = taskfile.load(TREES / "collect_cup.yaml")
    return Session(task, RunConfig.from_task(task, world=world, transport="inproc", vlm_noise=0.0))


def run(sess, seed: int, recorder: TreeRecorder):
    """One episode of the session, recorded; returns its outcome."""
    sess.recorder = recorder
    sess.episode(seed)
    return sess.last_outcome


def read(path: Path) -> dict[str, list[dict]]:
    """Entity path -> rows (timeline values and components), in logging order (row ids are
    time-ordered; chunks of one entity are not)."""
    from rerun.chunk import RrdReader

    rows: dict[str, list[dict]] = defaultdict(list)
    for chunk in RrdReader(path).stream():
        batch = chunk.to_record_batch()
        cols = [n for n in batch.schema.names if n not in ("log_time", "time")]
        data = batch.select(cols).to_pydict()
        rows[chunk.entity_path] += [{k: data[k][i] for k in cols} for i in range(chunk.num_rows)]
    for entity_rows in rows.values():
        entity_rows.sort(key=lambda r: r.pop("rerun.controls.RowId"))
    return rows


def texts(rows: dict, path: str) -> list[str]:
    return [r["TextLog:text"][0] for r in rows[path]]


def rgb(packed: int) -> tuple[int, int, int]:
    return (packed >> 24) & 255, (packed >> 16) & 255, (packed >> 8) & 255


STATUS_OF = {v: k for k, v in STATUS_COLOURS.items()}


@pytest.fixture(scope="module")
def symbolic():
    s = session()
    yield s
    s.close()


@pytest.fixture(scope="module")
def recorded(symbolic, tmp_path_factory):
    path = tmp_path_factory.mktemp("viz") / "episode.rrd"
    rec = TreeRecorder.open(["save", str(path)], name="collect_cup")
    outcome = run(symbolic, SEED_WITH_REPLAN, rec)
    rec.close()
    return path, outcome, read(path)


def test_recording_is_a_valid_rrd_with_the_tree_graph(recorded):
    path, outcome, rows = recorded
    assert outcome.success and outcome.replans == 1, "the seed should give one replan"
    env = {**os.environ, "RUST_LOG": "error"}
    verify = subprocess.run([str(RERUN), "rrd", "verify", str(path)], capture_output=True, text=True, env=env,
                            timeout=60)
    assert verify.returncode == 0, verify.stderr
    printed = subprocess.run([str(RERUN), "rrd", "print", str(path)], capture_output=True, text=True, env=env,
                             timeout=60).stdout
    assert ("/tree - data columns: [GraphEdges:edges GraphEdges:graph_type GraphNodes:colors GraphNodes:labels "
            "GraphNodes:node_ids GraphNodes:positions") in printed
    assert "/tree_text - data columns: [TextDocument:media_type TextDocument:text]" in printed
    for entity in ("/tree", "/tree_text", "/events/plan", "/events/actions", "/events/rounds", "/events/verifications",
                   "/events/situations", "/events/belief", "/scene/facts", "/scene/graph", "/verification/round",
                   "/stats/vlm_queries", "/stats/replans"):
        assert rows[entity], f"nothing logged at {entity}"


def tree_rows(rows: dict) -> list[dict]:
    """The drawing of the tree per logged tick: ids, labels, positions, statuses, edges."""
    return [{"tick": r["tick"], "ids": r["GraphNodes:node_ids"], "labels": r["GraphNodes:labels"],
             "positions": r["GraphNodes:positions"], "statuses": [STATUS_OF[rgb(c)] for c in r["GraphNodes:colors"]],
             "edges": [(e["first"], e["second"]) for e in r["GraphEdges:edges"]]}
            for r in rows["/tree"] if r.get("GraphNodes:node_ids")]


def test_tree_drawing_per_tick_folds_what_is_not_running(recorded):
    _, outcome, rows = recorded
    drawn = tree_rows(rows)
    ticks = [d["tick"] for d in drawn]
    assert ticks == sorted(set(ticks)) and ticks[0] == 1 and ticks[-1] == outcome.ticks
    for d in drawn:  # a tree over the visible nodes: each node but the root hangs from its parent
        assert d["ids"][0] == "0" and len(set(d["ids"])) == len(d["ids"])
        assert sorted(b for _, b in d["edges"]) == sorted(d["ids"][1:])
        assert all(b.rsplit(".", 1)[0] == a for a, b in d["edges"])
    first, last = drawn[0], drawn[-1]
    assert first["labels"][0].startswith("▶ plan") and first["statuses"][0] == Status.RUNNING
    # the root counts the plan's actions as the event log (and the command line) does
    said = next(t for t in texts(rows, "/events/plan") if t.startswith("plan: ")).split("\n")[0]
    assert first["labels"][0].split("\n")[0] == f"▶ plan · {said.removeprefix('plan: ')}", (first["labels"][0], said)
    assert any(i.count(".") >= 2 for i in first["ids"]), "the running first action is spread out"
    # the tick the effect check failed: the failing action stays open, its check marked ✗
    failed = next(d for d in drawn if d["statuses"][0] == Status.FAILURE)
    sit = outcome.situations[0]
    failing = [l for l, st in zip(failed["labels"], failed["statuses"]) if st == Status.FAILURE]
    assert failing[0].startswith("✗ plan") and failing[-1].split("\n")[0] == f"✗ {sit.atom}"
    assert failing[1] == f"✗ a{sit.step}: {sit.action}" and failing[2] == f"✗ {sit.kind[:3]}"
    # the final tick: every node of the replanned tree succeeded, each action folded to one node
    assert last["statuses"] and set(last["statuses"]) == {Status.SUCCESS}
    assert all(i.count(".") <= 1 for i in last["ids"]) and last["labels"][-1] == "✓ goal check"
    # logged only on change
    for a, b in zip(drawn, drawn[1:]):
        assert (a["labels"], a["statuses"], a["ids"]) != (b["labels"], b["statuses"], b["ids"])
    text = rows["/tree_text"][-1]["TextDocument:text"][0]
    assert text.startswith("{-} plan [✓]") and "[-]" not in text
    # what failed in the end is at most a view that did not settle, under a look that decided anyway
    # (what the hand holds: the gripper's feel)
    assert all(" -- vote=" in line for line in text.splitlines() if "[✕]" in line)


def test_text_log_tells_verifications_rounds_actions_and_situations(recorded):
    _, outcome, rows = recorded
    ctx = outcome.context
    ver = texts(rows, "/events/verifications")
    assert len(ver) == len(ctx.board.verifications)
    for line, v in zip(ver, ctx.board.verifications):
        assert str(v.atom) in line and v.outcome in line and v.action in line
    rounds = texts(rows, "/events/rounds")
    assert len(rounds) == sum(len(v.rounds) for v in ctx.board.verifications)
    first = ctx.board.verifications[0].rounds[0]
    assert all(f"Q: {q} → {'yes' if a else 'no'}" in rounds[0] for q, a in zip(first.questions, first.answers))
    assert "vote yes" in rounds[0]
    # each round's page, whole, among the pages of checks in progress and of verdicts
    pages = [r["TextDocument:text"][0] for r in rows["/verification/round"]]
    done = [p for p in pages if "- view sufficient: " in p]
    assert len(done) == len(rounds) and first.questions[0] in done[0]
    verdicts = [p for p in pages if p.startswith("# ") and "** (observed " in p.splitlines()[2]]
    assert len(verdicts) == len(ctx.board.verifications)
    for page, v in zip(verdicts, ctx.board.verifications):
        assert page.splitlines()[0] == f"# {'' if v.expected else 'not '}{v.atom}" and f": **{v.outcome}**" in page
    sit = texts(rows, "/events/situations")
    (situation,) = outcome.situations
    kind = situation.kind  # plotted by kind, on axes of its own
    assert [r["Scalars:scalars"][0] for r in rows[f"/stats/situations/{kind}"]] == [1.0]
    assert str(situation.atom) in sit[0] and rows["/events/situations"][0]["TextLog:level"] == ["WARN"]
    # raised, it says what the executive diagnosed; after the episode, the same line with the truth
    # the world's record gives beside it, then how many were right
    assert f"diagnosed {situation.diagnosis}: {situation.diagnosis_basis}" in sit[0] and "truth" not in sit[0]
    assert len(sit) == 3 and sit[1].startswith(sit[0] + " — truth ")
    right = sit[1].endswith("(right)")
    assert right or sit[1].endswith("(wrong)")
    assert sit[2] == f"diagnosis: {int(right)} of 1 situations as the world's record says"
    actions = texts(rows, "/events/actions")
    assert sum("start" in a for a in actions) == len(ctx.board.actions)
    assert sum("succeeded" in a for a in actions) == sum(e["state"] == "succeeded" for e in ctx.board.actions)
    # the recorder's own lines, among the run's progress lines that the session tees there too
    plan = [t for t in texts(rows, "/events/plan") if t.startswith(("episode ", "plan: ", "replan #"))]
    assert plan[0].startswith("episode 1") and plan[1].startswith("plan: ") and plan[2].startswith("replan #1")
    assert any(t.startswith("survey: ") for t in texts(rows, "/events/plan"))
    levels = {r["TextLog:text"][0].split(":")[0]: r["TextLog:level"][0] for r in rows["/events/plan"]}
    assert levels["replan #1"] == "WARN" and levels["plan"] == "INFO", "a replan is a warning"


def running_check(drawing: dict) -> str | None:
    """The atom of the check the drawing highlights (the running path's leaf, when it is a
    check: its label's first line is ``▶ <atom>`` and it has no shown children), else None."""
    ids = drawing["ids"]
    running = [(i, l) for i, l, st in zip(ids, drawing["labels"], drawing["statuses"]) if st == Status.RUNNING]
    leaves = [(i, l) for i, l in running if not any(j.startswith(i + ".") for j in ids)]
    label = leaves[-1][1].split("\n")[0][2:] if leaves else None
    # the gripper's word (feel hand) is asked in flight too, and has no verification page
    other = label is None or label.startswith(("execute ", "apply effects", "goal check", "feel hand")) \
        or re.match(r"a\d+: ", label)
    return None if other else label


def test_the_verification_page_names_the_check_the_tree_highlights_at_every_tick(recorded):
    """The panels in step: at every tick where the tree highlights a check, the verification
    page shown at that tick (the last one logged at or before it) is that check's page, and
    the page of a check in progress says what it is doing."""
    _, _, rows = recorded
    pages = [(r["tick"], r["TextDocument:text"][0]) for r in rows["/verification/round"]]
    drawings = tree_rows(rows)
    ticks = sorted({d["tick"] for d in drawings} | {t for t, _ in pages})
    checked = 0
    for tick in ticks:
        drawing = [d for d in drawings if d["tick"] <= tick][-1]
        atom = running_check(drawing)
        if atom is None:
            continue
        shown = [p for t, p in pages if t <= tick]
        assert shown, f"tick {tick}: the tree highlights {atom} and the page is empty"
        assert shown[-1].splitlines()[0] == f"# {atom}", (tick, atom, shown[-1][:200])
        checked += 1
    assert checked > 10, "the episode should highlight checks at many ticks"
    doing = [p for _, p in pages if "**now:** " in p]
    assert any("**now:** moving to the next viewpoint" in p for p in doing)
    assert any(re.search(r"\*\*now:\*\* asking the model: [1-4] of 5 answered", p) for p in doing), \
        "answers should be seen arriving one by one"


def test_belief_is_logged_when_it_changes(recorded):
    _, outcome, rows = recorded
    docs = rows["/scene/facts"]
    changes = outcome.graph.history
    assert len(texts(rows, "/events/belief")) == len(changes)
    assert 1 < len(docs) <= len(changes) + 1  # the initial survey, then at most once per tick with changes
    final = docs[-1]["TextDocument:text"][0]
    assert all(f"`{a}`" in final for a in outcome.graph.facts)
    graph = rows["/scene/graph"][-1]
    assert "cup" in graph["GraphNodes:node_ids"] and "on(cup, counter)" in graph["GraphNodes:node_ids"]
    # laid out: the cup hangs from the counter by a labelled edge, counter — on — cup
    edges = {(e["first"], e["second"]) for e in graph["GraphEdges:edges"]}
    assert {("counter", "on(cup, counter)"), ("on(cup, counter)", "cup")} <= edges
    assert len(graph["GraphNodes:positions"]) == len(graph["GraphNodes:node_ids"])


def test_episodes_of_one_session_share_a_timeline(symbolic, tmp_path):
    path = tmp_path / "two.rrd"
    with TreeRecorder.open(f"save {path}") as rec:
        symbolic.recorder = rec
        first_report, first = symbolic.episode(0), symbolic.last_outcome
        second_report, second = symbolic.episode(SEED_WITH_REPLAN), symbolic.last_outcome
    rows = read(path)
    assert [t.split(":")[0] for t in texts(rows, "/events/plan") if t.startswith("episode")] == [
        "episode 1", "episode 2"]
    ticks = [r["tick"] for r in rows["/tree"]]
    assert ticks == sorted(ticks) and ticks[-1] == first.ticks + second.ticks
    # the queries plot ends on the count the command line prints, summed over the episodes
    queries = [r["Scalars:scalars"][0] for r in rows["/stats/vlm_queries"]]
    assert queries == sorted(queries) and queries[-1] == first_report["vlm_queries"] + second_report["vlm_queries"]
    # the queries of each action's checks, one bar per checked action: the checks' queries (the
    # surveys' and the search's are in the total only)
    bars = rows["/stats/queries_per_action"][-1]["BarChart:values"][0]["buffer"]
    assert sum(bars) == sum(v.to_json()["queries"] for v in second.context.board.verifications)


@pytest.mark.slow
def test_pybullet_rounds_carry_their_camera_images(tmp_path):
    pytest.importorskip("pybullet")
    sess = session("pybullet")
    path = tmp_path / "pybullet.rrd"
    try:
        with TreeRecorder.open(["save", str(path)]) as rec:
            outcome = run(sess, 0, rec)
    finally:
        sess.close()
    rows = read(path)
    n_rounds = len(rows["/events/rounds"])
    assert n_rounds > 0 and n_rounds >= sum(len(v.rounds) for v in outcome.context.board.verifications)
    for entity, component in (("/world/camera/rgb", "EncodedImage:blob"), ("/world/camera/depth", "EncodedDepthImage:blob"),
                              ("/world/camera/detections", "Boxes2D:half_sizes")):
        assert sum(r.get(component) is not None for r in rows[entity]) == n_rounds, entity
    # a frame without detections logs no boxes (not the last frame's): most frames have some
    assert sum(bool(r["Boxes2D:half_sizes"]) for r in rows["/world/camera/detections"]) > n_rounds / 2
    # the depth image is stored as a lossless 16-bit PNG of millimetres: it decodes to the camera's size
    import cv2
    import numpy as np

    (w, h), = next(r["Pinhole:resolution"] for r in rows["/world/camera"] if r.get("Pinhole:resolution"))
    depth = cv2.imdecode(np.frombuffer(bytes(rows["/world/camera/depth"][0]["EncodedDepthImage:blob"][0]), np.uint8),
                         cv2.IMREAD_UNCHANGED)
    assert depth.dtype == np.uint16 and depth.shape == (int(h), int(w)) and 300 < np.median(depth[depth > 0]) < 10000
    # each detection box is named for what the robot took it for
    labels = {l for r in rows["/world/camera/detections"] for l in r.get("Boxes2D:labels") or ()}
    assert "cup" in labels or "(cup)" in labels, labels
    assert [r["view"] for r in rows["/world/camera/rgb"]] == list(range(1, n_rounds + 1))
    assert "(image #1)" in texts(rows, "/events/rounds")[0]
    camera = [r for r in rows["/world/camera"] if r.get("Pinhole:image_from_camera")]
    assert len(camera) == n_rounds
    assert rows["/world/objects"] and "cup" in rows["/world/objects"][0]["Boxes3D:labels"]
    # the fused clouds of what the builder tracks, thinned, each logged when it changed
    clouds = {p: r for p, r in rows.items() if p.startswith("/world/clouds/")}
    assert "/world/clouds/cup" in clouds, sorted(clouds)
    sizes = [len(r["Points3D:positions"]) for rs in clouds.values() for r in rs if r.get("Points3D:positions")]
    assert sizes and max(sizes) <= 600 and min(sizes) > 0
    # the cup's cloud lies in its box (belief's geometry and the points agree)
    cup = np.asarray(clouds["/world/clouds/cup"][-1]["Points3D:positions"])
    assert np.linalg.norm(cup.mean(axis=0) - np.asarray(box_centre_of_cup(outcome))) < 0.1


def box_centre_of_cup(outcome) -> tuple[float, float, float]:
    box = outcome.graph.objects["cup"].box
    return tuple((lo + hi) / 2 for lo, hi in zip(box[:3], box[3:]))


def test_spawn_without_a_display_fails_with_one_clear_line(monkeypatch):
    for var in ("DISPLAY", "WAYLAND_DISPLAY", "WAYLAND_SOCKET"):
        monkeypatch.delenv(var, raising=False)
    if not sys.platform.startswith("linux"):
        pytest.skip("the display check is Linux's")
    with pytest.raises(ViewerError) as err:
        TreeRecorder.open("spawn")
    msg = str(err.value)
    assert "\n" not in msg and "no display" in msg and "--rerun save" in msg
    assert err.value.exit_code == 4


def test_spawn_reports_the_viewers_own_error_when_it_dies(monkeypatch):
    if not sys.platform.startswith("linux"):
        pytest.skip("needs an X display name that does not exist")
    monkeypatch.setenv("DISPLAY", ":987")  # no X server there: the real viewer starts, then exits
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    with pytest.raises(ViewerError) as err:
        TreeRecorder.open(["spawn"])
    assert "\n" not in str(err.value) and "exited" in str(err.value)


def test_serve_listens_on_loopback_only():
    if not os.path.exists("/proc/net/tcp"):
        pytest.skip("needs Linux /proc")
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    rec = TreeRecorder.open(["serve", str(port)])
    try:
        rec.note("hello")
        assert rec.recording.url == f"rerun+http://127.0.0.1:{port}/proxy"
        found = listeners(port)
        assert found == ["0100007F"], found  # 127.0.0.1, and nothing else
        with pytest.raises(ViewerError, match="in use"):
            TreeRecorder.open(["serve", str(port)])
    finally:
        rec.close()


@pytest.mark.parametrize("words,expected", [
    (["spawn"], SinkSpec("spawn")),
    (["serve"], SinkSpec("serve", port=9876)),
    (["serve", "9000"], SinkSpec("serve", port=9000)),
    (["save", "out.rrd"], SinkSpec("save", path=Path("out.rrd"))),
    ("save:out.rrd", SinkSpec("save", path=Path("out.rrd"))),
])
def test_sink_words(words, expected):
    assert SinkSpec.parse(words) == expected


@pytest.mark.parametrize("words", [[], ["save"], ["save", "x.txt"], ["serve", "port"], ["spawn", "x"], ["web"]])
def test_bad_sink_words_are_input_errors(words):
    from vap_bt.errors import InputError

    with pytest.raises(InputError):
        SinkSpec.parse(words)


def test_viz_is_the_only_room_that_imports_rerun():
    """The executive stays rerun-free: importing it must not pull rerun in."""
    code = ("import sys; import vap_bt.app.runner, vap_bt.bt.executive; "
            "assert 'rerun' not in sys.modules, 'rerun imported by the executive'")
    subprocess.run([sys.executable, "-c", code], check=True, cwd=ROOT, timeout=120)
