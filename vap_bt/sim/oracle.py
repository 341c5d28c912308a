"""The oracle: the world's truth, held by exactly two kinds of code.

A real robot has no ``holds()``. In simulation the truth exists, and it is wrapped here so that
who may read it is explicit: the runner (to score an episode in its report: was the goal really
reached, which situations did the world inject) and the world-side simulated sensors and VLM
(which model what a real camera and a real model would return). The executive never receives
an oracle; ``tests/test_architecture.py`` checks that no object the executive holds can reach one.
"""

from __future__ import annotations

from typing import Callable, Iterable, Protocol

from vap_bt.domain.atoms import Atom
from vap_bt.world import InjectedSituation


class Oracle(Protocol):
    """Ground truth of a world, for scoring and for simulated sensors only."""

    def holds(self, atom: Atom) -> bool:
        """Whether ``atom`` is true in the world right now."""

    def true_atoms(self, candidates: Iterable[Atom]) -> frozenset[Atom]:
        """The candidates that hold right now."""

    def injected(self) -> list[InjectedSituation]:
        """Situations the world caused on purpose (Table II) or by script, in order."""

    def position(self, name: str) -> tuple[float, float, float] | None:
        """Where ``name``'s centre truly is (map frame), or None (a world without geometry)."""


class FunctionOracle:
    """An :class:`Oracle` over a truth function, an injection log and, in a world with geometry,
    where things are (both worlds use it)."""

    def __init__(self, holds: Callable[[Atom], bool], injected: Callable[[], list[InjectedSituation]],
                 position: Callable[[str], tuple[float, float, float] | None] | None = None) -> None:
        self._holds, self._injected, self._position = holds, injected, position

    def position(self, name: str) -> tuple[float, float, float] | None:
        return self._position(name) if self._position is not None else None

    def holds(self, atom: Atom) -> bool:
        return self._holds(atom)

    def true_atoms(self, candidates: Iterable[Atom]) -> frozenset[Atom]:
        return frozenset(a for a in candidates if self._holds(a))

    def injected(self) -> list[InjectedSituation]:
        return self._injected()
