"""A VLM served over HTTP: the one way every hosted backend asks, reads and records a query.

:meth:`HttpVLM.ask` is a template. A protocol (:mod:`.openai_compat`, :mod:`.gemini`) says only
where to POST, how to put the prompt, the frame and the options into a request, how to read its
reply, and which headers carry the key. Everything else is done once, here:

* the frame is encoded (lossless PNG, cached per frame), a frame without pixels is an abstention
  without a request;
* the request is sent through the shared :class:`~.http.Transport` (timeout, retries, deadline);
* *optional features* — constrained decoding, logprobs, thinking off — are sent by default, and
  a server that rejects one with a 400 naming it gets the request again without it; the feature
  stays off for that backend (it is listed in ``describe()["dropped"]``). Servers that ignore
  unknown fields (vLLM, Ollama, llama.cpp) simply answer;
* the reply is read strictly (:mod:`.reply`) and every query is recorded (:mod:`.record`).

:meth:`HttpVLM.paraphrase` is the protocol's optional part: one text-only request (as
:meth:`HttpVLM.complete` sends) asking the model to write question templates for a
predicate nobody wrote paraphrases for; its reply is checked line by line and recorded too.

``ask`` never raises: whatever goes wrong — the network, the server, the reply, a bug here — is
an :class:`~vap_bt.perception.vlm.Answer` with ``value=None`` and a record saying why. It is
safe to call from many threads at once.

``ask`` never raising means a server that is gone would have an episode go on without eyes, every
check an abstention after its retries (3.5 s each against a closed port, 90 s against one that
accepts and never answers), for as long as its budgets last. So the backend remembers, in
:attr:`HttpVLM.silent`, why the last query got no response at all once its retries were spent
(any response, even an error status, clears it), and the run wraps the backend in
:class:`StopWhenSilent`, which turns that into a :class:`~vap_bt.errors.TransportError`: the
episode ends "transport down" with its report, as for any other part that went away.

:meth:`HttpVLM.complete` asks for free text (goal parsing, the VLM-planner's next action): the
same template without options, returning the reply's text as a
:class:`~vap_bt.perception.vlm.Completion`; the frame, when one is given and has pixels, goes with
the prompt as in :meth:`HttpVLM.ask`.
"""

from __future__ import annotations

import logging
import threading
import time
from dataclasses import dataclass
from typing import Any, Callable

import httpx
import numpy as np

from vap_bt.errors import TransportError
from vap_bt.perception.backends.http import Exchange, RetryPolicy, Transport, retry_after
from vap_bt.perception.backends.image import EncodedImage, ImageCache
from vap_bt.perception.backends.record import RequestLog, RequestRecord
from vap_bt.perception.backends.reply import (
    YES_NO, TokenChoice, is_refusal, option_confidence, option_name, read_answer)
from vap_bt.perception.paraphrase import read_generated, request_prompt
from vap_bt.perception.vlm import Answer, Completion, Purpose, Query
from vap_bt.robot.frame import Frame

log = logging.getLogger("vap_bt.vlm")

ERROR_BODY_CHARS = 2000  # of an error body kept in a record: enough for any server's message
#: s a run waits for a VLM server to answer at all before saying none does: a server that is up
#: answers any request at once, if only with an error (a model still loading does not hold up its
#: HTTP layer)
PREFLIGHT_S = 5.0


@dataclass(frozen=True)
class Feature:
    """An optional part of a request, dropped if the server rejects it (400 naming a marker)."""

    name: str
    markers: tuple[str, ...]  # lower-case words a rejection of this feature names


@dataclass(frozen=True)
class Reply:
    """A protocol's reply, read into what the template needs."""

    text: str | None
    finish_reason: str | None = None
    refused: str | None = None  # the server's own refusal or block, in words
    tokens: tuple[TokenChoice, ...] = ()


def dig(data: Any, *path: str | int) -> Any:
    """``data[p0][p1]...``, or None where the path does not exist (replies may be any shape)."""
    for key in path:
        if isinstance(key, int) and isinstance(data, list) and -len(data) <= key < len(data):
            data = data[key]
        elif isinstance(key, str) and isinstance(data, dict):
            data = data.get(key)
        else:
            return None
    return data


def options_of(query: Query) -> tuple[str, ...]:
    """The answers a query allows, lower-cased: yes/no for a yes/no question, else its options."""
    return YES_NO if query.kind == "yesno" else tuple(o.lower() for o in query.options)


class HttpVLM:
    """Base of the HTTP backends: ``ask(query, frame) -> Answer``, ``describe()``, ``requests``."""

    name = "http"
    features: tuple[Feature, ...] = ()
    #: finish reasons meaning the reply was cut off at the token budget
    truncated: frozenset[str] = frozenset()

    def __init__(self, url: str, model: str, api_key: str = "", policy: RetryPolicy = RetryPolicy(),
                 max_tokens: int = 8, top_logprobs: int = 5,
                 on_request: Callable[[RequestRecord], None] | None = None, text_max_tokens: int = 400) -> None:
        self.url = url.rstrip("/")
        self.model = model
        self.policy = policy
        self.max_tokens = max_tokens
        self.top_logprobs = top_logprobs  # 0: logprobs not asked for
        self.text_max_tokens = text_max_tokens  # of a text-only reply: a goal of a dozen atoms, or five paraphrases, fits
        self._has_key = bool(api_key)
        self._log = RequestLog(on_request)
        self._images = ImageCache()
        self._transport = Transport(policy, self.auth_headers(api_key), self.retry_hint)
        self._dropped: set[str] = set()
        self._lock = threading.Lock()
        #: why the last query had no response at all after its retries (unreachable, timeout), or
        #: None once any response came (see the module docstring)
        self.silent: str | None = None

    # --- what a protocol says -------------------------------------------------------------------
    def endpoint(self) -> str:
        """The URL to POST a query to (the protocol's path under ``url``)."""
        raise NotImplementedError

    def auth_headers(self, api_key: str) -> dict[str, str]:
        """The headers that carry ``api_key`` (none when it is empty), as the protocol names them."""
        raise NotImplementedError

    def request(self, prompt: str, image: EncodedImage | None, options: tuple[str, ...],
                features: frozenset[str]) -> dict:
        """The request body; ``features`` names the optional features to include. Without
        options it asks for free text: no answer constraint, no logprobs, ``text_max_tokens``,
        and the image part only when there is an image (a text-only request has none)."""
        raise NotImplementedError

    def read(self, data: Any) -> Reply:
        """The reply body (parsed JSON) read as the protocol words it: text, finish reason, logprobs, or
        why there is none."""
        raise NotImplementedError

    def retry_hint(self, response: httpx.Response) -> float | None:
        """Seconds the server asks to wait before a retry, or None; the ``Retry-After`` header unless the
        protocol has a richer hint."""
        return retry_after(response)

    def unreachable(self, timeout_s: float = PREFLIGHT_S) -> str | None:
        """Why no server answers at the backend's URL (a sentence), or None when one does. Asked
        once before an episode: a wrong ``--vlm-url`` is then one line within seconds, not every
        query's retries spent one after the other (39 warnings in 150 s, the run still going)."""
        return self._transport.probe(self.url, timeout_s)

    # --- the template ---------------------------------------------------------------------------
    def ask(self, query: Query, frame: Frame) -> Answer:
        rgb, frame_id = frame.rgb, frame.frame_id
        rec = RequestRecord(backend=self.name, model=self.model, purpose=query.purpose, kind=query.kind,
                            prompt=query.prompt, options=options_of(query), frame_id=frame_id)
        self._recorded(rec, lambda deadline: self._ask(query, rgb, rec, deadline))
        raw = rec.reply if rec.status == 200 else ""  # an error body is for the record, not an answer's text
        return Answer(raw=raw, value=rec.value, confidence=rec.confidence, latency_s=rec.latency_s)

    def complete(self, prompt: str, purpose: Purpose = "goal", frame: Frame | None = None) -> Completion:
        """Ask ``prompt`` and return the model's free text (goal parsing; with ``frame``, the
        VLM-planner's next action about what the camera shows).

        The same transport, timeouts, retries, feature dropping and records as :meth:`ask`; the
        request carries no answer constraint and no logprobs, and has the larger
        ``text_max_tokens`` budget. The frame's picture goes with it when it has one (a frame
        without pixels leaves the request text-only: the prompt still says what is known). A reply
        cut off at that budget is not an answer (outcome ``unparsed``): a goal missing its tail
        would otherwise pass for a whole one. Never raises.
        """
        rec = RequestRecord(backend=self.name, model=self.model, purpose=purpose, kind="text",
                            prompt=prompt, options=(), frame_id=frame.frame_id if frame is not None else "")
        rgb = frame.rgb if frame is not None else None
        self._recorded(rec, lambda deadline: self._complete(prompt, rgb, rec, deadline))
        text = rec.reply if rec.outcome == "answer" else None
        return Completion(text=text, outcome=rec.outcome, error=rec.error, latency_s=rec.latency_s)

    def _recorded(self, rec: RequestRecord, work: Callable[[float], None]) -> None:
        """Run ``work(deadline)`` to fill ``rec``, time it and log it; nothing escapes."""
        t0 = time.perf_counter()
        try:
            work(time.monotonic() + self.policy.deadline_s)
        except Exception as e:  # the contract: an abstention, never an exception out of ask
            log.exception("VLM %s: query failed", self.name)
            rec.outcome, rec.value, rec.confidence, rec.error = "error", None, None, f"{type(e).__name__}: {e}"
        rec.latency_s = time.perf_counter() - t0
        rec.dropped = self.dropped
        self._log.add(rec)

    def _ask(self, query: Query, rgb: np.ndarray | None, rec: RequestRecord, deadline: float) -> None:
        if rgb is None:
            rec.outcome, rec.error = "no_image", "the frame has no pixels to show"
            return
        if not rec.options:
            rec.outcome, rec.error = "error", "a choice query without options"
            return
        try:
            image = self._images.encode(rgb)
        except ValueError as e:  # not an (H, W, 3) uint8 image
            rec.outcome, rec.error = "no_image", str(e)
            return
        rec.frame_sha1, rec.image_size = image.sha1, (image.width, image.height)
        reply = self._exchange(query.prompt, image, rec.options, deadline, rec)
        if reply is not None:
            self._interpret(query, reply, rec)

    def _complete(self, prompt: str, rgb: np.ndarray | None, rec: RequestRecord, deadline: float) -> None:
        image = None
        if rgb is not None:
            try:
                image = self._images.encode(rgb)
            except ValueError as e:  # not an (H, W, 3) uint8 image: nothing to show, nothing sent
                rec.outcome, rec.error = "no_image", str(e)
                return
            rec.frame_sha1, rec.image_size = image.sha1, (image.width, image.height)
        reply = self._exchange(prompt, image, (), deadline, rec)
        if reply is None:
            return
        rec.reply, rec.finish_reason = reply.text or "", reply.finish_reason
        if reply.refused:
            rec.outcome, rec.error = "refusal", reply.refused
        elif not rec.reply.strip():
            rec.outcome, rec.error = "empty", "the reply has no text"
        elif reply.finish_reason in self.truncated:
            rec.outcome, rec.error = "unparsed", f"the reply was cut off at the token budget ({self.text_max_tokens})"
        else:
            rec.outcome, rec.value = "answer", rec.reply.strip()

    def _exchange(self, prompt: str, image: EncodedImage | None, options: tuple[str, ...], deadline: float,
                  rec: RequestRecord) -> Reply | None:
        """POST and read the protocol's reply; None (with ``rec`` saying why) when there is none."""
        ex = self._post(prompt, image, options, deadline, rec)
        rec.status = ex.status
        self.silent = f"{ex.failure} after {ex.attempts} attempt(s): {ex.detail}" if ex.status is None else None
        if ex.failure:
            rec.outcome, rec.error, rec.reply = ex.failure, ex.detail, ex.text[:ERROR_BODY_CHARS]
            return None
        if ex.status != 200:
            rec.outcome, rec.error, rec.reply = "http_error", f"HTTP {ex.status}", ex.text[:ERROR_BODY_CHARS]
            return None
        data = ex.json()
        if not isinstance(data, dict):
            rec.outcome, rec.error, rec.reply = "malformed", "the body is not a JSON object", ex.text[:ERROR_BODY_CHARS]
            return None
        return self.read(data)

    def _post(self, prompt: str, image: EncodedImage | None, options: tuple[str, ...], deadline: float,
              rec: RequestRecord) -> Exchange:
        """POST, and once more without each optional feature the server rejects (bounded by their number)."""
        while True:
            sent = self._enabled()
            ex = self._transport.post(self.endpoint(), self.request(prompt, image, options, sent), deadline)
            rec.attempts += ex.attempts
            # each round trip sends strictly fewer features than the one before: the loop ends
            rejected = self._rejected(ex.text, sent) if ex.status == 400 else set()
            if not rejected:
                return ex
            log.warning("VLM %s at %s rejects %s: sending without", self.name, self.url, sorted(rejected))
            with self._lock:
                self._dropped |= rejected

    def _interpret(self, query: Query, reply: Reply, rec: RequestRecord) -> None:
        rec.reply, rec.finish_reason = reply.text or "", reply.finish_reason
        if reply.refused:
            rec.outcome, rec.error = "refusal", reply.refused
        elif not rec.reply.strip():
            rec.outcome, rec.error = "empty", "the reply has no text"
        elif is_refusal(rec.reply):
            rec.outcome, rec.error = "refusal", "the model refused or hedged"
        else:
            rec.value = read_answer(rec.reply, query.kind, rec.options)
            rec.outcome = "answer" if rec.value is not None else "unparsed"
            rec.confidence = option_confidence(reply.tokens, rec.options, option_name(rec.value))

    def _enabled(self) -> frozenset[str]:
        with self._lock:
            return frozenset(f.name for f in self.features if f.name not in self._dropped)

    def _rejected(self, error_body: str, sent: frozenset[str]) -> set[str]:
        """The features of this request that a 400's body names."""
        text = error_body.lower()
        return {f.name for f in self.features if f.name in sent and any(m in text for m in f.markers)}

    # --- paraphrases (the optional part of the VLM protocol) ------------------------------------
    def paraphrase(self, predicate: str, arg_types: tuple[str, ...], n: int) -> list[str] | None:
        """``n`` question templates for ``predicate`` written by the model in one text-only
        request (:func:`~vap_bt.perception.paraphrase.request_prompt`), checked line by line;
        None when the reply does not hold ``n`` usable ones. Recorded like every query; never raises."""
        prompt = request_prompt(predicate, tuple(arg_types), n)
        rec = RequestRecord(backend=self.name, model=self.model, purpose="paraphrase", kind="text",
                            prompt=prompt, options=(), frame_id="")
        texts: list[str] | None = None

        def work(deadline: float) -> None:
            nonlocal texts
            reply = self._exchange(prompt, None, (), deadline, rec)
            if reply is None:
                return
            rec.reply, rec.finish_reason = reply.text or "", reply.finish_reason
            texts = None if reply.refused else read_generated(reply.text, len(arg_types), n)
            rec.outcome = "refusal" if reply.refused else "answer" if texts else "unparsed"
            rec.error = reply.refused or (None if texts else f"no {n} usable question templates in the reply")
            rec.value = "\n".join(texts) if texts else None

        self._recorded(rec, work)
        return texts

    # --- for the report -------------------------------------------------------------------------
    @property
    def dropped(self) -> tuple[str, ...]:
        """The optional features a server refused with a 400, now left out of every request to it."""
        with self._lock:
            return tuple(sorted(self._dropped))

    @property
    def requests(self) -> list[RequestRecord]:
        """Every query so far, in completion order."""
        return self._log.records()

    def describe(self) -> dict:
        """Backend, endpoint, model and every parameter that shapes the answers; never the key."""
        p = self.policy
        return {"backend": self.name, "url": self.url, "model": self.model, "api_key": "set" if self._has_key else "unset",
                "temperature": 0, "max_tokens": self.max_tokens, "text_max_tokens": self.text_max_tokens,
                "top_logprobs": self.top_logprobs,
                "timeout_s": p.timeout_s, "deadline_s": p.deadline_s, "attempts": p.attempts,
                "backoff_s": p.backoff_s, "backoff_max_s": p.backoff_max_s,
                "features": sorted(self._enabled()), "dropped": list(self.dropped)}

    def close(self) -> None:
        """Close the connection pool and cut short any wait for a retry."""
        self._transport.close()

    def __enter__(self) -> "HttpVLM":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


class StopWhenSilent:
    """A backend whose server stopped answering ends the episode: after each query, a
    :class:`~vap_bt.errors.TransportError` if the backend's :attr:`~HttpVLM.silent` says its
    retries were spent without a response (the module docstring says why). Everything else is
    the backend's own."""

    def __init__(self, inner: HttpVLM) -> None:
        self.inner = inner
        self.name = inner.name

    def ask(self, query: Query, frame: Frame) -> Answer:
        """The inner backend's answer, or a :class:`~vap_bt.errors.TransportError` when its server has
        stopped answering."""
        return self._checked(self.inner.ask(query, frame))

    def complete(self, prompt: str, purpose: Purpose = "goal", frame: Frame | None = None) -> Completion:
        """The inner backend's free text, or a :class:`~vap_bt.errors.TransportError` when its server
        has stopped answering."""
        return self._checked(self.inner.complete(prompt, purpose, frame))

    def _checked(self, answer):
        why = self.inner.silent
        if why is not None:
            raise TransportError(f"the VLM server at {self.inner.url} stopped answering ({why})")
        return answer

    def __getattr__(self, name: str):
        return getattr(self.inner, name)
