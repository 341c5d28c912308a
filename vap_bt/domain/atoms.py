"""Ground atoms: the unit of belief, of verification and of situations.

An :class:`Atom` is a predicate applied to object names, ``on(cup, table)``. Everything that
crosses a room boundary about the symbolic state is a set of atoms: the scene graph's facts, an
action's preconditions and effects, a goal, a situation. Atoms are immutable and hashable, print
in the paper's notation and parse from both that notation and PDDL's ``(on cup table)``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

_FUNCTIONAL = re.compile(r"^\s*([A-Za-z][\w-]*)\s*(?:\(\s*(.*?)\s*\))?\s*$")
_PDDL = re.compile(r"^\s*\(\s*([A-Za-z][\w-]*)((?:\s+[^\s()]+)*)\s*\)\s*$")


class AtomSyntaxError(ValueError):
    """Raised when a string is not an atom in either notation."""


@dataclass(frozen=True, order=True)
class Atom:
    """A predicate over named objects; ``args`` are object names, lower-case."""

    predicate: str
    args: tuple[str, ...] = ()

    def __str__(self) -> str:
        return f"{self.predicate}({', '.join(self.args)})" if self.args else self.predicate

    def pddl(self) -> str:
        """The atom in PDDL's notation, ``(on cup table)``."""
        return "(" + " ".join((self.predicate, *self.args)) + ")"

    @classmethod
    def parse(cls, text: str) -> "Atom":
        """Parse ``on(cup, table)``, ``hand_empty`` or ``(on cup table)``."""
        m = _PDDL.match(text)
        if m:
            return cls(m.group(1).lower(), tuple(a.lower() for a in m.group(2).split()))
        m = _FUNCTIONAL.match(text)
        if not m:
            raise AtomSyntaxError(f"not an atom: {text!r} (expected pred(a, b) or (pred a b))")
        inner = m.group(2)
        args = tuple(a.strip().lower() for a in inner.split(",")) if inner else ()
        if any(not a or not re.fullmatch(r"[\w-]+", a) for a in args):
            raise AtomSyntaxError(f"bad argument list in {text!r}")
        return cls(m.group(1).lower(), args)


@dataclass(frozen=True, order=True)
class Literal:
    """An atom with a sign: a precondition may require an atom to be false."""

    atom: Atom
    positive: bool = True

    def __str__(self) -> str:
        return str(self.atom) if self.positive else f"not {self.atom}"
