"""The record of every request a VLM backend made, for the run's report.

One :class:`RequestRecord` per :meth:`ask`: what was asked (purpose, prompt, options), about
which frame (its id, and the SHA-1 of its rgb bytes, see :mod:`.image`), what came back (HTTP
status, the model's raw text, or the error body), how it was read (``outcome``, value,
confidence) and what it cost (attempts, latency). The API key is never part of a record. A
text-only ``complete`` (goal parsing) is recorded the same way, with kind ``text`` and no frame.

``outcome`` is one of:

=============  ==============================================================
answer         the reply was read as a value (text: the reply's stripped text)
unparsed       a reply, but not yes/no or exactly one option (text: cut off at the budget)
refusal        the model or the server declined (a refusal, a safety block)
empty          a well-formed reply without text (no choices, no candidates)
malformed      the body was not the protocol's JSON
http_error     a status that is not worth retrying (400, 401, 403, 404, ...)
rate_limited   429 until the attempts or the deadline ran out
server_error   5xx until the attempts or the deadline ran out
timeout        no reply within the per-request timeout, on every attempt
unreachable    no connection could be made
no_image       the frame had no pixels (or not an RGB image): nothing shown, nothing sent
error          anything else (a bug): logged with its traceback, still an abstention
=============  ==============================================================
"""

from __future__ import annotations

import logging
import threading
from dataclasses import asdict, dataclass, field
from typing import Callable

log = logging.getLogger("vap_bt.vlm")


@dataclass
class RequestRecord:
    """One query to a backend and what became of it (filled in as the query proceeds)."""

    backend: str
    model: str
    purpose: str
    kind: str
    prompt: str
    options: tuple[str, ...]
    frame_id: str
    frame_sha1: str | None = None  # SHA-1 of the frame's rgb bytes (None: no pixels)
    image_size: tuple[int, int] | None = None  # width, height
    status: int | None = None  # last HTTP status (None: no response at all)
    outcome: str = "error"
    reply: str = ""  # the model's raw text, or the error body (truncated)
    value: bool | str | None = None
    confidence: float | None = None
    finish_reason: str | None = None
    attempts: int = 0  # HTTP requests sent for this query, retries included
    latency_s: float = 0.0
    error: str | None = None  # why there is no answer, in words
    dropped: tuple[str, ...] = field(default=())  # request features this server rejected so far

    def to_json(self) -> dict:
        return asdict(self)


class RequestLog:
    """Every record of one backend, in completion order; thread-safe; optionally forwarded."""

    def __init__(self, on_record: Callable[[RequestRecord], None] | None = None) -> None:
        self._records: list[RequestRecord] = []
        self._lock = threading.Lock()
        self._on_record = on_record

    def add(self, record: RequestRecord) -> None:
        """Keep ``record`` and hand it to the listener; a listener that fails is logged, never raised to
        the caller."""
        with self._lock:
            self._records.append(record)
        if self._on_record is not None:
            try:
                self._on_record(record)
            except Exception:  # a faulty listener must not turn an answer into a crash
                log.exception("VLM request listener failed")

    def records(self) -> list[RequestRecord]:
        """Every record so far, in order (a copy: safe while queries go on)."""
        with self._lock:
            return list(self._records)
