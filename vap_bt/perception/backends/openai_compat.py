"""OpenAI-compatible chat completions: vLLM, Ollama, llama.cpp's server (and OpenAI itself).

One user message: the frame first, as ``{"type": "image_url", "image_url": {"url":
"data:image/png;base64,..."}}``, then the appendix prompt verbatim as the text part (the prompt
opens with "[Image attached]", so the image goes before it). ``POST {url}/chat/completions``
with, beside ``model`` and ``messages``::

    "temperature": 0, "max_tokens": 8, "n": 1, "stream": false,
    "structured_outputs": {"choice": ["yes", "no"]},    # vLLM >= 0.10.2
    "guided_choice": ["yes", "no"],                      # older vLLM (newer ones prefer the above)
    "grammar": "root ::= \\"yes\\" | \\"no\\"",              # llama.cpp's server (GBNF)
    "logprobs": true, "top_logprobs": 5

The options are those of the query (yes/no, or the viewpoint directions). Each server reads the
constraint it knows and ignores the fields it does not (vLLM logs them as ignored; Ollama and
llama.cpp pass over them); Ollama has no constrained choice here, so its answers are read
strictly like anyone's. A server that rejects an unknown field (OpenAI's own API answers 400
"Unrecognized request argument") gets the request again without it (see :mod:`.base`).

A text-only request (:meth:`~.base.HttpVLM.complete`, goal parsing) is the same POST with the
prompt as the message's plain string content, no image part, no constraint and no logprobs,
``max_tokens`` = ``text_max_tokens``; ``finish_reason == "length"`` means it was cut off. A
free-text request about a frame (the VLM-planner's next action) has the image part first, as a
question has, and is otherwise the same.

Paraphrases for a predicate without any (:meth:`~.base.HttpVLM.paraphrase`) are asked in a
text-only request to the same endpoint: one user message with the text as its content,
``temperature`` 0, a larger ``max_tokens``, no constraint and no logprobs.

The reply is ``choices[0].message.content``; ``message.refusal`` (OpenAI) or
``finish_reason == "content_filter"`` is a refusal; ``choices[0].logprobs.content[i]`` gives each
token's ``logprob`` and ``top_logprobs``, from which the answer's confidence is read. The key,
from ``OPENAI_API_KEY``, goes in ``Authorization: Bearer``; it may be empty for a local server,
and then no such header is sent.
"""

from __future__ import annotations

from typing import Any

from vap_bt.perception.backends.base import Feature, HttpVLM, Reply, dig
from vap_bt.perception.backends.image import EncodedImage
from vap_bt.perception.backends.reply import TokenChoice, token_choices

DEFAULT_URL = "http://127.0.0.1:8000/v1"  # vLLM's `vllm serve` default


def gbnf_choice(options: tuple[str, ...]) -> str:
    """A llama.cpp grammar whose only sentences are the options."""
    return "root ::= " + " | ".join(f'"{o}"' for o in options)


class OpenAICompatVLM(HttpVLM):
    """Asks an OpenAI-compatible chat-completions server about a frame."""

    name = "openai"
    truncated = frozenset({"length"})
    features = (
        Feature("structured_outputs", ("structured_outputs",)),
        Feature("guided_choice", ("guided_choice",)),
        Feature("grammar", ("grammar",)),
        Feature("logprobs", ("logprobs",)),
    )

    def endpoint(self) -> str:
        return f"{self.url}/chat/completions"

    def auth_headers(self, api_key: str) -> dict[str, str]:
        return {"Authorization": f"Bearer {api_key}"} if api_key else {}

    def request(self, prompt: str, image: EncodedImage | None, options: tuple[str, ...],
                features: frozenset[str]) -> dict:
        if image is None:  # text only (goal parsing): the prompt as the message, nothing constrained
            return {"model": self.model, "messages": [{"role": "user", "content": prompt}],
                    "temperature": 0, "max_tokens": self.text_max_tokens, "n": 1, "stream": False}
        content = [{"type": "image_url", "image_url": {"url": image.data_url()}}, {"type": "text", "text": prompt}]
        if not options:  # free text about the frame (the VLM-planner's next action): nothing constrained
            return {"model": self.model, "messages": [{"role": "user", "content": content}],
                    "temperature": 0, "max_tokens": self.text_max_tokens, "n": 1, "stream": False}
        body: dict[str, Any] = {"model": self.model, "messages": [{"role": "user", "content": content}],
                                "temperature": 0, "max_tokens": self.max_tokens, "n": 1, "stream": False}
        if "structured_outputs" in features:
            body["structured_outputs"] = {"choice": list(options)}
        if "guided_choice" in features:
            body["guided_choice"] = list(options)
        if "grammar" in features:
            body["grammar"] = gbnf_choice(options)
        if "logprobs" in features and self.top_logprobs > 0:
            body["logprobs"], body["top_logprobs"] = True, self.top_logprobs
        return body

    def read(self, data: Any) -> Reply:
        choice = dig(data, "choices", 0)
        if not isinstance(choice, dict):
            return Reply(text=None)
        finish = choice.get("finish_reason")
        refusal = dig(choice, "message", "refusal")
        if refusal or finish == "content_filter":
            return Reply(text=str(refusal or ""), finish_reason=finish,
                         refused=f"the server refused: {refusal or 'content filter'}")
        return Reply(text=_text(dig(choice, "message", "content")), finish_reason=finish,
                     tokens=_tokens(dig(choice, "logprobs", "content")))


def _text(content: Any) -> str | None:
    """The message text: a string, or (some servers) a list of text parts."""
    if isinstance(content, str):
        return content
    if isinstance(content, list):
        return "".join(p.get("text", "") for p in content if isinstance(p, dict) and isinstance(p.get("text"), str))
    return None


def _tokens(content: Any) -> tuple[TokenChoice, ...]:
    """``choices[0].logprobs.content``: one dict per token, with its ``top_logprobs``."""
    items = content if isinstance(content, list) else []
    return token_choices(((item, dig(item, "top_logprobs")) for item in items), "logprob")
