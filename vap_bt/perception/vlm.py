"""The vision-language model protocol: a yes/no question or a choice among options, about one image.

Every backend — the simulated one, OpenAI-compatible servers, Gemini — answers a :class:`Query`
about a :class:`~vap_bt.robot.frame.Frame` with an :class:`Answer`. Answers are parsed
strictly: anything that is not clearly "yes"/"no" (or one of the options) is ``None``, which the
vote treats as uncertainty. A timeout is the same: uncertainty, never a crash.

``Query.about`` names the atoms the question concerns. Real models ignore it (they have the
prompt and the image); the simulated model judges from what the world shows of those atoms' objects.

Two requests want free text rather than an answer among options: goal parsing (paper Alg. 1
line 2) asks a :class:`TextModel` to ``complete`` a text prompt, with no image, and the
VLM-planner baseline asks it for the next action, with the current frame; both read the free text
it returns (a :class:`Completion`). Only the real backends answer them; the simulated VLM neither
parses goals nor plans.
"""

from __future__ import annotations

import re
import threading
import time
from dataclasses import dataclass
from typing import Callable, Literal, Protocol, TypeVar, runtime_checkable

from vap_bt.domain.atoms import Atom
from vap_bt.robot.frame import Frame

T = TypeVar("T")
Purpose = Literal["predicate", "sufficiency", "viewpoint", "action", "goal", "plan"]


@dataclass(frozen=True)
class Query:
    """One question about a frame: the prompt, whether it wants a yes or no or one of ``options``, what it
    is for (``purpose``, the metering's key), and the atoms and objects it concerns (which only the
    simulated model reads)."""

    prompt: str
    kind: Literal["yesno", "choice"] = "yesno"
    purpose: Purpose = "predicate"
    about: tuple[Atom, ...] = ()
    objects: tuple[str, ...] = ()
    options: tuple[str, ...] = ()


@dataclass(frozen=True)
class Attempt:
    """One request of an exchange that asks a model for text and reads it strictly (goal parsing,
    the VLM-planner's next action): the prompt, the raw reply, the request's ``outcome``
    (:mod:`vap_bt.perception.backends.record` lists them), what was wrong with the reply (None: accepted), and the frame shown (None:
    text only)."""

    prompt: str
    reply: str | None  # the model's raw text; None when no reply came back
    outcome: str
    error: str | None
    latency_s: float | None = None
    frame_id: str | None = None

    def to_json(self) -> dict:
        return {"prompt": self.prompt, **({"frame_id": self.frame_id} if self.frame_id is not None else {}),
                "reply": self.reply, "outcome": self.outcome, "error": self.error,
                "latency_s": None if self.latency_s is None else round(self.latency_s, 4)}


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
        """Whether the reply gave a value; one that did not counts as uncertainty."""
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

    def ask(self, query: Query, frame: Frame) -> Answer:
        """Answer ``query`` about ``frame``. Blocks for as long as the model takes, within the backend's
        deadline; a reply that cannot be read, or none in time, is an :class:`Answer` whose value is
        None. Only a server that has stopped answering altogether raises
        (:class:`~vap_bt.errors.TransportError`)."""

    def describe(self) -> dict:
        """Backend name and every parameter that shapes its answers (for the report)."""


@dataclass(frozen=True)
class Completion:
    """A model's free-text reply to a text-only prompt.

    ``text`` is the reply when the model gave one to read, else ``None``; ``outcome`` says what
    became of the request in the words of :mod:`vap_bt.perception.backends.record` ("answer",
    "refusal", "empty", "unparsed" for a reply cut off at the token budget, "timeout",
    "unreachable", ...) and ``error`` why there is no text.
    """

    text: str | None
    outcome: str = "answer"
    error: str | None = None
    latency_s: float | None = None

    @property
    def replied(self) -> bool:
        """Whether the model wrote a reply at all (even a useless one); asking again can help only then."""
        return self.outcome not in NO_REPLY


#: outcomes without a reply from the model: the backend already retried what a retry can cure
#: (timeouts, 429, 5xx) within its deadline, and the rest (401, 404, a bug) a retry cannot
NO_REPLY = frozenset({"timeout", "unreachable", "rate_limited", "server_error", "http_error", "error"})


class TextModel(Protocol):
    """A model that answers a text prompt without an image (the real backends)."""

    name: str

    def complete(self, prompt: str, purpose: Purpose = "goal", frame: Frame | None = None) -> Completion:
        """Reply to a text prompt in free text, shown ``frame``'s picture when one is given and has
        pixels. Blocks like :meth:`VLM.ask`; what became of the request (a refusal, a timeout, ...)
        is said in the :class:`Completion`, not raised, short of a server that has stopped answering."""


@runtime_checkable
class Paraphraser(Protocol):
    """The optional part of the VLM protocol: write ``n`` yes/no question templates for a
    predicate (``{X}`` its first argument, ``{Y}`` its second, ...), or None when it cannot.
    What comes back is checked before use (:mod:`vap_bt.perception.paraphrase`)."""

    name: str

    def paraphrase(self, predicate: str, arg_types: tuple[str, ...], n: int) -> list[str] | None:
        """``n`` question templates for ``predicate``, whose arguments are of ``arg_types`` (``{X}`` for
        the first, ``{Y}`` for the second, ...), or None when the backend cannot write them. The caller
        checks them before use."""

    def describe(self) -> dict:
        """Backend name and every parameter that shapes its answers (for the report)."""


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
    """Wraps a VLM to count queries and their time per purpose (for reports and benchmarks).

    ``seconds`` adds up every query's own time; ``wall_s`` is the wall time during which at least
    one query was in flight — what the robot spent waiting on the model, which concurrent
    questions shorten and ``seconds`` does not show. Safe to call from several threads."""

    def __init__(self, inner: VLM) -> None:
        self.inner = inner
        self.name = inner.name
        self.counts: dict[str, int] = {}
        self.seconds = 0.0
        self._busy_s = 0.0
        self._in_flight = 0
        self._since = 0.0  # when the current stretch of queries in flight began
        self._lock = threading.Lock()

    def ask(self, query: Query, frame: Frame) -> Answer:
        return self._metered(query.purpose, lambda: self.inner.ask(query, frame))

    def complete(self, prompt: str, purpose: Purpose = "goal", frame: Frame | None = None) -> Completion:
        """The inner model's :meth:`TextModel.complete`, counted like a query."""
        complete = getattr(self.inner, "complete", None)
        if complete is None:
            raise TypeError(f"the {self.name} VLM answers questions about frames, not text prompts")
        return self._metered(purpose, lambda: complete(prompt, purpose, frame))

    def _metered(self, purpose: str, call: Callable[[], T]) -> T:
        t0 = time.perf_counter()
        with self._lock:
            if not self._in_flight:
                self._since = t0
            self._in_flight += 1
        try:
            return call()
        finally:
            t1 = time.perf_counter()
            with self._lock:
                self.seconds += t1 - t0
                self.counts[purpose] = self.counts.get(purpose, 0) + 1
                self._in_flight -= 1
                if not self._in_flight:
                    self._busy_s += t1 - self._since

    @property
    def wall_s(self) -> float:
        """Wall time with at least one query in flight, so far."""
        with self._lock:
            return self._busy_s + (time.perf_counter() - self._since if self._in_flight else 0.0)

    @property
    def total(self) -> int:
        """Queries asked so far, of every purpose."""
        return sum(self.counts.values())

    def describe(self) -> dict:
        return self.inner.describe()
