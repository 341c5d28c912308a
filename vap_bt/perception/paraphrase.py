"""Paraphrases: the question templates a predicate is asked with, checked, and generated where missing.

A paraphrase is a question template in the appendix's style: ``"Is the {X} on the {Y}?"``, where
``{X}`` stands for the predicate's first argument, ``{Y}`` for its second, then ``{Z}``, ``{U}``,
``{V}``, ``{W}`` (and ``{A7}``, ``{A8}``, ... beyond six). A usable template names every argument's
placeholder and no other — a question that leaves an argument out cannot tell two atoms apart,
and one that names an argument the predicate does not have cannot be asked at all (the ferry's
``on ?c`` asked with the household's ``on(X, Y)`` text) — and it is a question.

A predicate that should be asked of the VLM but has no paraphrases gets generated ones:

* from the backend when it can: a VLM with the optional ``paraphrase(predicate, arg_types, n)``
  method (:class:`~vap_bt.perception.vlm.Paraphraser`; the HTTP backends send one text-only
  request built by :func:`request_prompt` and read the reply with :func:`read_generated`). What
  it writes is checked like any profile's text; a reply without ``n`` usable questions is not
  used;
* else from :func:`template_paraphrases`, five fixed phrasings over the predicate's name and
  argument types, deterministic: ``at ?x - truck ?l - location`` gives "Is the truck {X} at the
  location {Y}?" and four more.
"""

from __future__ import annotations

import re
import string
from typing import Sequence

#: the placeholders of the first arguments, as the appendix writes them
PLACEHOLDERS = ("X", "Y", "Z", "U", "V", "W")
#: how many phrasings the templates give (the paper's N = 5)
TEMPLATE_COUNT = 5


def placeholder(i: int) -> str:
    """The placeholder of argument ``i`` (0-based): X, Y, Z, U, V, W, then A7, A8, ..."""
    return PLACEHOLDERS[i] if i < len(PLACEHOLDERS) else f"A{i + 1}"


def argument_index(name: str) -> int:
    """The argument a placeholder stands for (0-based): X -> 0, Y -> 1, ..., A7 -> 6."""
    return PLACEHOLDERS.index(name) if name in PLACEHOLDERS else int(name[1:]) - 1


def placeholders(arity: int) -> tuple[str, ...]:
    """The placeholders of a predicate's ``arity`` arguments, in order: X, Y, ..."""
    return tuple(placeholder(i) for i in range(arity))


def fields_of(template: str) -> list[tuple[str, str | None]]:
    """``template`` as (literal text, placeholder or None) pieces; ValueError if braces are unbalanced."""
    return [(lit, name) for lit, name, _, _ in string.Formatter().parse(template)]


def template_problem(template: str, arity: int, phrase: bool = False) -> str | None:
    """Why ``template`` is not a usable paraphrase of a predicate of ``arity`` arguments (None: it is);
    ``phrase=True`` checks an action's phrase instead, which goes inside a question and may leave
    arguments out (it need not name the room the robot is in)."""
    if not isinstance(template, str) or not template.strip():
        return "an empty paraphrase"
    try:
        pieces = list(string.Formatter().parse(template))
    except ValueError as exc:
        return f"{template!r}: {exc} (write a literal brace as {{{{ or }}}})"
    wanted = placeholders(arity)
    used = set()
    for _, name, spec, conversion in pieces:
        if name is None:
            continue
        if name not in wanted:
            takes = f"{arity} argument{'s' if arity != 1 else ''}"
            allowed = ", ".join(f"{{{p}}}" for p in wanted) or "no placeholders"
            return f"{template!r} names {{{name}}}, but the predicate takes {takes} ({allowed})"
        if spec or conversion:
            return f"{template!r}: write {{{name}}} plainly, without a format spec or conversion"
        used.add(name)
    missing = [p for p in wanted if p not in used]
    if missing and not phrase:
        return f"{template!r} leaves out {', '.join(f'{{{p}}}' for p in missing)}: every argument must be named"
    if not phrase and not template.rstrip().endswith("?"):
        return f"{template!r} is not a question (it must end with '?')"
    return None


def paraphrases_problem(templates: Sequence[str], arity: int) -> str | None:
    """Why a list of paraphrases is not usable (the first bad one, or a repeat), else None."""
    for i, t in enumerate(templates):
        why = template_problem(t, arity)
        if why:
            return f"paraphrase {i + 1}: {why}"
    seen: set[str] = set()
    for t in templates:
        if t in seen:
            return f"{t!r} is given twice (each paraphrase is one more independent question)"
        seen.add(t)
    return None


def words_of(name: str) -> str:
    """A predicate's or type's PDDL name as words: ``at-robby`` -> "at robby", ``turned_on`` ->
    "turned on" (object names are spoken by :func:`vap_bt.perception.prompts.spoken`)."""
    return name.replace("_", " ").replace("-", " ")


def listing(parts: list[str]) -> str:
    """Words listed as said: "a", "a and b", "a, b and c"."""
    return parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]


def _argument(i: int, type_name: str) -> str:
    # "the truck {X}"; an untyped argument is just "the {X}", as in the appendix
    t = words_of(type_name)
    return f"the {{{placeholder(i)}}}" if type_name == "object" else f"the {t} {{{placeholder(i)}}}"


def template_paraphrases(predicate: str, arg_types: Sequence[str], n: int = TEMPLATE_COUNT) -> list[str]:
    """``n`` (at most five) deterministic phrasings of ``predicate`` over its argument types.

    The first reads the predicate as a relation ("Is the truck {X} at the location {Y}?"); the
    others quote it, so that they stay questions whatever kind of word the name is."""
    if not 1 <= n <= TEMPLATE_COUNT:
        raise ValueError(f"templates give 1 to {TEMPLATE_COUNT} paraphrases, not {n}")
    w = words_of(predicate)
    args = [_argument(i, t) for i, t in enumerate(arg_types)]
    if not args:
        forms = [f"Is it the case that {w}?",
                 f"Does this image show that {w}?",
                 f"In this view, does '{w}' hold?",
                 f"Is '{w}' true in this image?",
                 f"Can you confirm from this image that '{w}' holds?"]
    else:
        subject, rest = args[0], (" " + listing(args[1:])) if len(args) > 1 else ""
        every = listing(args)
        forms = [f"Is {subject} {w}{rest}?",
                 f"Does this image show {subject} {w}{rest}?",
                 f"In this view, is {subject} {w}{rest}?",
                 f"Does '{w}' hold for {every}?",
                 f"Can you confirm from this image that '{w}' holds for {every}?"]
    return forms[:n]


def request_prompt(predicate: str, arg_types: Sequence[str], n: int) -> str:
    """The text-only request a backend is sent to write ``n`` paraphrases of ``predicate``."""
    names = placeholders(len(arg_types))
    signature = f"{predicate}({', '.join(f'{p} - {t}' for p, t in zip(names, arg_types))})"
    if names:
        fill = ("Write each of the placeholders " + ", ".join(f"{{{p}}}" for p in names)
                + " in every question, exactly as written, where that object's name goes (the robot fills them in).")
    else:
        fill = "The predicate has no arguments: the questions name no object."
    return (f"A robot checks a fact of its planning domain by asking a vision-language model yes/no questions "
            f"about a camera image.\n\n"
            f"Predicate: {signature}\n\n"
            f"Write {n} different yes/no questions, each asking whether this predicate holds in the image. {fill}\n"
            f"Answer with the {n} questions only, one per line.")


_BULLET = re.compile(r"^\s*(?:[-*\u2022]|\d+\s*[.)])\s*")


def usable(texts: Sequence[str], arity: int, n: int) -> list[str] | None:
    """The first ``n`` usable, distinct paraphrases of ``texts``, or None if there are fewer."""
    out: list[str] = []
    for t in texts:
        q = _BULLET.sub("", t).strip().strip('"\u201c\u201d').strip() if isinstance(t, str) else ""
        if q and template_problem(q, arity) is None and q not in out:
            out.append(q)
    return out[:n] if len(out) >= n else None


def read_generated(text: str | None, arity: int, n: int) -> list[str] | None:
    """The first ``n`` usable questions of a backend's reply (one per line), or None."""
    return usable((text or "").splitlines(), arity, n)
