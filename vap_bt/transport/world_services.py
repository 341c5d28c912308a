"""What a simulator offers over Zenoh besides its robot's drivers: the world-side VLM and the oracle.

When the pybullet world runs in a process of its own (``vap-bt sim``), two things that only a
simulation has must still reach the others:

* the **simulated VLM** answers from the world's record of each frame its camera took
  (:class:`~vap_bt.sim.sim_vlm.SimVLM`), so it can only run beside the world. :class:`VlmServer`
  answers ``vap/<robot>/vlm/ask`` — the key the embedded transport's arm server answers — and the
  executive's :class:`~vap_bt.transport.client.ZenohVLM` cannot tell where it is. Only the frame's
  id travels: the world that rendered it knows what it showed.
* the **oracle**, which the runner scores its report by (did the goal really hold, what did the
  world inject, how good was each scene graph). :class:`OracleServer` answers
  ``vap/world/oracle/<verb>``; the runner's :class:`RemoteWorld` offers what the runner reads of
  an in-process world — ``name``, ``oracle`` (``holds``, ``true_atoms``, ``injected``),
  ``site_map()``, ``situations.describe()``, ``detector.describe()``, ``reset(seed)`` — so the
  runner scores an episode the same way wherever the world is. The executive is never given any
  of it (the one rule): only the runner holds a RemoteWorld.

``reset(seed)`` starts the world (and the VLM's random stream) over for an episode, as the runner
does with an in-process world; the skill servers' kits notice the robot starting over.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Any, Callable, Iterable

import zenoh

from vap_bt.domain.atoms import Atom
from vap_bt.robot.frame import marked_frame
from vap_bt.robot.site_map import SiteMap
from vap_bt.transport import keys
from vap_bt.transport.client import first_reply
from vap_bt.transport.messages import (ErrorReply, MessageError, OracleQuery, OracleReply, VlmRequest, decode,
                                       encode)
from vap_bt.world import InjectedSituation

log = logging.getLogger(__name__)

#: verbs of the oracle queryable
VERBS = ("holds", "injected", "info", "site_map", "reset")
#: how long the runner waits for the oracle (a reset rebuilds the pybullet scene: seconds)
ORACLE_TIMEOUT_S = 10.0
RESET_TIMEOUT_S = 120.0


def _queryable(handler: Callable[[bytes], Any], what: str) -> Callable[[zenoh.Query], None]:
    """A queryable callback answering with ``handler``'s message, or one ErrorReply."""

    def on_query(query: zenoh.Query) -> None:
        try:
            answer = handler(query.payload.to_bytes() if query.payload else b"")
        except MessageError as exc:
            answer = ErrorReply(f"bad {what} request: {exc}")
        except Exception as exc:  # the world's failure is the caller's answer, not our crash
            log.exception("%s failed", what)
            answer = ErrorReply(f"{what} failed: {type(exc).__name__}: {exc}")
        query.reply(query.key_expr, encode(answer))

    return on_query


class VlmServer:
    """Answers ``vap/<robot>/vlm/ask`` with a world-side VLM (``vlm.ask(query, frame)``)."""

    def __init__(self, session: zenoh.Session, robot: str, vlm: Any) -> None:
        self.vlm = vlm
        self._declared = session.declare_queryable(keys.vlm(robot), _queryable(self._ask, "vlm"))

    def _ask(self, payload: bytes) -> Any:
        req = decode(payload, VlmRequest)
        return self.vlm.ask(req.query, marked_frame(req.frame_id, req.identified))

    def close(self) -> None:
        self._declared.undeclare()


@dataclass
class WorldFacts:
    """What the oracle server needs to know beyond the world itself."""

    task: str  # the task's name, so a runner of another task is told so
    vlm: Any = None  # the world-side VLM: reseeded with the world, described in ``info``


class OracleServer:
    """Answers ``vap/world/oracle/<verb>`` for ``world`` (a simulated one: it has an ``oracle``)."""

    def __init__(self, session: zenoh.Session, world: Any, facts: WorldFacts) -> None:
        self.world, self.facts = world, facts
        handlers = {"holds": self._holds, "injected": self._injected, "info": self._info,
                    "site_map": lambda q: self.world.site_map(), "reset": self._reset}
        self._declared = [session.declare_queryable(keys.oracle(verb), _queryable(lambda p, h=h: h(
            decode(p, OracleQuery)), f"oracle {verb}")) for verb, h in handlers.items()]

    def _holds(self, q: OracleQuery) -> OracleReply:
        return OracleReply({"holds": [bool(self.world.oracle.holds(a)) for a in q.atoms]})

    def _injected(self, q: OracleQuery) -> OracleReply:
        return OracleReply({"injected": [i.to_json() for i in self.world.oracle.injected()]})

    def _info(self, q: OracleQuery) -> OracleReply:
        w, vlm = self.world, self.facts.vlm
        detector = getattr(w, "detector", None)
        situations = getattr(w, "situations", None)
        return OracleReply({"name": w.name, "task": self.facts.task, "seed": getattr(w, "seed", None),
                            "injection": bool(getattr(situations, "enabled", False)),
                            "situations": situations.describe() if situations is not None else [],
                            "detector": detector.describe() if detector is not None else None,
                            "vlm": vlm.describe() if vlm is not None else None})

    def _reset(self, q: OracleQuery) -> OracleReply:
        if q.seed is None:
            raise MessageError("reset needs a seed")
        self.world.reset(int(q.seed))
        if self.facts.vlm is not None:
            self.facts.vlm.reseed(int(q.seed))
        log.info("world reset to seed %s", q.seed)
        return OracleReply({"seed": int(q.seed)})

    def close(self) -> None:
        for entity in self._declared:
            entity.undeclare()
        self._declared.clear()


# -- the runner's side -----------------------------------------------------------------------------


class RemoteOracle:
    """The :class:`~vap_bt.sim.oracle.Oracle` of a world served by an :class:`OracleServer`."""

    def __init__(self, ask: Callable[..., Any]) -> None:
        self._ask = ask

    def holds(self, atom: Atom) -> bool:
        """Whether ``atom`` holds in the world now."""
        return self._ask("holds", atoms=(atom,)).values["holds"][0]

    def true_atoms(self, candidates: Iterable[Atom]) -> frozenset[Atom]:
        """Those of ``candidates`` that hold in the world now (one query for all of them)."""
        atoms = tuple(candidates)
        truth = self._ask("holds", atoms=atoms).values["holds"]
        return frozenset(a for a, t in zip(atoms, truth) if t)

    def injected(self) -> list[InjectedSituation]:
        """The situations the world caused this episode, in order."""
        rows = self._ask("injected").values["injected"]
        return [InjectedSituation.from_json(r) for r in rows]


class _Described:
    """Stands for a world part the report only describes (its situation model, its detector)."""

    def __init__(self, describe: Callable[[], Any]) -> None:
        self.describe = describe


class RemoteWorld:
    """What the runner reads of a world that runs in another process (see the module docstring)."""

    def __init__(self, session: zenoh.Session, timeout: float = ORACLE_TIMEOUT_S) -> None:
        self.session, self.timeout = session, timeout
        self.oracle = RemoteOracle(self._ask)
        self.situations = _Described(lambda: self.info()["situations"])
        self.detector = _Described(lambda: self.info()["detector"])
        self._info: dict | None = None

    def info(self) -> dict:
        """The world's name, task, seed, situation model, detector and VLM (asked once per reset)."""
        if self._info is None:
            self._info = self._ask("info").values
        return self._info

    @property
    def name(self) -> str:
        return str(self.info()["name"])

    def reset(self, seed: int) -> None:
        """Start the world and its VLM over from ``seed`` for an episode; blocks until the world says it
        is done (a :class:`~vap_bt.errors.TransportError` if none answers within ``RESET_TIMEOUT_S``)."""
        self._ask("reset", seed=int(seed), timeout=RESET_TIMEOUT_S)
        self._info = None

    def site_map(self) -> SiteMap:
        """The world's site map, as its robot is given it."""
        return self._ask("site_map", expect=SiteMap)

    def close(self) -> None:
        """Nothing to withdraw: the world is the sim process's, and stays up."""

    def _ask(self, verb: str, atoms: tuple[Atom, ...] = (), seed: int | None = None,
             expect: type = OracleReply, timeout: float | None = None) -> Any:
        timeout = self.timeout if timeout is None else timeout
        payload = encode(OracleQuery(verb, tuple(atoms), seed))
        return first_reply(self.session.get(keys.oracle(verb), payload=payload, timeout=timeout), expect,
                           f"the simulated world's oracle ({verb})",
                           f"no simulated world answered {keys.oracle(verb)} within {timeout:g} s "
                           "(is `vap-bt sim` running and reachable?)")
