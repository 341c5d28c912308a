"""Real vision-language models behind the one VLM protocol, spoken over HTTP.

``make_backend(name, url, model, ...)`` builds one; each answers ``ask(query, frame) -> Answer``
about a :class:`~vap_bt.robot.frame.Frame` (only ``frame.rgb`` and ``frame.frame_id`` are read),
keeps a record of every request (``backend.requests``, or an ``on_request`` callback) and says
what it is in ``describe()`` — never its key.

=========  ==================================================  ====================================
name       protocol                                            key (may be empty for local servers)
=========  ==================================================  ====================================
openai     OpenAI-compatible chat completions (vLLM, Ollama,   ``OPENAI_API_KEY``, Bearer header
           llama.cpp server; :mod:`.openai_compat`)
gemini     Gemini generateContent REST (:mod:`.gemini`)        ``GEMINI_API_KEY``, x-goog-api-key
=========  ==================================================  ====================================

The offline ``sim`` backend is served from the world's side and is not built here.
"""

from __future__ import annotations

import os
from typing import Callable, Mapping
from urllib.parse import urlsplit

from vap_bt.errors import InputError
from vap_bt.perception.backends import gemini, openai_compat
from vap_bt.perception.backends.base import HttpVLM
from vap_bt.perception.backends.gemini import GeminiVLM
from vap_bt.perception.backends.http import RetryPolicy
from vap_bt.perception.backends.openai_compat import OpenAICompatVLM
from vap_bt.perception.backends.record import RequestRecord

__all__ = ["BACKENDS", "GeminiVLM", "HttpVLM", "OpenAICompatVLM", "RequestRecord", "RetryPolicy", "make_backend"]

BACKENDS: dict[str, type[HttpVLM]] = {"openai": OpenAICompatVLM, "gemini": GeminiVLM}
_KEYS = {"openai": "OPENAI_API_KEY", "gemini": "GEMINI_API_KEY"}


def make_backend(name: str, url: str | None = None, model: str | None = None, *, timeout_s: float = 30.0,
                 deadline_s: float | None = None, attempts: int = 4, api_key: str | None = None,
                 max_tokens: int = 8, top_logprobs: int = 5,
                 on_request: Callable[[RequestRecord], None] | None = None,
                 env: Mapping[str, str] = os.environ) -> HttpVLM:
    """Build the HTTP VLM backend ``name`` (``openai`` or ``gemini``).

    * ``url`` — the API root, version included: ``--vlm-url``. openai: default
      ``OPENAI_BASE_URL`` or vLLM's ``http://127.0.0.1:8000/v1``; gemini: Google's
      ``https://generativelanguage.googleapis.com/v1beta`` (a local endpoint for tests).
    * ``model`` — ``--vlm-model``; required for openai (the server's served model name),
      ``gemini-2.5-flash`` by default for gemini.
    * ``timeout_s`` per HTTP request; ``deadline_s`` per query, retries and waits included
      (default ``3 * timeout_s``); ``attempts`` HTTP requests at most per query.
    * ``api_key`` — default from ``OPENAI_API_KEY`` / ``GEMINI_API_KEY`` in ``env``; may be empty
      for a local server, but Google's own endpoint needs one.
    * ``max_tokens`` — the answer budget; ``top_logprobs`` — candidates asked per token (0: none).
    * ``on_request`` — called with each :class:`RequestRecord` as its query ends.

    Bad arguments raise :class:`~vap_bt.errors.InputError` naming the option (exit code 2).
    """
    if name not in BACKENDS:
        raise InputError("--vlm", f"unknown HTTP backend {name!r}; choose one of {', '.join(BACKENDS)}")
    defaults = {"openai": (env.get("OPENAI_BASE_URL") or openai_compat.DEFAULT_URL, None),
                "gemini": (gemini.DEFAULT_URL, gemini.DEFAULT_MODEL)}[name]
    url = _checked_url(url or defaults[0])
    model = model or defaults[1]
    if not model:
        raise InputError("--vlm-model", f"the {name} backend needs a model name (the server's served model)")
    key = api_key if api_key is not None else env.get(_KEYS[name], "")
    if name == "gemini" and not key and url == gemini.DEFAULT_URL:
        raise InputError(_KEYS[name], "not set: Google's Gemini API needs a key (or point --vlm-url at a local endpoint)")
    if not timeout_s > 0:
        raise InputError("--vlm-timeout", f"must be a positive number of seconds, got {timeout_s}")
    if deadline_s is not None and not deadline_s >= timeout_s:
        raise InputError("--vlm-deadline", f"must be at least the timeout ({timeout_s} s), got {deadline_s}")
    if attempts < 1 or max_tokens < 1 or not 0 <= top_logprobs <= 20:
        raise InputError("--vlm", "attempts and max_tokens must be >= 1 and top_logprobs within 0..20")
    policy = RetryPolicy(timeout_s=timeout_s, deadline_s=deadline_s or 3 * timeout_s, attempts=attempts)
    return BACKENDS[name](url, model, api_key=key, policy=policy, max_tokens=max_tokens,
                          top_logprobs=top_logprobs, on_request=on_request)


def _checked_url(url: str) -> str:
    parts = urlsplit(url)
    if parts.scheme not in ("http", "https") or not parts.netloc:
        raise InputError("--vlm-url", f"expected an http(s) URL such as http://127.0.0.1:8000/v1, got {url!r}")
    return url.rstrip("/")
