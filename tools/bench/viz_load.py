"""How quickly a recording opens in the web viewer (issue 27): file size, time to the first drawn
tree, time to the whole recording — for one .rrd or several side by side, however they were made.

    python tools/bench/viz_load.py --rrd /tmp/viewload/before.rrd --label before \\
        --rrd /tmp/viewload/after.rrd --label after [--runs 5] [--keep DIR] [--by-entity]

Each file is served on loopback (``rerun --serve-web --bind 127.0.0.1``) and opened in Debian's
headless chromium with tests/web_viewer.py, the live-view test's machinery: a fresh server and a
fresh browser profile per page (the viewer's wasm is fetched and compiled every time alike). The
clock starts when the page is sent to the viewer's URL. A run is two pages:

1. In a 1920x1080 window — the test's window, where the tree panel box (``TREE_PANEL``) and the
   ink bars are measured, a usual screen, and large enough for the tree's labels to be read:
   * **viewer up**: the viewer's handle exists (``window._handle``: its wasm has started) — the
     same for every file, the part of the rest that is the viewer's own start-up;
   * **first tree**: the first frame whose tree panel holds at least ``--ink`` pixels of the status
     hues (green, orange, red; ``web_viewer.ink``, the test's judge). The viewer follows the newest
     tick while it loads, so this is when a user first sees a tree. Frames come from the page's
     screencast (CDP ``Page.startScreencast``, PNG) timed by the browser's swap time: a screenshot
     instead forces a frame and took 8-24 s each here, longer than the wait it measures.
2. In the test's 320x240 window (``LOAD_WIDTH`` x ``LOAD_HEIGHT``), waited for by the very loop
   of the test's ``viewer()`` (``web_viewer.load``):
   * **whole recording**: the viewer follows the file's recording to its last tick (read from the
     file). The viewer ingests the recording a little per drawn frame, and SwiftShader draws a
     1920x1080 frame in about 4 s on this 2-core machine: at full size the same file took 392 s
     instead of about 70 s, a figure of the software rasterizer more than of the file (a GPU
     draws a frame in milliseconds). The small window keeps what the file costs in front; the
     tree panel is hidden in it, hence the first page;
   * **end px**: then, enlarged to 1920x1080 as in the test, the finished tree's green ink (the
     test asks for more than 500 px in a boil_water run whose last plan has actions, 150 when it
     has none): that the tree the file holds is drawn. ``--no-end-check`` skips it (a full-size
     screenshot: 10-20 s).

The measure is the same for every file; absolute seconds on SwiftShader are not a GPU's, the
ratios between files are the figure. Runs alternate between the files, in reversed order every
other round (A B, B A, A B, ...), so that the noise of a shared machine falls on all alike; each
file's ratio to the first is taken within each round, and summarised by its median and range.
Medians per file [min-max] and those ratios go to stdout; progress and each run's figures to
stderr.

The two recordings of issue 27, one per commit, each made in a checkout of that commit (``git
worktree add /tmp/viewload/at-X X``), with that checkout first on the path (the installed
``vap-bt`` may be an editable install of another checkout):

    cd /tmp/viewload/at-X && PYTHONPATH=$PWD vap-bt run trees/boil_water.yaml --world pybullet \\
        --no-injection --seed 0 --rerun save /tmp/viewload/X.rrd -q

(1-3 minutes each). ``--by-entity`` prints, per file, the bytes per entity path (Arrow in memory,
and after LZ4 as estimated by compressing each chunk's Arrow IPC message, as the .rrd does).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from collections import Counter
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
import vap_bt  # noqa: E402,F401  (first: it pins numpy's kernels, vap_bt/numerics.py, before anything loads numpy)
sys.path.insert(0, str(ROOT / "tests"))

from py_trees.common import Status  # noqa: E402

from web_viewer import (HANDLE_READY, HEIGHT, LOAD_HEIGHT, LOAD_WIDTH, TREE_PANEL, WIDTH, browser,  # noqa: E402
                        ink, load, recording_id, served, shot)

#: the status hues that count as a drawn tree (INVALID's grey carries no hue)
DRAWN = (Status.SUCCESS, Status.RUNNING, Status.FAILURE)


@dataclass
class Recording:
    path: Path
    label: str
    recording_id: str = ""
    last_tick: int = 0

    @property
    def mb(self) -> float:
        return self.path.stat().st_size / 1e6


@dataclass
class Run:
    label: str
    up_s: float | None = None
    first_tree_s: float | None = None
    loaded_s: float | None = None
    end_px: int | None = None
    note: str = ""

    def line(self) -> str:
        return (f"{self.label}: viewer up {fmt(self.up_s)} s, first tree {fmt(self.first_tree_s)} s, "
                f"whole recording {fmt(self.loaded_s)} s, end {'-' if self.end_px is None else self.end_px} px" + (f" ({self.note.strip()})" if self.note else ""))


@dataclass
class Summary:
    """One measure of several runs: its median and range."""

    values: list[float | None] = field(default_factory=list)

    def cell(self, digits: int = 1) -> str:
        got = [v for v in self.values if v is not None]
        if not got:
            return "-"
        text = f"{statistics.median(got):.{digits}f}"
        if len(got) > 1:
            text += f" [{min(got):.{digits}f}-{max(got):.{digits}f}]"
        missed = len(self.values) - len(got)
        return text + (f" ({missed} missed)" if missed else "")


def fmt(v: float | None) -> str:
    return "-" if v is None else f"{v:.1f}"


# ---- the command line ------------------------------------------------------------------------

def parse(argv: list[str] | None = None) -> argparse.Namespace:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rrd", type=Path, action="append", required=True,
                    help="a recording (repeat: the first is the baseline of the ratios)")
    ap.add_argument("--label", action="append", default=[],
                    help="a name per --rrd, in the same order (default: the file's stem)")
    ap.add_argument("--runs", type=int, default=5, help="runs per file (default 5)")
    ap.add_argument("--ink", type=int, default=150,
                    help="status-hued pixels in the tree panel that count as a drawn tree (default 150)")
    ap.add_argument("--poll", type=float, default=0.5, help="seconds between looks (default 0.5)")
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds each page may take (default 600)")
    ap.add_argument("--keep", type=Path, help="keep screenshots and the servers' logs in this folder")
    ap.add_argument("--end-check", action=argparse.BooleanOptionalAction, default=True,
                    help="after loading, screenshot the finished tree at full size (default on)")
    ap.add_argument("--by-entity", action="store_true", help="also print each file's bytes per entity path")
    args = ap.parse_args(argv)
    if args.label and len(args.label) != len(args.rrd):
        ap.error(f"{len(args.label)} --label for {len(args.rrd)} --rrd: give one per file, or none")
    args.label = args.label or [p.stem for p in args.rrd]
    if len(set(args.label)) != len(args.label):
        ap.error(f"labels must differ: {args.label}")
    if args.runs < 1:
        ap.error("--runs must be at least 1")
    missing = [str(p) for p in args.rrd if not p.is_file()]
    if missing:
        ap.error(f"no such file: {', '.join(missing)}")
    return args


def schedule(n_files: int, runs: int) -> list[list[int]]:
    """The files' order in each round: as given, then reversed, and so on."""
    order = list(range(n_files))
    return [order if r % 2 == 0 else order[::-1] for r in range(runs)]


# ---- the measures ----------------------------------------------------------------------------

def recording(path: Path, label: str) -> Recording:
    """The file's recording id and last tick (the largest ``tick`` of any of its chunks)."""
    import pyarrow.compute as pc
    from rerun.chunk import RrdReader

    last = 0
    for chunk in RrdReader(path).stream():
        if "tick" in chunk.timeline_names:
            batch = chunk.to_record_batch()
            last = max(last, pc.max(batch.column("tick")).as_py() or 0)
    return Recording(path, label, recording_id(path), last)


def tree_ink(image) -> int:
    """Status-hued pixels of ``image`` (a tree panel's pixels, as RGB)."""
    return sum(ink(image, s, box=(0, 0, image.shape[1], image.shape[0])) for s in DRAWN)


@contextmanager
def opened(rec: Recording, log: Path, width: int, height: int):
    """The file served, and a page of a fresh browser (its profile, some 45 MB, removed after it)
    at ``width`` x ``height``; yields (the viewer's URL, the page), not yet sent there."""
    with tempfile.TemporaryDirectory(prefix="chromium-") as profile, served(rec.path, log) as url, \
            browser(Path(profile), width, height) as page:
        yield url, page


def first_tree(rec: Recording, work: Path, args: argparse.Namespace, tag: str, run: Run) -> None:
    """Phase 1, in the full window: the seconds until the viewer's handle exists and until a
    screencast frame shows the tree panel with ``args.ink`` status-hued pixels."""
    import base64

    import cv2
    import numpy as np

    with opened(rec, work / f"rerun-{tag}-tree.log", WIDTH, HEIGHT) as (url, page):
        cdp = page.context.new_cdp_session(page)
        t0 = 0.0

        def on_frame(event: dict) -> None:
            cdp.send("Page.screencastFrameAck", {"sessionId": event["sessionId"]})
            if run.first_tree_s is not None:
                return
            png = base64.b64decode(event["data"])
            image = cv2.imdecode(np.frombuffer(png, np.uint8), cv2.IMREAD_COLOR)
            x0, y0, x1, y1 = TREE_PANEL
            if image is not None and tree_ink(cv2.cvtColor(image[y0:y1, x0:x1], cv2.COLOR_BGR2RGB)) >= args.ink:
                # the frame's swap time, else its arrival (which lags by the encoding and the transfer)
                run.first_tree_s = event.get("metadata", {}).get("timestamp", time.time()) - t0
                if args.keep:
                    (work / f"first-tree-{tag}.png").write_bytes(png)

        cdp.on("Page.screencastFrame", on_frame)
        cdp.send("Page.startScreencast", {"format": "png"})
        t0 = time.time()
        page.goto(url, wait_until="commit")
        while run.first_tree_s is None and time.time() - t0 < args.timeout:
            if run.up_s is None and page.evaluate(HANDLE_READY):
                run.up_s = time.time() - t0
            page.wait_for_timeout(args.poll * 1000)  # screencast frames are handled meanwhile
        cdp.send("Page.stopScreencast")
    if run.first_tree_s is None:
        run.note += f" no tree in {args.timeout:.0f} s;"


def whole_recording(rec: Recording, work: Path, args: argparse.Namespace, tag: str, run: Run) -> None:
    """Phase 2, in the test's small window, waited for as the test's ``viewer()`` does: the seconds
    until the viewer follows the recording to its last tick; then, at full size, the green ink of
    the finished tree."""
    with opened(rec, work / f"rerun-{tag}-load.log", LOAD_WIDTH, LOAD_HEIGHT) as (url, page):
        run.loaded_s, state = load(page, url, rec.last_tick, timeout_s=args.timeout, poll_s=args.poll)
        if run.loaded_s is None:
            run.note += f" not loaded in {args.timeout:.0f} s (viewer at {state and state.current});"
            return
        if state.recording_id != rec.recording_id:
            run.note += f" the viewer shows recording {state.recording_id}, not {rec.recording_id};"
        if args.end_check:
            page.set_viewport_size({"width": WIDTH, "height": HEIGHT})
            page.wait_for_timeout(2000)  # the last frames render, as in the test
            end = shot(page, work / f"end-{tag}.png")
            run.end_px = ink(end, Status.SUCCESS)


def measure(rec: Recording, work: Path, args: argparse.Namespace, tag: str) -> Run:
    run = Run(rec.label)
    first_tree(rec, work, args, tag, run)
    whole_recording(rec, work, args, tag, run)
    return run


# ---- the table -------------------------------------------------------------------------------

MEASURES = (("viewer up s", "up_s"), ("first tree s", "first_tree_s"), ("whole recording s", "loaded_s"))


def table(recs: list[Recording], rounds: list[dict[str, Run]]) -> str:
    """Medians [min-max] per file, then each file's ratio to the first, taken within each round."""
    head = ["recording", "MB", *(name for name, _ in MEASURES), "end px"]
    rows = []
    for rec in recs:
        runs = [r[rec.label] for r in rounds if rec.label in r]
        rows.append([rec.label, f"{rec.mb:.2f}", *(Summary([getattr(x, a) for x in runs]).cell() for _, a in MEASURES),
                     Summary([x.end_px for x in runs]).cell(0)])
    base = recs[0]
    for rec in recs[1:]:
        cells = [f"{rec.label}/{base.label}", f"{rec.mb / base.mb:.2f}"]
        for _, a in MEASURES:
            pairs = [(getattr(r[rec.label], a), getattr(r[base.label], a)) for r in rounds
                     if rec.label in r and base.label in r]
            cells.append(Summary([x / y if x is not None and y else None for x, y in pairs]).cell(2))
        rows.append(cells + [""])
    widths = [max(len(str(row[k])) for row in [head, *rows]) for k in range(len(head))]
    line = lambda row: "  ".join(str(c).ljust(w) if k == 0 else str(c).rjust(w)  # noqa: E731
                                 for k, (c, w) in enumerate(zip(row, widths)))
    return "\n".join([line(head), line(["-" * w for w in widths]), *map(line, rows)])


def by_entity(path: Path) -> str:
    """Bytes per entity path: Arrow in memory, and the chunk's IPC message after LZ4 (what the .rrd
    stores, near enough: each chunk is one compressed message, its schema included)."""
    import pyarrow as pa
    from rerun.chunk import RrdReader

    raw, packed, chunks, rows = Counter(), Counter(), Counter(), Counter()
    for chunk in RrdReader(path).stream():
        batch, e = chunk.to_record_batch(), chunk.entity_path
        sink = pa.BufferOutputStream()
        with pa.ipc.new_stream(sink, batch.schema) as w:
            w.write_batch(batch)
        raw[e] += batch.nbytes
        packed[e] += len(pa.compress(sink.getvalue(), codec="lz4", asbytes=True))
        chunks[e] += 1
        rows[e] += chunk.num_rows
    total = sum(packed.values()) or 1
    out = [f"{path} ({path.stat().st_size / 1e6:.2f} MB on disk; recording store, blueprints left out)",
           f"  {'entity':34} {'chunks':>6} {'rows':>6} {'MB arrow':>9} {'MB lz4':>7} {'share':>6}"]
    for e, b in packed.most_common():
        out.append(f"  {e:34} {chunks[e]:6} {rows[e]:6} {raw[e] / 1e6:9.2f} {b / 1e6:7.2f} {100 * b / total:5.1f}%")
    out.append(f"  {'total':34} {sum(chunks.values()):6} {sum(rows.values()):6} {sum(raw.values()) / 1e6:9.2f} "
               f"{total / 1e6:7.2f}")
    return "\n".join(out)


def main(argv: list[str] | None = None) -> int:
    args = parse(argv)
    recs = [recording(p, label) for p, label in zip(args.rrd, args.label)]
    for rec in recs:
        print(f"{rec.label}: {rec.path} {rec.mb:.2f} MB, recording {rec.recording_id}, last tick {rec.last_tick}",
              file=sys.stderr)
    if args.keep:
        args.keep.mkdir(parents=True, exist_ok=True)
    rounds: list[dict[str, Run]] = []
    with tempfile.TemporaryDirectory(prefix="viz-load-") as tmp:
        work = args.keep or Path(tmp)
        for r, order in enumerate(schedule(len(recs), args.runs)):
            rounds.append({})
            for k in order:
                run = measure(recs[k], work, args, f"{recs[k].label}-{r}")
                rounds[-1][recs[k].label] = run
                print(f"[round {r + 1}/{args.runs}] {run.line()}", file=sys.stderr)
    print(f"web viewer in headless chromium (SwiftShader); first tree in {WIDTH}x{HEIGHT}, whole recording in "
          f"{LOAD_WIDTH}x{LOAD_HEIGHT}; {args.runs} runs per file; seconds from navigation, median [min-max]")
    print(table(recs, rounds))
    if args.by_entity:
        for rec in recs:
            print()
            print(by_entity(rec.path))
    return 0


if __name__ == "__main__":
    sys.exit(main())
