"""The vision-language model protocol: a yes/no question or a choice among options, about one image.

Every backend — the simulated one, OpenAI-compatible servers, Gemini — answers a :class:`Query`
about a :class:`~vap_bt.robot.frame.Frame` with an :class:`Answer`. Answers are parsed
strictly: anything that is not clearly "yes"/"no" (or one of the options) is ``None``, which the
vote treats as uncertainty. A timeout is the same: uncertainty, never a crash.

``Query.about`` names the atoms the question concerns. Real models ignore it (they have the
prompt and the image); the simulated model judges from what the world shows of those atoms' objects.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Literal, Protocol, runtime_checkable

from vap_bt.domain.atoms import Atom
from vap_bt.robot.frame import Frame

Purpose = Literal["predicate", "sufficiency", "viewpoint", "action"]


@dataclass(frozen=True)
class Query:
    prompt: str
    kind: Literal["yesno", "choice"] = "yesno"
    purpose: Purpose = "predicate"
    about: tuple[Atom, ...] = ()
    objects: tuple[str, ...] = ()
    options: tuple[str, ...] = ()


@dataclass(frozen=True)
class Answer:
    """A model's reply, read strictly.

    ``confidence`` is the probability the model gave its own answer, renormalised over the
    options (yes/no, or the choice's options), from the first answer token's log-probabilities;
    ``None`` when the backend returned none (the simulated ones, servers without logprobs).
    ``latency_s`` is the wall time of the whole query, retries included, where measured.
    """

    raw: str
    value: bool | str | None  # None: no usable answer
    confidence: float | None = None
    latency_s: float | None = None

    @property
    def usable(self) -> bool:
        return self.value is not None

    @property
    def p_yes(self) -> float | None:
        """The model's probability of "yes" for a yes/no answer with a confidence, else None."""
        if not isinstance(self.value, bool) or self.confidence is None:
            return None
        return self.confidence if self.value else 1.0 - self.confidence


class VLM(Protocol):
    """A model that answers queries about frames. A backend that can also write paraphrases for
    predicates nobody wrote any for implements :class:`Paraphraser` as well (optional)."""

    name: str

    def ask(self, query: Query, frame: Frame) -> Answer: ...

    def describe(self) -> dict:
        """Backend name and every parameter that shapes its answers (for the report)."""


@runtime_checkable
class Paraphraser(Protocol):
    """The optional part of the VLM protocol: write ``n`` yes/no question templates for a
    predicate (``{X}`` its first argument, ``{Y}`` its second, ...), or None when it cannot.
    What comes back is checked before use (:mod:`vap_bt.perception.paraphrase`)."""

    name: str

    def paraphrase(self, predicate: str, arg_types: tuple[str, ...], n: int) -> list[str] | None: ...

    def describe(self) -> dict: ...


_YES = re.compile(r"^\W*(yes|y|true)\b", re.I)
_NO = re.compile(r"^\W*(no|n|false)\b", re.I)


def parse_yes_no(text: str) -> bool | None:
    """Strict: the reply must open with yes or no; anything else is no answer."""
    if _YES.match(text):
        return True
    if _NO.match(text):
        return False
    return None


def parse_choice(text: str, options: tuple[str, ...]) -> str | None:
    """The single option the reply names; none or several named is no answer."""
    words = set(re.findall(r"[a-z]+", text.lower()))
    named = [o for o in options if o in words]
    return named[0] if len(named) == 1 else None


class MeteredVLM:
    """Wraps a VLM to count queries and their time per purpose (for reports and benchmarks)."""

    def __init__(self, inner: VLM) -> None:
        self.inner = inner
        self.name = inner.name
        self.counts: dict[str, int] = {}
        self.seconds = 0.0

    def ask(self, query: Query, frame: Frame) -> Answer:
        import time

        t0 = time.perf_counter()
        try:
            return self.inner.ask(query, frame)
        finally:
            self.seconds += time.perf_counter() - t0
            self.counts[query.purpose] = self.counts.get(query.purpose, 0) + 1

    @property
    def total(self) -> int:
        return sum(self.counts.values())

    def describe(self) -> dict:
        return self.inner.describe()
