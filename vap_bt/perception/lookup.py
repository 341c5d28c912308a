"""From a question's text back to the atom it asks about.

A model served behind an endpoint sees only the prompt and the image. The simulated one still has
to know which fact it is being asked — so it reads the question the way the executive wrote it:
the appendix prompt around a paraphrase of the domain's perception profile, with the objects'
spoken names in the placeholders. :class:`QuestionLookup` inverts exactly that rendering:

* the prompt (predicate query, view sufficiency or viewpoint selection, from
  :mod:`vap_bt.perception.prompts`) is peeled off to its question (:meth:`~QuestionLookup.parse_prompt`);
* each paraphrase of the profile is matched against the question, literal text for literal text,
  each placeholder against the spoken names of the task's objects of the predicate's argument
  type (a placeholder used twice binds the same object both times);
* every way the question parses is collected: exactly one atom is the answer, none or several
  (two atoms that would be worded alike) is None — never a guess.

Exact for every question the profile can produce, provided no two atoms render to the same text;
the profile already refuses one question text for two predicates.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterator, Mapping

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import DomainKnowledge
from vap_bt.perception import prompts
from vap_bt.perception.paraphrase import argument_index, fields_of, placeholder
from vap_bt.perception.profile import PerceptionProfile, PredicatePerception
from vap_bt.perception.prompts import spoken


@dataclass(frozen=True)
class _Template:
    predicate: PredicatePerception
    pieces: tuple[tuple[str, str | None], ...]  # (literal, placeholder or None), in order


def _prompt_pattern(template: str) -> re.Pattern:
    """A prompt template as a regex whose groups are its fields (the question, the target)."""
    out = []
    for literal, name in fields_of(template):
        out.append(re.escape(literal))
        if name is not None:
            out.append(f"(?P<{name}>.+?)")
    return re.compile("".join(out), re.S)


class QuestionLookup:
    """The atom a question asks about, given a domain's profile and a task's objects (name -> type).

    With ``knowledge``, a placeholder only takes objects of its argument's type (or a subtype);
    without, any object."""

    def __init__(self, profile: PerceptionProfile, objects: Mapping[str, str],
                 knowledge: DomainKnowledge | None = None) -> None:
        self._templates = [_Template(p, tuple(fields_of(t))) for p in profile.predicates.values()
                           for t in p.paraphrases]
        self._objects = dict(objects)
        self._knowledge = knowledge
        self._candidates: dict[tuple[str, int], dict[str, list[str]]] = {}
        book = prompts.book()
        self._prompts = (("predicate", _prompt_pattern(book.predicate_query)),
                         ("sufficiency", _prompt_pattern(book.view_sufficiency)),
                         ("viewpoint", _prompt_pattern(book.viewpoint_selection)))

    def parse_prompt(self, text: str) -> tuple[str, str] | None:
        """``(purpose, question)`` of a whole appendix prompt, or None if ``text`` is not one."""
        for purpose, pattern in self._prompts:
            m = pattern.fullmatch(text)
            if m:
                return purpose, m.group("paraphrased_question" if purpose == "predicate" else "predicate_question")
        return None

    def atom_of_question(self, text: str) -> Atom | None:
        """The one atom ``text`` — a bare question or a whole prompt — asks about, else None."""
        parsed = self.parse_prompt(text)
        question = parsed[1] if parsed else text.strip()
        found = {Atom(t.predicate.name, args) for t in self._templates for args in self._parses(t, question)}
        return found.pop() if len(found) == 1 else None

    def _parses(self, t: _Template, text: str) -> Iterator[tuple[str, ...]]:
        """The argument tuples under which ``t`` renders to exactly ``text``."""
        order = [placeholder(i) for i in range(t.predicate.arity)]  # a usable template names each
        for binding in self._match(t, 0, text, 0, {}):
            yield tuple(binding[n] for n in order)

    def _match(self, t: _Template, i: int, text: str, pos: int, binding: dict[str, str]) -> Iterator[dict]:
        if i == len(t.pieces):
            if pos == len(text):
                yield dict(binding)
            return
        literal, name = t.pieces[i]
        if not text.startswith(literal, pos):
            return
        pos += len(literal)
        if name is None:
            yield from self._match(t, i + 1, text, pos, binding)
            return
        if name in binding:  # the same placeholder again: the same object
            said = spoken(binding[name])
            if text.startswith(said, pos):
                yield from self._match(t, i + 1, text, pos + len(said), binding)
            return
        for said, objs in self._fitting(t.predicate, argument_index(name)).items():
            if text.startswith(said, pos):
                for o in objs:
                    binding[name] = o
                    yield from self._match(t, i + 1, text, pos + len(said), binding)
                    del binding[name]

    def _fitting(self, p: PredicatePerception, arg: int) -> dict[str, list[str]]:
        """Spoken name -> the objects that may stand at argument ``arg`` of ``p`` and are said so."""
        key = (p.key, arg)
        if key not in self._candidates:
            want, k = p.types[arg], self._knowledge
            out: dict[str, list[str]] = {}
            for o, typ in sorted(self._objects.items()):
                if k is None or k.is_subtype(typ, want):
                    out.setdefault(spoken(o), []).append(o)
            self._candidates[key] = out
        return self._candidates[key]


def atom_of_question(profile: PerceptionProfile, objects: Mapping[str, str], text: str,
                     knowledge: DomainKnowledge | None = None) -> Atom | None:
    """One-off :meth:`QuestionLookup.atom_of_question` (build a lookup to ask many)."""
    return QuestionLookup(profile, objects, knowledge).atom_of_question(text)
