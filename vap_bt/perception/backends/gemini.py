"""Gemini's generateContent REST API, spoken directly over httpx.

Why REST and not google-genai: the request is one small JSON document, and the SDK (with
google-auth and its other dependencies) would bring its own retry and timeout logic, which
would hide the very things this backend must control and record: the per-query deadline, the
429's ``google.rpc.RetryInfo`` delay, the attempts. ``base_url`` also points at a local server
without the SDK's notion of API versions getting in the way.

``POST {url}/models/{model}:generateContent`` (``url`` includes the API version, default
``https://generativelanguage.googleapis.com/v1beta``), key in ``x-goog-api-key`` (never in the
URL, so it cannot leak into logs), body::

    {"contents": [{"role": "user", "parts": [
        {"inline_data": {"mime_type": "image/png", "data": "<base64>"}},
        {"text": "<the appendix prompt, verbatim>"}]}],
     "generationConfig": {
        "temperature": 0, "maxOutputTokens": 8, "candidateCount": 1,
        "responseMimeType": "text/x.enum",
        "responseSchema": {"type": "STRING", "enum": ["yes", "no"]},
        "thinkingConfig": {"thinkingBudget": 0},
        "responseLogprobs": true, "logprobs": 5}}

Thinking is off because a reasoning model otherwise spends the small token budget thinking and
returns no answer. Not every model takes every part: models without logprobs, without a
thinking switch (or that cannot stop thinking) answer 400 naming the field, and are asked again
without it (see :mod:`.base`). A rate limit is a 429 whose ``error.details`` holds a
``type.googleapis.com/google.rpc.RetryInfo`` with ``retryDelay`` (a duration such as
``"37s"``): that delay is waited when it fits the query's deadline, else the query abstains.

A text-only request (:meth:`~.base.HttpVLM.complete`, goal parsing) has only the text part, no
enum and no logprobs, thinking still off, ``maxOutputTokens`` = ``text_max_tokens``;
``finishReason`` MAX_TOKENS means it was cut off. A free-text request about a frame (the
VLM-planner's next action) has the inline image before the text, as a question has, and is
otherwise the same.

Paraphrases for a predicate without any (:meth:`~.base.HttpVLM.paraphrase`) are asked with the
same endpoint and a text-only body: one text part, ``temperature`` 0, a larger
``maxOutputTokens``, thinking off where the model allows it, no enum and no logprobs.

The reply is ``candidates[0].content.parts[*].text`` (thought parts skipped); a prompt blocked
(``promptFeedback.blockReason``) or an answer stopped for safety (``finishReason`` SAFETY,
PROHIBITED_CONTENT, ...) is a refusal; ``candidates[0].logprobsResult`` gives
``chosenCandidates`` and ``topCandidates[i].candidates`` (``token``, ``logProbability``).
"""

from __future__ import annotations

import re
from typing import Any

import httpx

from vap_bt.perception.backends.base import Feature, HttpVLM, Reply, dig
from vap_bt.perception.backends.http import retry_after
from vap_bt.perception.backends.image import EncodedImage
from vap_bt.perception.backends.reply import TokenChoice, token_choices

DEFAULT_URL = "https://generativelanguage.googleapis.com/v1beta"
DEFAULT_MODEL = "gemini-2.5-flash"
RETRY_INFO = "type.googleapis.com/google.rpc.RetryInfo"
BLOCKED = frozenset({"SAFETY", "RECITATION", "BLOCKLIST", "PROHIBITED_CONTENT", "SPII", "IMAGE_SAFETY"})
_DURATION = re.compile(r"^\s*(\d+(?:\.\d*)?)s\s*$")


def retry_delay(response: httpx.Response) -> float | None:
    """Seconds from the error's RetryInfo ``retryDelay``, else from ``Retry-After``, else None."""
    try:
        details = dig(response.json(), "error", "details")
    except ValueError:
        details = None
    for d in details if isinstance(details, list) else ():
        if isinstance(d, dict) and d.get("@type") == RETRY_INFO and isinstance(d.get("retryDelay"), str):
            m = _DURATION.match(d["retryDelay"])
            if m:
                return float(m.group(1))
    return retry_after(response)


class GeminiVLM(HttpVLM):
    """Asks a Gemini model (or a local server speaking its REST API) about a frame."""

    name = "gemini"
    truncated = frozenset({"MAX_TOKENS"})
    features = (
        Feature("enum", ("responsemimetype", "response_mime_type", "responseschema", "response_schema", "x.enum")),
        Feature("thinking", ("thinking",)),
        Feature("logprobs", ("logprob",)),
    )

    def endpoint(self) -> str:
        return f"{self.url}/models/{self.model}:generateContent"

    def auth_headers(self, api_key: str) -> dict[str, str]:
        return {"x-goog-api-key": api_key} if api_key else {}

    def retry_hint(self, response: httpx.Response) -> float | None:
        return retry_delay(response)

    def request(self, prompt: str, image: EncodedImage | None, options: tuple[str, ...],
                features: frozenset[str]) -> dict:
        free = not options  # free text (goal parsing, the VLM-planner): no enum, no logprobs
        config: dict[str, Any] = {"temperature": 0, "candidateCount": 1,
                                  "maxOutputTokens": self.text_max_tokens if free else self.max_tokens}
        if "enum" in features and not free:
            config["responseMimeType"] = "text/x.enum"
            config["responseSchema"] = {"type": "STRING", "enum": list(options)}
        if "thinking" in features:
            config["thinkingConfig"] = {"thinkingBudget": 0}
        if "logprobs" in features and self.top_logprobs > 0 and not free:
            config["responseLogprobs"], config["logprobs"] = True, self.top_logprobs
        parts = [] if image is None else [{"inline_data": {"mime_type": image.mime, "data": image.png_b64}}]
        return {"contents": [{"role": "user", "parts": [*parts, {"text": prompt}]}], "generationConfig": config}

    def read(self, data: Any) -> Reply:
        candidate = dig(data, "candidates", 0)
        if not isinstance(candidate, dict):
            block = dig(data, "promptFeedback", "blockReason")
            return Reply(text=None, refused=f"the prompt was blocked: {block}" if block else None)
        finish = candidate.get("finishReason")
        parts = dig(candidate, "content", "parts")
        text = "".join(p["text"] for p in parts if isinstance(p, dict) and isinstance(p.get("text"), str)
                       and not p.get("thought")) if isinstance(parts, list) else None
        if finish in BLOCKED:
            return Reply(text=text, finish_reason=finish, refused=f"the answer was stopped: {finish}")
        return Reply(text=text, finish_reason=finish, tokens=_tokens(candidate.get("logprobsResult")))


def _tokens(result: Any) -> tuple[TokenChoice, ...]:
    """``logprobsResult``: ``chosenCandidates[i]`` with ``topCandidates[i].candidates``."""
    chosen = dig(result, "chosenCandidates")
    items = chosen if isinstance(chosen, list) else []
    return token_choices(((c, dig(result, "topCandidates", i, "candidates")) for i, c in enumerate(items)),
                         "logProbability")
