"""Zenoh session configuration: loopback by default, a real deployment's file passed through.

Zenoh's own defaults listen on every interface and scout by multicast; a robot executive should
not. So the default here is explicit and local:

* ``listen/endpoints``: only what the caller names (a skill server: ``tcp/127.0.0.1:7448``,
  :data:`DEFAULT_ENDPOINT`); a client listens nowhere,
* ``connect/endpoints``: only what the caller names (a client: the servers' endpoints),
* ``scouting/multicast/enabled: false``,
* a short link lease (:data:`LEASE_MS`, keep-alive every lease/4) so that a hung peer is
  declared dead — and its liveliness tokens vanish — within about two seconds.

An episode run as separate processes (``vap-bt sim``, ``vap-bt serve --world remote``, ``vap-bt
run --connect``) has the sim's session as its hub: a Zenoh *router* listening on
:data:`SIM_ENDPOINT` unless told otherwise, the other parts its *clients* (:func:`part_settings`),
so each part needs one address and the router routes between them. A part given ``--listen`` is
a *peer* instead, reachable there directly as well (peers that listen mesh up by gossip).

``--zenoh-config FILE`` replaces all of that with the file (router, TLS, user/password, access
control); ``--listen``/``--connect`` given as well are written over the file's endpoints.

``zenoh.open`` does not fail when a peer refuses our credentials, or is simply not there: it
opens a lonely session. :func:`open_session` therefore waits, up to ``peer_timeout``, for at
least one peer or router to be connected whenever the configuration says there should be one
(connect endpoints, or client mode), and otherwise raises :class:`~vap_bt.errors.TransportError`
(exit code 4) with one line saying what it tried.

When ``zenoh.open`` does fail (a client whose router is not there, a port already taken) it says
so in Rust's debug form (``Unable to connect to any of [Single(tcp/…)]!``). Every session of the
project is opened here, so :func:`start_failure` turns that into the one line a person can act on:
the endpoint, what is wrong there — a TCP probe tells "nothing listens" from "something listens
and refused us" — and what to do, in the words of the part expected there (:class:`Peer`: the
sim, for the parts of an episode run as separate processes).
"""

from __future__ import annotations

import argparse
import errno
import json
import os
import re
import socket
import time
from dataclasses import dataclass
from pathlib import Path

import zenoh

from vap_bt.errors import TransportError
# the endpoints and waits are options of the commands that open sessions: declared with them
from vap_bt.settings import CAMERA_TIMEOUT_S, DEFAULT_ENDPOINT, PEER_TIMEOUT_S, REJOIN_TIMEOUT_S, SIM_ENDPOINT

#: link lease in ms: a peer silent this long is dropped (and its tokens with it)
LEASE_MS = 2000
KEEP_ALIVE = 4  # keep-alives per lease period


@dataclass(frozen=True)
class Peer:
    """Who a session's connect endpoints should reach and how to bring it up: the words of the
    one line said when it cannot be reached."""

    who: str = "a Zenoh peer or router"
    remedy: str = "start it first, or pass --connect where it listens"


#: the hub of an episode run as separate processes, which its other parts connect to
SIM = Peer("the sim", f"start `vap-bt sim TASK` first (it listens on {SIM_ENDPOINT} unless given --listen), "
                      "or pass --connect where it listens")


@dataclass(frozen=True)
class TransportSettings:
    """How to open a session; built from the command-line options (:class:`vap_bt.settings.Zenoh`)
    by :func:`settings_from_args` or :func:`part_settings`."""

    listen: tuple[str, ...] = ()
    connect: tuple[str, ...] = ()
    config_file: str | None = None
    peer_timeout: float = PEER_TIMEOUT_S
    #: how long a camera (or world-side VLM) request may take, and how long the executive waits for
    #: a vanished skill server's robot to be served again (client.py's defaults)
    camera_timeout: float = CAMERA_TIMEOUT_S
    rejoin_timeout: float = REJOIN_TIMEOUT_S
    mode: str = "peer"
    peer: Peer = Peer()  # who the connect endpoints should reach, for the line said when they do not


def describe(settings: TransportSettings) -> str:
    """Where a session sits on the network, in words for a ``ready`` line: ``router listening on
    tcp/…``, ``connected to tcp/…``, both, or the file that configures it."""
    said = []
    if settings.listen:
        said.append(f"{'router ' if settings.mode == 'router' and not settings.config_file else ''}"
                    f"listening on {', '.join(settings.listen)}")
    if settings.connect:
        said.append(f"connected to {', '.join(settings.connect)}")
    if settings.config_file:
        said.append(f"as {settings.config_file} configures it")
    return ", ".join(said) or "on no endpoint"


def build_config(settings: TransportSettings) -> zenoh.Config:
    """The :class:`zenoh.Config` for ``settings``; a bad file is one TransportError."""
    if settings.config_file:
        conf = _read_file(settings.config_file)
    else:
        conf = zenoh.Config()
        _insert(conf, "mode", settings.mode)
        _insert(conf, "scouting/multicast/enabled", False)
        _insert(conf, "transport/link/tx/lease", LEASE_MS)
        _insert(conf, "transport/link/tx/keep_alive", KEEP_ALIVE)
        _insert(conf, "listen/endpoints", list(settings.listen))
        _insert(conf, "connect/endpoints", list(settings.connect))
    if settings.config_file and settings.listen:
        _insert(conf, "listen/endpoints", list(settings.listen))
    if settings.config_file and settings.connect:
        _insert(conf, "connect/endpoints", list(settings.connect))
    return conf


def open_session(settings: TransportSettings) -> zenoh.Session:
    """Open a session and, if it is meant to reach someone, make sure it did."""
    conf = build_config(settings)
    try:
        session = zenoh.open(conf)
    except zenoh.ZError as exc:
        raise TransportError(start_failure(exc, conf, settings.peer)) from None
    targets = expected_peers(conf)
    if targets is not None and not _wait_for_peer(session, settings.peer_timeout):
        session.close()
        raise TransportError(_unreachable(targets, settings.peer, f"within {settings.peer_timeout:g} s"))
    return session


def start_failure(exc: zenoh.ZError, conf: zenoh.Config, peer: Peer) -> str:
    """The one line for a session ``zenoh.open`` refused: whom it could not reach, or where it
    could not listen, and what to do; Zenoh's own words only for what is neither."""
    text = _short(exc)
    if text.startswith("Unable to connect to any of"):  # a client whose router did not answer
        return _unreachable(expected_peers(conf) or "the configured router", peer)
    taken = _LISTEN_FAILED.search(text)
    if taken:
        return _cannot_listen(taken["endpoint"], int(taken["errno"]))
    where = "; ".join(f"{key} {', '.join(eps)}" for key in ("listen", "connect") if (eps := _endpoints(conf, key)))
    return f"zenoh could not start{f' ({where})' if where else ''}: {text}"


#: how zenoh says a listener could not be bound: ``… listener bound to tcp/h:p: [h:p: … (os error 98) …``
_LISTEN_FAILED = re.compile(r"listener bound to (?P<endpoint>\S+?): .*?\(os error (?P<errno>\d+)\)")


def _unreachable(targets: str, peer: Peer, waited: str = "") -> str:
    """``cannot reach the sim at tcp/…: nothing listens there — start …``."""
    return f"cannot reach {peer.who} at {targets}: {_what_is_there(targets, waited)} — {peer.remedy}"


def _what_is_there(targets: str, waited: str) -> str:
    """What a plain TCP connection finds at the endpoints: Zenoh's refusal and its silence look
    the same, but a port nobody listens on is not a router that refused our credentials."""
    listening = [_tcp_listens(ep) for ep in targets.split(", ")]
    if listening and not any(x is None or x for x in listening):
        return "nothing listens there"
    answered = f"no Zenoh peer or router answered{f' {waited}' if waited else ''}"
    if any(listening):
        return f"something listens there, but {answered} (not a Zenoh router, or credentials or TLS refused)"
    return f"{answered} (not running, wrong address, or credentials refused)"


def _tcp_listens(endpoint: str) -> bool | None:
    """Whether something accepts a TCP connection at a ``tcp/`` or ``tls/`` endpoint (None: another
    protocol, or an address this cannot read)."""
    found = re.fullmatch(r"(?:tcp|tls)/\[?([^\]\s]+?)\]?:(\d+)(?:[?#].*)?", endpoint.strip())
    if found is None:
        return None
    try:
        with socket.create_connection((found[1], int(found[2])), timeout=1.0):
            return True
    except OSError:
        return False


#: why a port could not be listened on, and what to do about it, by errno
_LISTEN_ADVICE = {
    errno.EADDRINUSE: ("another process listens there already (a `vap-bt sim` or `vap-bt serve` still running?)",
                       "stop it, or pass --listen with another port"),
    errno.EADDRNOTAVAIL: ("no network interface of this machine has that address",
                          "pass --listen with one of its addresses, e.g. tcp/127.0.0.1:PORT"),
    errno.EACCES: ("permission denied (ports below 1024 need privileges)", "pass --listen with a port above 1023"),
}


def _cannot_listen(endpoint: str, code: int) -> str:
    why, remedy = _LISTEN_ADVICE.get(code, (os.strerror(code).lower(), "check --listen"))
    return f"cannot listen at {endpoint}: {why} — {remedy}"


def expected_peers(conf: zenoh.Config) -> str | None:
    """A description of whom the session must reach, or None when it need reach nobody."""
    endpoints = _endpoints(conf, "connect")
    if endpoints:
        return ", ".join(endpoints)
    return "the configured router" if _mode(conf) == "client" else None


def _mode(conf: zenoh.Config) -> str:
    return json.loads(conf.get_json("mode") or "null") or "peer"


def _endpoints(conf: zenoh.Config, key: str) -> list[str]:
    """The ``listen`` or ``connect`` endpoints of ``conf`` in its mode."""
    endpoints = json.loads(conf.get_json(f"{key}/endpoints") or "[]")
    if isinstance(endpoints, dict):  # per-mode lists
        endpoints = endpoints.get(_mode(conf), [])
    return list(endpoints)


def _wait_for_peer(session: zenoh.Session, timeout: float) -> bool:
    deadline = time.monotonic() + timeout
    while True:
        info = session.info
        if info.routers_zid() or info.peers_zid():
            return True
        if time.monotonic() >= deadline:
            return False
        time.sleep(0.02)


def _read_file(path: str) -> zenoh.Config:
    if not Path(path).is_file():
        raise TransportError(f"{path}: zenoh config file not found")
    try:
        return zenoh.Config.from_file(path)
    except zenoh.ZError as exc:
        raise TransportError(f"{path}: not a valid zenoh config: {_short(exc)}") from None


def _insert(conf: zenoh.Config, key: str, value: object) -> None:
    try:
        conf.insert_json5(key, json.dumps(value))
    except zenoh.ZError as exc:
        raise TransportError(f"bad zenoh setting {key}={value!r}: {_short(exc)}") from None


def _short(exc: BaseException) -> str:
    """Zenoh's message without the Rust source locations it appends."""
    text = re.sub(r"\s*at /\S+\.rs:\d+\.?\]?", "", str(exc))
    return " ".join(text.split())


def settings_from_args(args: argparse.Namespace, *, default_listen: bool,
                       default_endpoint: str = DEFAULT_ENDPOINT, mode: str = "peer") -> TransportSettings:
    """The transport settings the command-line options in ``args`` give; with no endpoint or file given,
    a part that must be reachable (``default_listen``) listens on ``default_endpoint``."""
    listen = tuple(args.listen)
    if default_listen and not (args.listen or args.connect or args.zenoh_config):
        listen = (default_endpoint,)
    return TransportSettings(listen=listen, connect=tuple(args.connect), config_file=args.zenoh_config,
                             peer_timeout=args.peer_timeout, mode=mode, **_waits(args))


def part_settings(args: argparse.Namespace) -> TransportSettings:
    """A part of an episode that reaches the others through ``vap-bt sim``'s router: a client of
    ``--connect`` (default :data:`SIM_ENDPOINT`), or a peer when it ``--listen``s too."""
    connect = tuple(args.connect) or (() if args.zenoh_config else (SIM_ENDPOINT,))
    return TransportSettings(listen=tuple(args.listen), connect=connect, config_file=args.zenoh_config,
                             peer_timeout=args.peer_timeout, mode="peer" if args.listen else "client", peer=SIM,
                             **_waits(args))


def _waits(args: argparse.Namespace) -> dict[str, float]:
    """The executive's waits, where the command has them (``vap-bt run``: :class:`vap_bt.settings.Zenoh`)."""
    return {"camera_timeout": getattr(args, "camera_timeout", CAMERA_TIMEOUT_S),
            "rejoin_timeout": getattr(args, "rejoin_timeout", REJOIN_TIMEOUT_S)}
