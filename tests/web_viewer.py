"""A recording in rerun's web viewer, served on loopback and opened in Debian's headless chromium.

Shared by the live-view test (tests/test_live_view.py) and the loading bench
(tools/bench/viz_load.py); Playwright, which drives the browser, is a ``test`` extra.

* ``served``: ``rerun --serve-web --bind 127.0.0.1`` (web viewer and gRPC proxy on loopback only,
  checked in ``/proc/net/tcp``); yields the page's URL.
* ``browser``: Debian's ``chromium``, headless, driven by Playwright (which cannot download
  browsers here, hence ``executable_path``), in a fresh profile. WebGL runs on SwiftShader
  (``--use-angle=swiftshader --enable-unsafe-swiftshader``); ``--disable-gpu`` is left out: it is
  not needed (tried: the viewer draws with or without it). Every request that is not to 127.0.0.1
  (fonts, telemetry, the version check) is aborted by the page's router, so nothing leaves the
  machine.
* ``ViewerState``: what the viewer says it shows (``window._handle.viewer_state()``, a protobuf);
  ``loaded``: it names the recording's id and its ``tick`` timeline has reached the last tick.
* ``load``: the page sent to the viewer, and the seconds until the recording has loaded;
  ``viewer``: all of it together, for a test: the page once the recording has loaded (in a small
  window, then enlarged to ``WIDTH`` x ``HEIGHT``).
* ``shot``, ``ink``, ``ink_box`` and ``read_text``: a screenshot; how many of its pixels in the
  tree panel carry a status's hue (the tree's labels are drawn in ``STATUS_COLOURS``); where
  anything is drawn in a box; what tesseract reads in a box.
"""

from __future__ import annotations

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
from py_trees.common import Status

from vap_bt.viz.tree_graph import STATUS_COLOURS

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
#: the small window ``viewer`` loads a recording in, and how long it waits for it
LOAD_WIDTH, LOAD_HEIGHT = 320, 240
LOAD_TIMEOUT_S = 240


# ---- served on loopback ----------------------------------------------------------------------

def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_listening(port: int, timeout_s: float = 30.0) -> None:
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        with socket.socket() as s:
            if s.connect_ex(("127.0.0.1", port)) == 0:
                return
        time.sleep(0.2)
    raise AssertionError(f"nothing listens on 127.0.0.1:{port} after {timeout_s:.0f} s")


def listeners(port: int) -> list[str]:
    """Local addresses of the TCP sockets listening on ``port`` (Linux /proc)."""
    out = []
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        if not os.path.exists(table):
            continue
        for line in Path(table).read_text().splitlines()[1:]:
            local, state = line.split()[1], line.split()[3]
            addr, p = local.rsplit(":", 1)
            if int(p, 16) == port and state == "0A":  # LISTEN
                out.append(addr)
    return out


@contextmanager
def served(rrd: Path, log: Path):
    """The web viewer and the recording's gRPC proxy, on loopback only; yields the page's URL."""
    grpc, web = free_port(), free_port()
    with log.open("w") as out:
        proc = subprocess.Popen([str(BIN / "rerun"), "--serve-web", "--bind", "127.0.0.1", "--port", str(grpc),
                                 "--web-viewer-port", str(web), str(rrd)], stdin=subprocess.DEVNULL, stdout=out,
                                stderr=subprocess.STDOUT, start_new_session=True, env={**os.environ, "RUST_LOG": "warn"})
    try:
        wait_listening(grpc)
        wait_listening(web)
        if os.path.exists("/proc/net/tcp"):
            assert listeners(grpc) == ["0100007F"] and listeners(web) == ["0100007F"], "must listen on 127.0.0.1 only"
        yield f"http://127.0.0.1:{web}/?url=rerun%2Bhttp%3A%2F%2F127.0.0.1%3A{grpc}%2Fproxy"
    finally:
        os.killpg(proc.pid, signal.SIGTERM)  # the launcher and the viewer binary it started
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)


# ---- in headless chromium --------------------------------------------------------------------

@contextmanager
def browser(profile: Path, width: int = WIDTH, height: int = HEIGHT):
    """A page of headless chromium in a fresh profile (``profile``, an empty folder) whose requests
    go to 127.0.0.1 only; the browser closes on leaving."""
    if not os.access(CHROMIUM, os.X_OK):
        raise FileNotFoundError(f"{CHROMIUM} is missing: tools/setup.sh installs Debian's chromium")
    from playwright.sync_api import sync_playwright

    with sync_playwright() as pw:
        context = pw.chromium.launch_persistent_context(
            str(profile), executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS,
            viewport={"width": width, "height": height})
        try:
            page = context.new_page()
            page.route("**/*", lambda r: r.continue_() if r.request.url.startswith("http://127.0.0.1:") else r.abort())
            yield page
        finally:
            context.close()


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


HANDLE_READY = "() => window._handle !== undefined"


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

    def loaded(self, last_tick: int) -> bool:
        """The ``tick`` timeline has reached ``last_tick``, and the viewer follows it there."""
        return self.ends.get("tick") == last_tick and self.current == ("tick", last_tick)


def recording_id(rrd: Path) -> str:
    from rerun.chunk import RrdReader

    return RrdReader(rrd).recordings()[0].recording_id


def load(page, url: str, last_tick: int, timeout_s: float = LOAD_TIMEOUT_S, poll_s: float = 1.0):
    """Sends the page to the viewer's ``url`` and waits until the recording has loaded (``loaded``).
    Returns the seconds from navigation until then (None if ``timeout_s`` passed first) and the
    viewer's last state. The waits let Playwright run the page's router meanwhile."""
    t0 = time.monotonic()
    page.goto(url)
    page.wait_for_function(HANDLE_READY, timeout=60_000)
    state = None
    while time.monotonic() - t0 < timeout_s:
        state = ViewerState.read(page)
        if state.loaded(last_tick):
            return time.monotonic() - t0, state
        page.wait_for_timeout(poll_s * 1000)
    return None, state


@contextmanager
def viewer(rrd: Path, last_tick: int, tmp_path: Path):
    """The recording in the web viewer in headless chromium; yields the page once it has loaded:
    the viewer names the recording's id and follows its tick timeline to ``last_tick``."""
    expected = recording_id(rrd)
    profile = Path(tempfile.mkdtemp(prefix="chromium-", dir=tmp_path))
    with served(rrd, tmp_path / "rerun.log") as url, browser(profile) as page:
        # the viewer ingests the recording a little per drawn frame, and software rendering draws
        # a full-size frame slowly: it loads in a small window, then takes the test's size
        page.set_viewport_size({"width": LOAD_WIDTH, "height": LOAD_HEIGHT})
        seconds, state = load(page, url, last_tick)
        assert state is not None and state.recording_id == expected, state
        assert seconds is not None and state.loaded(last_tick), state
        page.set_viewport_size({"width": WIDTH, "height": HEIGHT})
        time.sleep(2.0)  # let the last frames render
        yield page


# ---- reading its pixels ----------------------------------------------------------------------

def shot(page, path: Path) -> np.ndarray:
    """A screenshot of the page, saved at ``path``, as RGB."""
    import cv2

    # a full-size frame drawn by SwiftShader took over Playwright's default 30 s on this 2-core
    # machine at a load of 13 (other suites running); when it is quick, this waits no longer
    page.screenshot(path=str(path), timeout=120_000)
    return cv2.cvtColor(cv2.imread(str(path)), cv2.COLOR_BGR2RGB)


def ink(image: np.ndarray, status: Status, box=TREE_PANEL) -> int:
    """Pixels in ``box`` of the hue of ``status``'s colour: labels are thin anti-aliased text, so
    their pixels are judged by hue (within 12 degrees) and saturation, not by exact colour."""
    import cv2

    x0, y0, x1, y1 = box
    hsv = cv2.cvtColor(np.ascontiguousarray(image[y0:y1, x0:x1, :3]), cv2.COLOR_RGB2HSV).astype(int)
    want = int(cv2.cvtColor(np.uint8([[STATUS_COLOURS[status]]]), cv2.COLOR_RGB2HSV)[0, 0, 0])
    near = np.minimum(np.abs(hsv[..., 0] - want), 180 - np.abs(hsv[..., 0] - want)) <= 6  # OpenCV hue: 0..179
    return int((near & (hsv[..., 1] > 100) & (hsv[..., 2] > 80)).sum())


def ink_box(image: np.ndarray, box) -> tuple[int, int, int, int]:
    """Bounding box, in window pixels, of what is drawn in ``box`` on the view's white background:
    label frames, edges and arrowheads (dark) and label text (coloured or grey)."""
    x0, y0, x1, y1 = box
    ys, xs = np.nonzero(image[y0:y1, x0:x1, :3].min(axis=2) < 200)
    return x0 + int(xs.min()), y0 + int(ys.min()), x0 + int(xs.max()), y0 + int(ys.max())


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
