"""The live view of a real pybullet run, read back from its .rrd and opened in a real browser.

One recording, made as a user makes it — ``vap-bt run trees/collect_cup.yaml --world pybullet
--no-injection --seed 0 --rerun save X.rrd`` — is

* read back with rerun's chunk reader: the tree's nodes with their status at the final tick, a
  camera frame of a verification (decoded), and the questions and answers of a verification
  (checked against the report and the paper's paraphrases);
* served with ``rerun --serve-web --bind 127.0.0.1`` (web viewer and gRPC proxy on loopback only)
  and opened in Debian's headless ``chromium``, driven by Playwright (which cannot download
  browsers here, hence ``executable_path``). WebGL runs on SwiftShader (``--use-angle=swiftshader
  --enable-unsafe-swiftshader``); ``--disable-gpu`` is left out: it is not needed (tried: the
  viewer draws with or without it). Every request that is not to 127.0.0.1 (fonts, telemetry, the
  version check) is aborted by the page's router, so nothing leaves the machine. That machinery
  lives in tests/web_viewer.py, which the loading bench (tools/bench/viz_load.py) uses too.

The page counts as having loaded the recording when the viewer's own state
(``window._handle.viewer_state()``, a protobuf) names the recording's id and its ``tick``
timeline reaches the recording's last tick. The tree view counts as drawn when the tree panel's
pixels carry the status colours the recording holds at the shown tick: green only at the end,
and the orange running path at a tick in the middle — which is also the screenshot saved as
``docs/live-view.png`` (shown in ``docs/viz.md``) when ``VAP_BT_UPDATE_SCREENSHOTS=1`` — a test run
otherwise keeps its pictures in its own temporary folder, and a clone stays as it was checked out.

The panels in step: the time strip is clicked to the middle of the longest stretch of ticks in
which the tree highlights one check (read from the recording), and the verification panel's
pixels are read by OCR (Debian's ``tesseract``): the text must read as that check's atom, and
better than as any other check's of the episode (``docs/live-view-check.png``).
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from py_trees.common import Status

from conftest import ROOT, TREES, household_profile

pytest.importorskip("rerun")

from test_viz import read, tree_rows  # noqa: E402
from web_viewer import (BIN, HEIGHT, TIME_STRIP_Y, TREE_CONTENT, VERIFICATION_PANEL, WIDTH,  # noqa: E402
                        ViewerState, ink, ink_box, read_text, shot, viewer)

#: where the screenshots docs/viz.md shows are refreshed from (only on request: see the docstring)
UPDATE_SCREENSHOTS = os.environ.get("VAP_BT_UPDATE_SCREENSHOTS") == "1"


def _shot_path(name: str, tmp: Path) -> Path:
    return (ROOT / "docs" if UPDATE_SCREENSHOTS else tmp) / name


TASK, SEED = "collect_cup.yaml", 0


@dataclass
class Recorded:
    path: Path
    rows: dict
    report: dict


@pytest.fixture(scope="module")
def boil(tmp_path_factory) -> Recorded:
    out = tmp_path_factory.mktemp("live")
    rrd, report = out / "episode.rrd", out / "report.json"
    # collect_cup seed 0: five actions, their checks, no situation, about 15 s; what the browser test
    # reads (a skill in flight, a check's page) is in any episode (boil_water seed 1 took 90 s; the
    # symbolic recordings of test_viz have the situations, replans and recoveries)
    cmd = [str(BIN / "vap-bt"), "run", str(TREES / TASK), "--world", "pybullet", "--no-injection",
           "--seed", str(SEED), "--rerun", "save", str(rrd), "--report", str(report), "-q"]
    # this checkout's code, not the one an editable install in the environment points at (a worktree's
    # .venv may be another checkout's)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")]))}
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=900, cwd=ROOT, env=env)
    assert done.returncode == 0, done.stderr[-2000:]
    return Recorded(rrd, read(rrd), json.loads(report.read_text()))


# ---- read back -------------------------------------------------------------------------------

@pytest.mark.slow(seconds=20)  # the recording's episode
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


@pytest.mark.slow(seconds=90)  # 90 s in the full run of 2026-12-05
def test_the_web_viewer_shows_the_recording_and_draws_the_tree(boil, tmp_path):
    last_tick = boil.report["ticks"]
    with viewer(boil.path, last_tick, tmp_path) as page:
        end = shot(page, tmp_path / "end.png")
        green, orange = ink(end, Status.SUCCESS), ink(end, Status.RUNNING)
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
        middle = shot(page, _shot_path("live-view.png", tmp_path))
        green, orange = ink(middle, Status.SUCCESS), ink(middle, Status.RUNNING)
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
    shown = ViewerState.read(page).current[1]
    for x in xs:
        page.mouse.click(x, TIME_STRIP_Y)
        shown = _moved_from(page, shown)
        ticks.append(shown)
    assert ticks[1] > ticks[0], f"clicking the time strip did not move the time: {ticks}"
    x = xs[0] + (target - ticks[0]) * (xs[1] - xs[0]) / (ticks[1] - ticks[0])
    page.mouse.click(x, TIME_STRIP_Y)
    page.mouse.move(WIDTH / 2, HEIGHT / 2)
    _moved_from(page, shown)
    page.wait_for_timeout(1000)  # the panels draw at the new time before a screenshot is taken
    return ViewerState.read(page).current[1]


def _moved_from(page, tick: int, timeout_s: float = 5.0) -> int:
    """The tick the viewer shows once a click has moved its time off ``tick`` (polled: a fixed
    second after each click was most of a scrub's time), or the one it shows after ``timeout_s``
    (a click that landed on the tick shown already)."""
    deadline = time.monotonic() + timeout_s
    while True:
        page.wait_for_timeout(200)
        shown = ViewerState.read(page).current[1]
        if shown != tick or time.monotonic() > deadline:
            return shown


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
    image = shot(page, _shot_path("live-view-check.png", tmp_path))
    assert ink(image, Status.RUNNING) > 50, "the highlighted path is not drawn"
    text = read_text(image, VERIFICATION_PANEL)
    atoms = {a for _, _, a in _check_stretches(rows)}
    scores = {a: _named(text, a) for a in atoms}
    best = max(scores, key=scores.get)
    assert scores[highlighted] >= 0.8 and best == highlighted, (shown, highlighted, scores, text[:400])


@pytest.mark.slow(seconds=30)
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
        image = shot(page, _shot_path("live-view-20.png", tmp_path))
    # the drawing at tick 20 (a19 open): its orange running path and 19 green finished actions
    orange, green = ink(image, Status.RUNNING), ink(image, Status.SUCCESS)
    assert orange > 100 and green > 1000, (orange, green)
    _assert_not_cut_off(image)


def _assert_not_cut_off(image: np.ndarray) -> None:
    """Nothing of the tree is cut off: its ink ends short of every edge of the panel's drawing area."""
    x0, y0, x1, y1 = TREE_CONTENT
    drawn = ink_box(image, TREE_CONTENT)
    assert x0 + 3 < drawn[0] and drawn[2] < x1 - 3 and y0 + 3 < drawn[1] and drawn[3] < y1 - 3, (drawn, TREE_CONTENT)

