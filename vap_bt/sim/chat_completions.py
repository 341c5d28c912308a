"""OpenAI chat completions, as far as a client of a vision model uses them: the request read, the reply written.

The simulated VLM's HTTP endpoint (:mod:`vap_bt.sim.vlm_endpoint`) speaks this. vLLM's
OpenAI-compatible server is the reference for what is accepted and what is refused.

**Request** (``POST /v1/chat/completions``, a JSON object):

* ``model`` — the served model's name; any other is 404, as vLLM answers for a model it does not serve;
* ``messages`` — the last ``user`` message is the question: its text (a string, or the ``text``
  parts of a list, joined by newlines) is the prompt, its ``image_url`` parts the images;
* ``max_tokens`` (or ``max_completion_tokens``) at least 1 (default 16); ``n`` at least 1 (the
  model answers as at temperature 0: ``n`` equal choices); ``stream`` must be false (this
  endpoint does not stream: 400);
* ``logprobs`` (bool) and ``top_logprobs`` (0..20, only with ``logprobs``, as OpenAI and vLLM say);
* structured outputs as vLLM reads them: ``structured_outputs: {"choice": [...]}`` (vLLM >=
  0.10.2), else ``guided_choice: [...]`` — the reply is then exactly one of the choices. Other
  structured-output kinds (``json``, ``regex``, ``grammar``) are refused with a 400: the simulated
  model only ever says one of a question's options. ``grammar`` at the top level (llama.cpp's
  field), ``temperature`` and every other field are ignored, as vLLM ignores fields it does not
  know (the model's draws are seeded: it behaves as at temperature 0 whatever is asked).

A malformed request is a 400 (404 for the model) with OpenAI's error body ``{"error": {"message",
"type", "param", "code"}}``.

**Reply**: ``chat.completion`` with ``choices[i].message.content`` (the answer), ``finish_reason``
(``stop``; ``length`` when the text was cut at ``max_tokens``, counting a word as a token) and,
when asked, ``logprobs.content``: one entry per token, the first with ``top_logprobs`` over the
answer's options from the probabilities the model states (:class:`Said`). The logprobs are
chosen so that renormalising them over the options — what a client does — gives back the stated
probability to the last bit (a probability of 0 is written as -9999.0, as vLLM writes -inf).
A reply without stated probabilities has ``logprobs: null``.
"""

from __future__ import annotations

import base64
import binascii
import math
import re
import time
import uuid
from dataclasses import dataclass
from typing import Any

import cv2
import numpy as np

DEFAULT_MAX_TOKENS = 16
MAX_TOP_LOGPROBS = 20
NO_PROBABILITY = -9999.0  # log(0) as vLLM writes it: JSON has no -inf
_DATA_URL = re.compile(r"^data:image/[\w.+-]+;base64,(?P<data>.*)$", re.S)


class BadRequest(Exception):
    """A request the server refuses: HTTP ``status`` with OpenAI's error body."""

    def __init__(self, message: str, param: str | None = None, status: int = 400) -> None:
        super().__init__(message)
        self.message, self.param, self.status = message, param, status

    def body(self) -> dict:
        """The JSON body to answer with (OpenAI's error shape; a 404 is a NotFoundError)."""
        kind = "NotFoundError" if self.status == 404 else "BadRequestError"
        return error_body(self.message, kind, self.param, self.status)


def error_body(message: str, kind: str, param: str | None, code: int) -> dict:
    """An error reply in OpenAI's shape: ``{"error": {"message", "type", "param", "code"}}``."""
    return {"error": {"message": message, "type": kind, "param": param, "code": code}}


@dataclass(frozen=True)
class ChatRequest:
    """What a chat-completions request asks, read and checked."""

    prompt: str  # the last user message's text
    images: tuple[str, ...]  # its image URLs, in order
    max_tokens: int = DEFAULT_MAX_TOKENS
    n: int = 1
    logprobs: bool = False
    top_logprobs: int = 0
    choices: tuple[str, ...] | None = None  # the structured-output constraint, if any


@dataclass(frozen=True)
class Said:
    """What the model says: its text, and the probability it states for each option (None: none)."""

    text: str
    probabilities: dict[str, float] | None = None


def read_request(body: Any, model: str) -> ChatRequest:
    """The request ``body`` (parsed JSON) for the model served as ``model``; :class:`BadRequest` if malformed."""
    if not isinstance(body, dict):
        raise BadRequest("the request body must be a JSON object")
    if not isinstance(body.get("model"), str):
        raise BadRequest("'model' must be a string", "model")
    if body["model"] != model:
        raise BadRequest(f"The model `{body['model']}` does not exist.", "model", 404)
    if body.get("stream"):
        raise BadRequest("streaming is not supported by this endpoint", "stream")
    prompt, images = _last_user_message(body.get("messages"))
    max_tokens = body.get("max_completion_tokens", body.get("max_tokens", DEFAULT_MAX_TOKENS))
    n = body.get("n", 1)
    n = 1 if n is None else n
    logprobs = body.get("logprobs") or False
    top = body.get("top_logprobs") or 0
    for name, value, low, high in (("max_tokens", max_tokens, 1, None), ("n", n, 1, 16),
                                   ("top_logprobs", top, 0, MAX_TOP_LOGPROBS)):
        if not _int_within(value, low, high):
            raise BadRequest(f"'{name}' must be an integer {low}..{high or 'any'}, got {value!r}", name)
    if not isinstance(logprobs, bool):
        raise BadRequest("'logprobs' must be a boolean", "logprobs")
    if top and not logprobs:
        raise BadRequest("'top_logprobs' needs 'logprobs': true", "top_logprobs")
    return ChatRequest(prompt, images, max_tokens, n, logprobs, top, _choices(body))


def _int_within(value: Any, low: int, high: int | None) -> bool:
    return isinstance(value, int) and not isinstance(value, bool) and value >= low and (high is None or value <= high)


def _last_user_message(messages: Any) -> tuple[str, tuple[str, ...]]:
    if not isinstance(messages, list) or not messages:
        raise BadRequest("'messages' must be a non-empty list", "messages")
    users = [m for m in messages if isinstance(m, dict) and m.get("role") == "user"]
    if not users:
        raise BadRequest("no message with role 'user'", "messages")
    content = users[-1].get("content")
    if isinstance(content, str):
        return content, ()
    if not isinstance(content, list):
        raise BadRequest("a message's 'content' must be a string or a list of parts", "messages")
    texts, images = [], []
    for part in content:
        kind = part.get("type") if isinstance(part, dict) else None
        if kind == "text" and isinstance(part.get("text"), str):
            texts.append(part["text"])
        elif kind == "image_url":
            url = part.get("image_url")
            url = url.get("url") if isinstance(url, dict) else url
            if not isinstance(url, str):
                raise BadRequest("an image_url part needs a url", "messages")
            images.append(url)
        else:
            raise BadRequest(f"unsupported content part {kind!r}", "messages")
    return "\n".join(texts), tuple(images)


def _choices(body: dict) -> tuple[str, ...] | None:
    """The choice constraint as vLLM reads it: ``structured_outputs`` first, then ``guided_choice``."""
    so = body.get("structured_outputs")
    if so is not None:
        if not isinstance(so, dict):
            raise BadRequest("'structured_outputs' must be an object", "structured_outputs")
        other = sorted(k for k, v in so.items() if k != "choice" and v is not None)
        if other:
            raise BadRequest(f"structured output {', '.join(other)} is not supported here (only choice)",
                             "structured_outputs")
        if "choice" in so:
            return _choice_list(so["choice"], "structured_outputs.choice")
    if body.get("guided_choice") is not None:
        return _choice_list(body["guided_choice"], "guided_choice")
    return None


def _choice_list(value: Any, param: str) -> tuple[str, ...]:
    if not isinstance(value, list) or not value or not all(isinstance(c, str) and c for c in value):
        raise BadRequest(f"'{param}' must be a non-empty list of strings", param)
    return tuple(value)


def decode_image(url: str) -> np.ndarray | None:
    """The RGB pixels of a ``data:image/...;base64,`` URL, or None: another kind of URL (this
    endpoint fetches nothing), bad base64, or bytes no image decoder reads."""
    m = _DATA_URL.match(url)
    if m is None:
        return None
    try:
        raw = base64.b64decode(m.group("data"), validate=True)
    except (binascii.Error, ValueError):
        return None
    bgr = cv2.imdecode(np.frombuffer(raw, np.uint8), cv2.IMREAD_COLOR)
    return None if bgr is None else cv2.cvtColor(bgr, cv2.COLOR_BGR2RGB)


def completion_body(req: ChatRequest, said: Said, model: str) -> dict:
    """The ``chat.completion`` reply saying ``said`` to ``req`` (see the module docstring)."""
    words = said.text.split(" ")
    cut = len(words) > req.max_tokens
    text = " ".join(words[:req.max_tokens]) if cut else said.text
    logprobs = None
    if req.logprobs and said.probabilities is not None:
        logprobs = {"content": _token_logprobs(text, said.probabilities, req.top_logprobs)}
    choice = lambda i: {"index": i, "message": {"role": "assistant", "content": text, "refusal": None},  # noqa: E731
                        "logprobs": logprobs, "finish_reason": "length" if cut else "stop"}
    return {"id": f"chatcmpl-{uuid.uuid4().hex}", "object": "chat.completion", "created": int(time.time()),
            "model": model, "choices": [choice(i) for i in range(req.n)],
            "usage": {"prompt_tokens": len(req.prompt.split()), "completion_tokens": len(text.split()),
                      "total_tokens": len(req.prompt.split()) + len(text.split())}}


def _token_logprobs(text: str, probabilities: dict[str, float], top: int) -> list[dict]:
    """One entry for the answer (an option is one token), its ``top`` candidates the options by
    stated probability; logprobs exact under renormalisation over the options."""
    lp = exact_logprobs(probabilities, text)
    ranked = sorted(lp, key=lambda o: -lp[o])[:top]
    entry = lambda t, v: {"token": t, "logprob": v, "bytes": list(t.encode())}  # noqa: E731
    return [{**entry(text, lp.get(text, NO_PROBABILITY)), "top_logprobs": [entry(o, lp[o]) for o in ranked]}]


def exact_logprobs(probabilities: dict[str, float], chosen: str) -> dict[str, float]:
    """Log-probabilities of the options such that ``exp(lp[chosen]) / sum(exp(lp))`` equals
    ``probabilities[chosen]`` exactly in floating point (or exceeds it by the least amount when
    no double does): a client that renormalises over the options reads back the stated value,
    and a threshold it compares with decides as it would on that value."""
    lp = {o: math.log(p) if p > 0.0 else NO_PROBABILITY for o, p in probabilities.items()}
    target = probabilities.get(chosen)
    if target is None or target <= 0.0:
        return lp
    others = sum(math.exp(v) for o, v in lp.items() if o != chosen)

    def read(v: float) -> float:
        return math.exp(v) / (math.exp(v) + others)

    v = lp[chosen]
    for _ in range(64):  # a few ulps at most: log and exp each round once
        r = read(v)
        if r == target:
            break
        if r < target:
            v = math.nextafter(v, math.inf)
            continue
        lower = math.nextafter(v, -math.inf)
        if read(lower) < target:
            break
        v = lower
    lp[chosen] = v
    return lp
