"""The live view of a real pybullet run, read back from its .rrd and opened in a real browser.

One recording, made as a user makes it — ``vap-bt run trees/boil_water.yaml --world pybullet
--no-injection --rerun save X.rrd`` — is

* read back with rerun's chunk reader: the tree's nodes with their status at the final tick, a
  camera frame of a verification (decoded), and the questions and answers of a verification
  (checked against the report and the paper's paraphrases);
* served with ``rerun --serve-web --bind 127.0.0.1`` (web viewer and gRPC proxy on loopback only)
  and opened in Debian's headless ``chromium``, driven by Playwright (which cannot download
  browsers here, hence ``executable_path``). WebGL runs on SwiftShader (``--use-angle=swiftshader
  --enable-unsafe-swiftshader``); ``--disable-gpu`` is left out: it is not needed (tried: the
  viewer draws with or without it). Every request that is not to 127.0.0.1 (fonts, telemetry, the
  version check) is aborted by the page's router, so nothing leaves the machine.

The page counts as having loaded the recording when the viewer's own state
(``window._handle.viewer_state()``, a protobuf) names the recording's id and its ``tick``
timeline reaches the recording's last tick. The tree view counts as drawn when the tree panel's
pixels carry the status colours the recording holds at the shown tick: green only at the end,
and the orange running path at a tick in the middle — which is also the screenshot saved as
``docs/live-view.png`` (shown in ``docs/viz.md``) when ``VAP_BT_UPDATE_SCREENSHOTS=1`` — a test run
otherwise keeps its pictures in its own temporary folder, and a clone stays as it was checked out.
"""

from __future__ import annotations

import json
import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from py_trees.common import Status

from conftest import ROOT, TREES, household_profile

pytest.importorskip("rerun")

from test_viz import _listeners, read, tree_rows  # noqa: E402
from vap_bt.viz.tree_graph import STATUS_COLOURS  # noqa: E402

BIN = Path(sys.executable).parent
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--no-sandbox",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--no-first-run"]
WIDTH, HEIGHT = 1920, 1080
#: the behaviour-tree panel of the default blueprint in that window (left 9/20, above the event
#: log): its drawing area (inside the borders, under the title bar), and a box within it for counting ink
TREE_CONTENT = (2, 60, 858, 848)
TREE_PANEL = (0, 60, 850, 800)
#: the verification panel (the middle column, 9/20 to 14/20 of the width, its upper half, under its title bar)
VERIFICATION_PANEL = (868, 60, 1340, 520)
#: the collapsed time panel's strip at the bottom of the window: a click there sets the time
TIME_STRIP_Y = HEIGHT - 14
#: where the screenshots docs/viz.md shows are refreshed from (only on request: see the docstring)
UPDATE_SCREENSHOTS = os.environ.get("VAP_BT_UPDATE_SCREENSHOTS") == "1"


def _shot_path(name: str, tmp: Path) -> Path:
    return (ROOT / "docs" if UPDATE_SCREENSHOTS else tmp) / name
LOAD_TIMEOUT_S = 240


@dataclass
class Recorded:
    path: Path
    rows: dict
    report: dict


@pytest.fixture(scope="module")
def boil(tmp_path_factory) -> Recorded:
    out = tmp_path_factory.mktemp("live")
    rrd, report = out / "boil_water.rrd", out / "report.json"
    cmd = [str(BIN / "vap-bt"), "run", str(TREES / "boil_water.yaml"), "--world", "pybullet", "--no-injection",
           "--rerun", "save", str(rrd), "--report", str(report), "-q"]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=900, cwd=ROOT)
    assert done.returncode == 0, done.stderr[-2000:]
    return Recorded(rrd, read(rrd), json.loads(report.read_text()))


# ---- read back -------------------------------------------------------------------------------

@pytest.mark.slow
def test_the_recording_holds_the_final_tree_a_frame_and_a_verifications_questions(boil):
    from vap_bt.domain.atoms import Atom

    rep = boil.report
    assert rep["success"] and rep["goal_satisfied"]
    # the tree at the final tick: every node succeeded, each action folded to one node
    final = tree_rows(boil.rows)[-1]
    assert final["tick"] == rep["ticks"]
    plan = rep["plans"][-1]["actions"]
    steps = dict((i, (l, s)) for i, l, s in zip(final["ids"], final["labels"], final["statuses"]) if i.count(".") == 1)
    assert [steps[f"0.{k}"][0] for k in range(len(plan))] == [f"✓ a{k}: {a}" for k, a in enumerate(plan)]
    assert [l for l, _ in steps.values()][-2:] == ["✓ goal", "✓ goal check"]
    assert set(final["statuses"]) == {Status.SUCCESS} and len(final["ids"]) == 1 + len(steps)
    text = boil.rows["/tree_text"][-1]["TextDocument:text"][0]
    assert text.startswith("{-} plan [✓]") and all(f"{{-}} a{k}: {a} [✓]" in text for k, a in enumerate(plan))
    # a frame: the JPEG of a verification's view decodes to the camera's resolution, and is no blank
    import cv2

    frames = boil.rows["/world/camera/rgb"]
    assert len(frames) == sum(v["views"] for v in rep["verifications"])
    image = cv2.imdecode(np.frombuffer(bytes(frames[0]["EncodedImage:blob"][0]), np.uint8), cv2.IMREAD_COLOR)
    (w, h), = next(r["Pinhole:resolution"] for r in boil.rows["/world/camera"] if r.get("Pinhole:resolution"))
    assert image.shape == (int(h), int(w), 3) and image.std() > 10
    # the questions and answers of the first verification: the page of its first round (after the
    # pages of the check in progress) holds the paper's paraphrases for the atom, each with the
    # answer the report recorded, then the vote and view sufficiency
    v = rep["verifications"][0]
    page = next(p for r in boil.rows["/verification/round"] for p in r["TextDocument:text"] if "\n- vote: " in p)
    questions = household_profile().questions(Atom.parse(v["predicate"]), 5)
    answers = v["rounds"][0]["answers"]
    assert page.startswith(f"# {v['predicate']}") and f"check of **{v['action']}**" in page
    for i, (q, a) in enumerate(zip(questions, answers), start=1):
        assert f"| {i} | {q} | {a} |" in page
    said = {True: "yes", False: "no", None: "?"}
    first = v["rounds"][0]
    assert f"- vote: **{said[first['vote']]}**" in page and f"- view sufficient: {said[first['sufficient']]}" in page


# ---- in a browser ----------------------------------------------------------------------------

def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _wait_listening(port: int, timeout_s: float = 30.0) -> None:
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        with socket.socket() as s:
            if s.connect_ex(("127.0.0.1", port)) == 0:
                return
        time.sleep(0.2)
    raise AssertionError(f"nothing listens on 127.0.0.1:{port} after {timeout_s:.0f} s")


@contextmanager
def served(rrd: Path, log: Path):
    """The web viewer and the recording's gRPC proxy, on loopback only; yields the page's URL."""
    grpc, web = _free_port(), _free_port()
    with log.open("w") as out:
        proc = subprocess.Popen([str(BIN / "rerun"), "--serve-web", "--bind", "127.0.0.1", "--port", str(grpc),
                                 "--web-viewer-port", str(web), str(rrd)], stdin=subprocess.DEVNULL, stdout=out,
                                stderr=subprocess.STDOUT, start_new_session=True, env={**os.environ, "RUST_LOG": "warn"})
    try:
        _wait_listening(grpc)
        _wait_listening(web)
        if os.path.exists("/proc/net/tcp"):
            assert _listeners(grpc) == ["0100007F"] and _listeners(web) == ["0100007F"], "must listen on 127.0.0.1 only"
        yield f"http://127.0.0.1:{web}/?url=rerun%2Bhttp%3A%2F%2F127.0.0.1%3A{grpc}%2Fproxy"
    finally:
        os.killpg(proc.pid, signal.SIGTERM)  # the launcher and the viewer binary it started
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)


def _fields(buf: bytes) -> list[tuple[int, object]]:
    """One level of protobuf wire format: (field number, int or bytes) pairs."""
    out, i = [], 0

    def varint() -> int:
        nonlocal i
        value = shift = 0
        while True:
            byte = buf[i]
            i += 1
            value |= (byte & 0x7F) << shift
            shift += 7
            if byte < 0x80:
                return value

    while i < len(buf):
        key = varint()
        number, kind = key >> 3, key & 7
        if kind == 0:
            out.append((number, varint()))
        elif kind == 2:
            n = varint()
            out.append((number, buf[i:i + n]))
            i += n
        elif kind in (1, 5):
            size = 8 if kind == 1 else 4
            out.append((number, buf[i:i + size]))
            i += size
        else:
            raise ValueError(f"protobuf wire type {kind}")
    return out


def _get(buf: bytes, number: int, default=None):
    return next((v for n, v in _fields(buf) if n == number), default)


@dataclass
class ViewerState:
    """What the viewer says it shows: the recording, each timeline's last time, the current time."""

    recording_id: str | None
    ends: dict[str, int]
    current: tuple[str, int] | None

    @classmethod
    def read(cls, page) -> "ViewerState":
        # window._handle is the page's rerun.WebHandle; viewer_state() is a protobuf whose field 3 is
        # the active recording: (2) its timelines {1: {1: name}, 3: {1: min, 2: max}} and (3) the
        # current time {1: {1: name}, 3: {1: value}} (read off rerun 0.41's viewer, which is pinned)
        raw = bytes(page.evaluate("() => Array.from(window._handle.viewer_state())"))
        found = re.search(rb"recording_id=([0-9a-f]+)", raw)
        active = _get(raw, 3, b"")
        ends, current = {}, None
        for number, value in _fields(active):
            if number == 2:
                ends[_get(_get(value, 1, b""), 1, b"").decode()] = _get(_get(value, 3, b""), 2, 0)
            elif number == 3:
                current = (_get(_get(value, 1, b""), 1, b"").decode(), _get(_get(value, 3, b""), 1, 0))
        return cls(found.group(1).decode() if found else None, ends, current)


def _ink(image: np.ndarray, status: Status, box=TREE_PANEL) -> int:
    """Pixels in ``box`` of the hue of ``status``'s colour: labels are thin anti-aliased text, so
    their pixels are judged by hue (within 12 degrees) and saturation, not by exact colour."""
    import cv2

    x0, y0, x1, y1 = box
    hsv = cv2.cvtColor(np.ascontiguousarray(image[y0:y1, x0:x1, :3]), cv2.COLOR_RGB2HSV).astype(int)
    want = int(cv2.cvtColor(np.uint8([[STATUS_COLOURS[status]]]), cv2.COLOR_RGB2HSV)[0, 0, 0])
    near = np.minimum(np.abs(hsv[..., 0] - want), 180 - np.abs(hsv[..., 0] - want)) <= 6  # OpenCV hue: 0..179
    return int((near & (hsv[..., 1] > 100) & (hsv[..., 2] > 80)).sum())


def _shot(page, path: Path) -> np.ndarray:
    import cv2

    page.screenshot(path=str(path))
    return cv2.cvtColor(cv2.imread(str(path)), cv2.COLOR_BGR2RGB)


def _skill_in_flight(rows: dict, first_step: int = 2) -> int:
    """The middle tick of the longest stretch where action ``first_step`` or a later one is open
    with ``✓ pre`` and its ``execute`` node running: the moment docs/live-view.png shows (the
    longest, so that a click on the time strip, a few ticks off, still lands in it)."""
    def shows(d: dict) -> bool:
        at = dict(zip(d["ids"], zip(d["labels"], d["statuses"])))
        return any(i.count(".") == 1 and int(i.split(".")[1]) >= first_step and
                   at.get(f"{i}.0", ("", None))[0] == "✓ pre" and at.get(f"{i}.1", ("", None))[1] == Status.RUNNING
                   for i in at)

    ticks = [d["tick"] for d in tree_rows(rows)]
    flags = [shows(d) for d in tree_rows(rows)]
    stretches, start = [], None  # (first, last) drawing index of each stretch
    for k, f in enumerate([*flags, False]):
        if f and start is None:
            start = k
        elif not f and start is not None:
            stretches.append((start, k - 1))
            start = None
    first, last = max(stretches, key=lambda st: ticks[st[1]] - ticks[st[0]])
    return (ticks[first] + ticks[last]) // 2


def _drawing_at(rows: dict, tick: int) -> dict:
    """The tree drawing the viewer shows at ``tick``: the last one logged at or before it."""
    return [d for d in tree_rows(rows) if d["tick"] <= tick][-1]


@contextmanager
def viewer(rrd: Path, last_tick: int, tmp_path: Path):
    """The recording in the web viewer in headless chromium; yields the page once it has loaded:
    the viewer names the recording's id and follows its tick timeline to ``last_tick``."""
    if not os.access(CHROMIUM, os.X_OK):
        pytest.fail(f"{CHROMIUM} is missing: tools/setup.sh installs Debian's chromium")
    from playwright.sync_api import sync_playwright
    from rerun.chunk import RrdReader

    recording_id = RrdReader(rrd).recordings()[0].recording_id
    with served(rrd, tmp_path / "rerun.log") as url, sync_playwright() as pw:
        browser = pw.chromium.launch_persistent_context(
            tempfile.mkdtemp(prefix="chromium-", dir=tmp_path), executable_path=CHROMIUM, headless=True,
            args=CHROMIUM_ARGS, viewport={"width": WIDTH, "height": HEIGHT})
        try:
            page = browser.new_page()
            page.route("**/*", lambda r: r.continue_() if r.request.url.startswith("http://127.0.0.1:") else r.abort())
            # the viewer ingests the recording a little per drawn frame, and software rendering draws
            # a full-size frame slowly: it loads in a small window, then takes the test's size
            page.set_viewport_size({"width": 320, "height": 240})
            page.goto(url)
            page.wait_for_function("() => window._handle !== undefined", timeout=60_000)
            deadline, state = time.monotonic() + LOAD_TIMEOUT_S, None
            while time.monotonic() < deadline:
                state = ViewerState.read(page)
                if state.ends.get("tick") == last_tick and state.current == ("tick", last_tick):
                    break
                time.sleep(1.0)
            assert state is not None and state.recording_id == recording_id, state
            assert state.ends.get("tick") == last_tick and state.current == ("tick", last_tick), state
            page.set_viewport_size({"width": WIDTH, "height": HEIGHT})
            time.sleep(2.0)  # let the last frames render
            yield page
        finally:
            browser.close()


@pytest.mark.slow
def test_the_web_viewer_shows_the_recording_and_draws_the_tree(boil, tmp_path):
    last_tick = boil.report["ticks"]
    with viewer(boil.path, last_tick, tmp_path) as page:
        end = _shot(page, tmp_path / "end.png")
        green, orange = _ink(end, Status.SUCCESS), _ink(end, Status.RUNNING)
        # a drawn label is some tens of green pixels, none when the panel draws nothing; the last
        # tree is the last plan's, shorter after a replan (985 px in one such run), so the bar is
        # well under; a last plan of no actions is its goal checks alone (295 px in one run)
        bar = 500 if boil.report["plans"][-1]["actions"] else 150
        assert green > bar, f"the finished tree's green labels are not drawn ({green} px)"
        assert orange < 30, f"nothing runs at the end, yet orange is drawn in the tree panel ({orange} px)"

        # a tick where a later action is spread out, its preconditions confirmed and its skill in
        # flight (the middle of that stretch), set by clicking the time strip, whose pixel-to-tick
        # scale is read off two calibration clicks
        target = _skill_in_flight(boil.rows)
        shown = _scrub(page, target)
        drawing = _drawing_at(boil.rows, shown)
        assert abs(shown - target) <= 0.05 * last_tick, (shown, target)
        assert any(i.count(".") >= 2 for i in drawing["ids"]), f"no action is spread out at tick {shown}"
        assert Status.RUNNING in drawing["statuses"] and Status.SUCCESS in drawing["statuses"]
        middle = _shot(page, _shot_path("live-view.png", tmp_path))
        green, orange = _ink(middle, Status.SUCCESS), _ink(middle, Status.RUNNING)
        assert orange > 100, f"the running path's orange labels are not drawn ({orange} px)"
        assert green > 100, f"the finished actions' green labels are not drawn ({green} px)"
        _assert_not_cut_off(middle)
        # the camera panel shows the frame of the current verification, not an empty view
        camera = middle[60:400, 1350:1640, :3]
        assert camera.std() > 20, "the camera panel is blank"
        _the_verification_panel_follows_the_tree(page, boil.rows, tmp_path)


def _scrub(page, target: int) -> int:
    """Set the viewer's time to about ``target`` by clicking the time strip, whose pixel-to-tick
    scale is read off two calibration clicks; returns the tick the viewer then shows."""
    xs, ticks = (0.3 * WIDTH, 0.7 * WIDTH), []
    for x in xs:
        page.mouse.click(x, TIME_STRIP_Y)
        time.sleep(1.0)
        ticks.append(ViewerState.read(page).current[1])
    assert ticks[1] > ticks[0], f"clicking the time strip did not move the time: {ticks}"
    x = xs[0] + (target - ticks[0]) * (xs[1] - xs[0]) / (ticks[1] - ticks[0])
    page.mouse.click(x, TIME_STRIP_Y)
    page.mouse.move(WIDTH / 2, HEIGHT / 2)
    time.sleep(3.0)
    return ViewerState.read(page).current[1]


def _check_stretches(rows: dict) -> list[tuple[int, int, str]]:
    """(first tick, last tick, atom) of each stretch of ticks during which the tree highlights one
    check — what the viewer shows from a drawing's tick up to the next drawing's."""
    from test_viz import running_check

    drawings = tree_rows(rows)
    out: list[tuple[int, int, str]] = []
    for d, nxt in zip(drawings, [*drawings[1:], None]):
        atom, end = running_check(d), (nxt["tick"] - 1 if nxt else d["tick"])
        if atom is None:
            continue
        if out and out[-1][2] == atom and out[-1][1] + 1 == d["tick"]:
            out[-1] = (out[-1][0], end, atom)
        else:
            out.append((d["tick"], end, atom))
    return out


def read_text(image: np.ndarray, box) -> str:
    """What tesseract reads in ``box`` of a screenshot: enlarged three times (the viewer's text is
    12-14 px, small for it) and made dark on light (the viewer's theme is light on dark)."""
    import cv2

    x0, y0, x1, y1 = box
    grey = cv2.cvtColor(np.ascontiguousarray(image[y0:y1, x0:x1, :3]), cv2.COLOR_RGB2GRAY)
    grey = cv2.resize(grey, None, fx=3, fy=3, interpolation=cv2.INTER_CUBIC)
    if grey.mean() < 128:
        grey = 255 - grey
    ok, png = cv2.imencode(".png", grey)
    done = subprocess.run(["tesseract", "stdin", "stdout", "--psm", "6"], input=png.tobytes(), capture_output=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr.decode()[-500:]
    return done.stdout.decode(errors="replace")


def _letters(text: str) -> str:
    return re.sub(r"[^a-z0-9]", "", text.lower())


def _named(text: str, atom: str) -> float:
    """How well the best line of ``text`` reads as ``atom`` (1.0: letter for letter; OCR drops
    underscores and brackets, so only letters and digits are compared)."""
    from difflib import SequenceMatcher

    lines = [_letters(l) for l in text.splitlines() if _letters(l)]
    return max((SequenceMatcher(None, _letters(atom), l).ratio() for l in lines), default=0.0)


def _the_verification_panel_follows_the_tree(page, rows: dict, tmp_path: Path) -> None:
    """Scrubbed to the middle of the longest stretch during which the tree highlights one check,
    the verification panel names that check's atom — read off the screen by OCR, and read better
    as that atom than as any other check's of the episode."""
    first, last, atom = max(_check_stretches(rows), key=lambda st: st[1] - st[0])
    shown = _scrub(page, (first + last) // 2)
    highlighted = next((a for f, l, a in _check_stretches(rows) if f <= shown <= l), None)
    assert highlighted is not None, f"scrubbed to tick {shown}, where the tree highlights no check ({first}..{last})"
    shot = _shot(page, _shot_path("live-view-check.png", tmp_path))
    assert _ink(shot, Status.RUNNING) > 50, "the highlighted path is not drawn"
    text = read_text(shot, VERIFICATION_PANEL)
    atoms = {a for _, _, a in _check_stretches(rows)}
    scores = {a: _named(text, a) for a in atoms}
    best = max(scores, key=scores.get)
    assert scores[highlighted] >= 0.8 and best == highlighted, (shown, highlighted, scores, text[:400])


@pytest.mark.slow
def test_a_20_action_plan_is_drawn_whole_in_the_tree_panel(tmp_path):
    """The recorder itself, fed a compiled 20-action tree as ticking leaves it (action k running,
    the ones before it done), one tick per action: every label of the drawing lies inside the
    tree panel at the viewer's default zoom (screenshot: docs/live-view-20.png)."""
    import py_trees

    from test_viz_tree import compiled, plan_of, running_at
    from vap_bt.viz import TreeRecorder

    _, a = plan_of("gather_kindling.yaml")
    _, b = plan_of("retrieve_bottles.yaml")
    root = compiled(actions=(list(a) + list(b))[:20])
    tree = py_trees.trees.BehaviourTree(root)
    rrd = tmp_path / "twenty.rrd"
    with TreeRecorder.open(["save", str(rrd)], name="20 actions") as rec:
        for k in range(20):
            running_at(root, k, checks_done=1)
            rec.on_tree(tree, k + 1)
    drawn = tree_rows(read(rrd))
    assert [d["tick"] for d in drawn] == list(range(1, 21))
    with viewer(rrd, 20, tmp_path) as page:
        shot = _shot(page, _shot_path("live-view-20.png", tmp_path))
    # the drawing at tick 20 (a19 open): its orange running path and 19 green finished actions
    orange, green = _ink(shot, Status.RUNNING), _ink(shot, Status.SUCCESS)
    assert orange > 100 and green > 1000, (orange, green)
    _assert_not_cut_off(shot)


def _assert_not_cut_off(shot: np.ndarray) -> None:
    """Nothing of the tree is cut off: its ink ends short of every edge of the panel's drawing area."""
    x0, y0, x1, y1 = TREE_CONTENT
    ink = _ink_box(shot, TREE_CONTENT)
    assert x0 + 3 < ink[0] and ink[2] < x1 - 3 and y0 + 3 < ink[1] and ink[3] < y1 - 3, (ink, TREE_CONTENT)


def _ink_box(image: np.ndarray, box) -> tuple[int, int, int, int]:
    """Bounding box, in window pixels, of what is drawn in ``box`` on the view's white background:
    label frames, edges and arrowheads (dark) and label text (coloured or grey)."""
    x0, y0, x1, y1 = box
    ys, xs = np.nonzero(image[y0:y1, x0:x1, :3].min(axis=2) < 200)
    return x0 + int(xs.min()), y0 + int(ys.min()), x0 + int(xs.max()), y0 + int(ys.max())
