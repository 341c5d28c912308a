"""The simulated VLM behind a local OpenAI-compatible endpoint: offline runs go through the real client.

``vap-bt run TASK --vlm sim-http`` starts this server on the world's side (127.0.0.1, a free
port) and hands the executive nothing but the ``openai`` backend
(:class:`~vap_bt.perception.backends.openai_compat.OpenAICompatVLM`) pointed at it: every
question crosses HTTP as it would to vLLM — the appendix prompt, the frame as a PNG data URL,
the answer constrained to its options, logprobs asked for — and the reply is read strictly by the
same code that reads a real model's. The request and reply formats are in
:mod:`vap_bt.sim.chat_completions`.

The server is shown what a real model is shown, and works out the rest the way the simulated
model needs it:

* **which capture** — the image is decoded and its pixels hashed; the world's capture log knows
  which capture carried exactly those pixels (:meth:`~vap_bt.sim.captures.CaptureLog.by_image`).
  PNG is lossless, so the pixels are the camera's to the last bit; an image encoded lossily
  (JPEG) does not match and is an unknown image. Several captures carry the same pixels when
  the robot looks again without anything having moved (consecutive checks from one pose, a
  viewpoint move that failed); the latest of them is taken, which is the one being asked about:
  the executive asks all of a frame's questions before it captures the next;
* **which question** — the prompt is read back to its purpose and atom with the executive's own
  wording (:class:`~vap_bt.perception.lookup.QuestionLookup` over the perception profile the run
  uses) and rebuilt as the :class:`~vap_bt.perception.vlm.Query` the executive asked; unless the
  rebuilt prompt is exactly the one received, the prompt is unread;
* **the answer** — :meth:`SimVLM.answer <vap_bt.sim.sim_vlm.SimVLM.answer>` on that record: the
  same seeded draws as the in-process ``--vlm sim``, so one seed gives the same answers either
  way. Its stated probability becomes the logprobs; a viewpoint answer states none
  (``logprobs: null``) rather than an invented one.

What it cannot identify it does not answer truly. An **unknown image** (not a capture the world
still holds, a lossy copy, a URL to fetch, several images) or an **unread prompt** (not an
appendix prompt over the profile's wording: an action-level question — whose implied facts depend
on arguments its phrase leaves out and on the state the plan expects, so that a run refuses the
action-level strategies over this endpoint (docs/perception.md) —, a typo) gets what a model
might say to a picture or a question it cannot make sense of: constrained to choices, a seeded
uniform guess among them with equal logprobs for every choice (a guess stated as one); otherwise
a hedge, "I can't tell from this image.", which the client reads as no answer. The same goes for
a question the simulated model abstains on (it cannot see the relation at all): constrained to
choices it guesses among them with equal logprobs, unconstrained it hedges. A text-only request
(goal parsing, writing paraphrases) gets "I can only answer questions about an image.": the
simulated model neither parses goals nor writes paraphrases, so a profile's missing paraphrases
come from its templates, as with ``--vlm sim``. Every such case is counted (``describe()["counts"]``,
printed in the report).

``latency_s`` is added to every answered request (a model's inference time, for benchmarks);
requests are served each on its own thread, so questions in flight at once wait concurrently, as
on a real server with batching.
"""

from __future__ import annotations

import json
import logging
import random
import socket
import threading
import time
from collections import Counter
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any

from vap_bt.domain.task import PlanningTask
from vap_bt.perception import prompts
from vap_bt.perception.backends.image import rgb_sha1
from vap_bt.perception.lookup import QuestionLookup
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.perception.verification import objects_of, sufficiency_query, target_of, viewpoint_query
from vap_bt.perception.vlm import Query
from vap_bt.sim.captures import CaptureLog, CaptureRecord
from vap_bt.sim.chat_completions import (
    BadRequest, ChatRequest, Said, completion_body, decode_image, error_body, read_request)
from vap_bt.sim.sim_vlm import SimVLM

log = logging.getLogger("vap_bt.sim.vlm_endpoint")

MODEL = "vap-bt-sim-vlm"
HEDGE = "I can't tell from this image."
TEXT_ONLY = "I can only answer questions about an image."
YES_NO = ("yes", "no")


class SimVLMEndpoint:
    """``vlm`` served as OpenAI chat completions at :attr:`url` (see the module docstring).

    ``captures`` is the world's capture log; :meth:`read_questions` gives the endpoint the
    wording of the run's questions (until then every image question is unread). Start with
    :meth:`start` (or ``with``), stop with :meth:`close`."""

    def __init__(self, vlm: SimVLM, captures: CaptureLog, latency_s: float = 0.0, model: str = MODEL,
                 port: int = 0) -> None:
        if not latency_s >= 0.0:
            raise ValueError(f"latency_s must be >= 0, got {latency_s}")
        self.vlm, self.captures, self.latency_s, self.model = vlm, captures, latency_s, model
        self.lookup: QuestionLookup | None = None
        self.counts: Counter[str] = Counter()
        self._lock = threading.Lock()
        self._httpd = ThreadingHTTPServer(("127.0.0.1", port), _handler(self))
        self._httpd.daemon_threads = True
        self._httpd.block_on_close = False  # a request still sleeping out its latency is not waited for
        self._thread: threading.Thread | None = None

    # --- life cycle -----------------------------------------------------------------------------
    @property
    def url(self) -> str:
        """The API root, as ``--vlm-url`` takes it."""
        return f"http://127.0.0.1:{self._httpd.server_address[1]}/v1"

    def start(self) -> "SimVLMEndpoint":
        """Serve on a daemon thread (once; a second call does nothing); returns self."""
        if self._thread is None:
            self._thread = threading.Thread(target=self._httpd.serve_forever, kwargs={"poll_interval": 0.05},
                                            name="sim-vlm-endpoint", daemon=True)
            self._thread.start()
        return self

    def close(self) -> None:
        if self._thread is not None:
            self._httpd.shutdown()
            self._thread.join(timeout=5.0)
            self._thread = None
        self._httpd.server_close()

    def __enter__(self) -> "SimVLMEndpoint":
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.close()

    def reset(self, seed: int) -> None:
        """A new episode: the model's draws follow ``seed``, the counts start again."""
        self.vlm.reseed(seed)
        with self._lock:
            self.counts.clear()

    def read_questions(self, profile: PerceptionProfile, task: PlanningTask) -> None:
        """Understand questions in ``profile``'s words about ``task``'s objects."""
        self.lookup = QuestionLookup(profile, task.objects, task.knowledge)

    def describe(self) -> dict:
        """Where it listens, the model it answers as, requests counted by outcome and the simulated VLM's
        parameters, for the report."""
        with self._lock:
            counts = dict(self.counts)
        return {"url": self.url, "model": self.model, "latency_s": self.latency_s, "counts": counts,
                "sim": self.vlm.describe(),
                "unidentified": "an unknown image or an unread prompt: a seeded uniform guess among the "
                                "constrained choices (equal logprobs), else the hedge " + repr(HEDGE)}

    # --- one request ----------------------------------------------------------------------------
    def respond(self, body: Any) -> tuple[int, dict]:
        """``(status, JSON reply)`` to a parsed request body (no latency added here)."""
        try:
            req = read_request(body, self.model)
        except BadRequest as e:
            self._count("bad_request")
            return e.status, e.body()
        return 200, completion_body(req, self._say(req), self.model)

    def _say(self, req: ChatRequest) -> Said:
        if not req.images:
            self._count("text_only")
            return Said(TEXT_ONLY)
        record = self._record(req.images)
        query = self._query(req.prompt)
        if record is None or query is None:
            self._count("unknown_image" if record is None else "unread_prompt")
            return self._unidentified(req)
        answer = self.vlm.answer(query, record)
        self._count("answered")
        options = query.options or YES_NO
        text = answer.raw
        if req.choices is not None:  # constrained decoding: the reply is one of the choices
            fitting = [c for c in req.choices if c.lower() == text.lower()]
            if not fitting:  # an abstention, forced by the constraint into a guess stated as one
                self._count("abstention_forced" if answer.value is None else "constraint_without_answer")
                return self._unidentified(req)
            text, options = fitting[0], req.choices
        if answer.confidence is None or len(options) != 2:
            return Said(text)
        other = next(o for o in options if o != text)
        return Said(text, {text: answer.confidence, other: 1.0 - answer.confidence})

    def _record(self, images: tuple[str, ...]) -> CaptureRecord | None:
        if len(images) != 1:  # which picture would the question be about?
            return None
        rgb = decode_image(images[0])
        return None if rgb is None else self.captures.by_image(rgb_sha1(rgb))

    def _query(self, prompt: str) -> Query | None:
        """The query the executive asked with ``prompt``, rebuilt; None when it is not one."""
        lookup = self.lookup
        parsed = lookup.parse_prompt(prompt) if lookup is not None else None
        if parsed is None:
            return None
        purpose, question = parsed
        atom = lookup.atom_of_question(question)
        if atom is None:
            return None
        if purpose == "sufficiency":
            query = sufficiency_query(atom, question)
        elif purpose == "viewpoint":
            query = viewpoint_query(atom, question, target_of(atom))
        else:
            query = Query(prompts.predicate_query(question), about=(atom,), objects=objects_of(atom))
        return query if query.prompt == prompt else None

    def _unidentified(self, req: ChatRequest) -> Said:
        """What a model says about what it cannot make out (see the module docstring)."""
        if req.choices is None:
            return Said(HEDGE)
        rng = random.Random(f"{self.vlm.seed}|unidentified|{'|'.join(req.images)}|{req.prompt}")
        return Said(rng.choice(req.choices), {c: 1.0 / len(req.choices) for c in req.choices})

    def _count(self, what: str) -> None:
        with self._lock:
            self.counts[what] += 1


def _handler(endpoint: SimVLMEndpoint) -> type[BaseHTTPRequestHandler]:
    class Handler(BaseHTTPRequestHandler):
        """POST {root}/chat/completions and GET {root}/models; nothing else is served."""

        protocol_version = "HTTP/1.1"  # keep-alive: the client pools connections

        def setup(self) -> None:
            super().setup()
            # headers and body leave in two writes: without this, Nagle's algorithm holds the body
            # for the client's delayed ACK (40 ms a reply on Linux)
            self.connection.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)

        def do_POST(self) -> None:  # noqa: N802 (http.server's naming)
            raw = self.rfile.read(int(self.headers.get("content-length") or 0))
            if not self.path.rstrip("/").endswith("/chat/completions"):
                return self._send(404, error_body(f"no route {self.path}", "NotFoundError", None, 404))
            try:
                body = json.loads(raw)
            except ValueError:
                return self._send(400, error_body("the body is not JSON", "BadRequestError", None, 400))
            status, reply = endpoint.respond(body)
            if status == 200 and endpoint.latency_s:
                time.sleep(endpoint.latency_s)
            self._send(status, reply)

        def do_GET(self) -> None:  # noqa: N802
            if self.path.rstrip("/").endswith("/models"):
                return self._send(200, {"object": "list", "data": [
                    {"id": endpoint.model, "object": "model", "owned_by": "vap_bt"}]})
            self._send(404, error_body(f"no route {self.path}", "NotFoundError", None, 404))

        def _send(self, status: int, payload: dict) -> None:
            data = json.dumps(payload).encode()
            self.send_response(status)
            self.send_header("content-type", "application/json")
            self.send_header("content-length", str(len(data)))
            self.end_headers()
            self.wfile.write(data)

        def log_message(self, fmt: str, *args: Any) -> None:  # requests are in the client's records
            log.debug("sim VLM endpoint: " + fmt, *args)

    return Handler
