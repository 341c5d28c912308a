"""What a model's reply means: its text read strictly, and a confidence from its token log-probabilities.

A real model does not always answer the question. Servers that constrain decoding return exactly
one option; the others may write prose, hedge, or refuse. The reading here never guesses:

* a refusal or hedge ("I can't help with that", "No, I cannot tell", "I'm not sure") is no
  answer, even when it happens to open with "no";
* a yes/no reply must open with yes or no (:func:`~vap_bt.perception.vlm.parse_yes_no`) and must
  not name the other answer too ("yes and no", "Yes, but no cup is visible");
* a choice must name exactly one option (:func:`~vap_bt.perception.vlm.parse_choice`).

Confidence comes from the first answer token (leading whitespace, quote and markup tokens are
skipped): the probability mass of the top candidates that begin an option, each candidate
credited to the single option it is a prefix of ("Yes", " yes" and "y" all count for yes),
renormalised over the options. Options are often several tokens ("behind"), so the first token
stands for the whole option; the viewpoint options begin with distinct letters, so this is
unambiguous for them.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any, Iterable, Literal, Sequence

from vap_bt.perception.vlm import parse_choice, parse_yes_no

YES_NO = ("yes", "no")

_REFUSAL = re.compile(
    r"\b(can[’']?t|cannot|can not|unable|not able|sorry|apologi[sz]e|as an ai|not sure|unsure|"
    r"uncertain|unclear|impossible to (tell|say|determine)|i don[’']?t know|refuse)\b", re.I)
_WORDS = re.compile(r"[a-z]+")
_MARKUP = " \t\r\n\"'`*_.:,;!?()[]{}<>"


@dataclass(frozen=True)
class TokenChoice:
    """One generated token with its log-probability and the top candidates at that position."""

    token: str
    logprob: float
    top: tuple[tuple[str, float], ...] = ()


def token_choices(positions: Iterable[tuple[Any, Any]], logprob_key: str) -> tuple[TokenChoice, ...]:
    """Read a protocol's (chosen token, top candidates) pairs — dicts ``{"token": str, logprob_key:
    number}`` — up to the first malformed position (those after it may not line up)."""
    out = []
    for chosen, top in positions:
        lp = _logprob(chosen, logprob_key)
        if lp is None:
            break
        pairs = tuple((t["token"], p) for t in top if (p := _logprob(t, logprob_key)) is not None) \
            if isinstance(top, list) else ()
        out.append(TokenChoice(chosen["token"], lp, pairs))
    return tuple(out)


def _logprob(item: Any, key: str) -> float | None:
    if not isinstance(item, dict) or not isinstance(item.get("token"), str):
        return None
    value = item.get(key)
    return float(value) if isinstance(value, (int, float)) else None


def is_refusal(text: str) -> bool:
    """True when the reply refuses or hedges instead of answering."""
    return bool(_REFUSAL.search(text))


def read_answer(text: str, kind: Literal["yesno", "choice"], options: Sequence[str]) -> bool | str | None:
    """The answer the reply text gives, or None: refusals, hedges and ambiguity are no answer."""
    if is_refusal(text):
        return None
    if kind == "choice":
        return parse_choice(text, tuple(options))
    value = parse_yes_no(text)
    other = "no" if value else "yes"
    if value is None or other in _WORDS.findall(text.lower()):
        return None
    return value


def option_name(value: bool | str | None) -> str | None:
    """The option a parsed value stands for: "yes"/"no" for booleans, the choice itself otherwise."""
    if isinstance(value, bool):
        return "yes" if value else "no"
    return value


def option_confidence(tokens: Sequence[TokenChoice], options: Sequence[str], chosen: str | None) -> float | None:
    """P(chosen) renormalised over ``options`` at the first answer token, or None without evidence."""
    if chosen is None:
        return None
    first = next((t for t in tokens if t.token.strip(_MARKUP)), None)
    if first is None:
        return None
    candidates = dict(first.top)
    candidates.setdefault(first.token, first.logprob)  # the sampled token may be outside the top k
    mass = dict.fromkeys(options, 0.0)
    for token, logprob in candidates.items():
        option = _option_begun_by(token, options)
        if option is not None and math.isfinite(logprob):
            mass[option] += math.exp(logprob)
    total = sum(mass.values())
    return mass.get(chosen, 0.0) / total if total > 0.0 else None


def _option_begun_by(token: str, options: Sequence[str]) -> str | None:
    t = token.strip(_MARKUP).lower()
    if not t:
        return None
    if t in options:
        return t
    begun = [o for o in options if o.startswith(t)]
    return begun[0] if len(begun) == 1 else None
