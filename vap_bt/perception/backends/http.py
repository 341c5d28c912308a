"""The HTTP transport every VLM backend shares: one JSON POST, retried within a deadline.

A query must end, with an answer or without one, before its deadline; the robot waits for it.
:meth:`Transport.post` therefore sends one request with a per-request timeout and retries only
what a retry can cure:

* connection errors and timeouts;
* 408, 429 and 5xx (500, 502, 503, 504), waiting what the server asks (``Retry-After`` in
  seconds or as an HTTP date; a backend may read a richer hint, such as Gemini's
  ``google.rpc.RetryInfo``), else an exponential backoff (``backoff_s`` doubling up to
  ``backoff_max_s``; no jitter, so runs repeat; a server's own hint spreads concurrent callers).

It stops after ``attempts`` requests, and never sleeps past the deadline: when the server asks
for a longer wait than is left, the query gives up at once. Each attempt's timeout is cut to what
is left of the deadline. (httpx's timeout bounds each phase — connect, each read — not the whole
exchange; a server trickling bytes could outlast it, which real inference servers do not do.)

Any other status is returned as is, for the backend to read. The transport never raises for a
network failure: it returns an :class:`Exchange` saying what happened. ``close()`` interrupts
waits, so a run that is shutting down does not sit out a backoff.

httpx's ``Client`` is thread-safe and pools connections: one transport serves every thread.
"""

from __future__ import annotations

import email.utils
import json
import logging
import threading
import time
from dataclasses import dataclass
from typing import Any, Callable

import httpx

log = logging.getLogger("vap_bt.vlm")

RETRY_STATUSES = frozenset({408, 429, 500, 502, 503, 504})


@dataclass(frozen=True)
class RetryPolicy:
    """How long one request may take, how often it is retried, and the query's total deadline."""

    timeout_s: float = 30.0  # per HTTP request
    deadline_s: float = 90.0  # per query: every attempt and wait included
    attempts: int = 4  # HTTP requests at most, the first included
    backoff_s: float = 0.5  # first wait without a server hint; doubles per retry
    backoff_max_s: float = 8.0

    def backoff(self, retry: int) -> float:
        """The wait before retry number ``retry`` (1-based) when the server gave no hint."""
        return min(self.backoff_max_s, self.backoff_s * 2 ** (retry - 1))


@dataclass(frozen=True)
class Exchange:
    """What one :meth:`Transport.post` came to: the final response, or why there is none."""

    status: int | None  # None: no response at all
    text: str
    attempts: int
    failure: str | None = None  # rate_limited | server_error | timeout | unreachable (retries spent)
    detail: str = ""  # the last failure in words

    def json(self) -> Any | None:
        """The response body as JSON, or None when it is not JSON (or there was no response)."""
        try:
            return json.loads(self.text)
        except ValueError:
            return None


def retry_after(response: httpx.Response) -> float | None:
    """Seconds to wait from a ``Retry-After`` header (delta-seconds or an HTTP date), if any."""
    value = response.headers.get("retry-after")
    if not value:
        return None
    try:
        return max(0.0, float(value))
    except ValueError:
        pass
    try:
        when = email.utils.parsedate_to_datetime(value)
    except (TypeError, ValueError):
        return None
    return max(0.0, when.timestamp() - time.time())


class Transport:
    """POSTs JSON with a timeout per request, bounded retries, and a deadline per call."""

    def __init__(self, policy: RetryPolicy, headers: dict[str, str],
                 retry_hint: Callable[[httpx.Response], float | None] = retry_after) -> None:
        self.policy = policy
        self.retry_hint = retry_hint
        self._client = httpx.Client(headers=headers, timeout=policy.timeout_s, follow_redirects=False)
        self._closed = threading.Event()

    def post(self, url: str, body: dict, deadline: float) -> Exchange:
        """POST ``body`` to ``url``, retrying as the policy allows until ``deadline`` (monotonic)."""
        attempt, status, text, failure, detail = 0, None, "", "timeout", ""
        while attempt < self.policy.attempts and not self._closed.is_set():
            left = deadline - time.monotonic()
            if left <= 0:
                break
            attempt += 1
            hint = None
            try:
                r = self._client.post(url, json=body, timeout=min(self.policy.timeout_s, left))
            except httpx.TimeoutException as e:
                status, text, failure, detail = None, "", "timeout", f"no reply within the timeout ({type(e).__name__})"
            except httpx.HTTPError as e:  # connection refused, reset, DNS, protocol errors
                status, text, failure, detail = None, "", "unreachable", f"{type(e).__name__}: {e}"
            else:
                if r.status_code not in RETRY_STATUSES:
                    return Exchange(r.status_code, r.text, attempt)
                status, text, hint = r.status_code, r.text, self.retry_hint(r)
                failure = "rate_limited" if r.status_code == 429 else "server_error"
                detail = f"HTTP {r.status_code}"
            wait = hint if hint is not None else self.policy.backoff(attempt)
            if attempt >= self.policy.attempts:
                break
            if time.monotonic() + wait >= deadline:
                detail += f"; a retry in {wait:.2f} s would pass the deadline"
                break
            log.info("VLM POST %s: %s; retry %d/%d in %.2f s", url, detail, attempt, self.policy.attempts - 1, wait)
            if self._closed.wait(wait):
                detail += "; closed while waiting"
                break
        if attempt == 0:
            detail = "closed" if self._closed.is_set() else "the deadline had passed before the first attempt"
        log.warning("VLM POST %s gave up after %d attempt(s): %s", url, attempt, detail)
        return Exchange(status, text, attempt, failure, detail)

    def probe(self, url: str, timeout_s: float) -> str | None:
        """One GET of ``url``, no retry: why nothing answered (a sentence), or None when a server
        did — with any status (the API root is a 404 on many servers, and a 404 is an answer)."""
        try:
            self._client.get(url, timeout=timeout_s)
        except httpx.TimeoutException:
            return f"no answer within {timeout_s:g} s"
        except httpx.ConnectError as e:
            return f"nothing accepts a connection there ({e})"
        except httpx.HTTPError as e:
            return f"{type(e).__name__}: {e}"
        return None

    def close(self) -> None:
        self._closed.set()
        self._client.close()
