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
"""

from __future__ import annotations

import argparse
import json
import re
import time
from dataclasses import dataclass
from pathlib import Path

import zenoh

from vap_bt.errors import TransportError

#: where ``vap-bt serve`` listens, and clients connect, unless told otherwise
DEFAULT_ENDPOINT = "tcp/127.0.0.1:7448"
#: where ``vap-bt sim`` (the episode's Zenoh router) listens, and its parts connect, by default
SIM_ENDPOINT = "tcp/127.0.0.1:7447"
#: link lease in ms: a peer silent this long is dropped (and its tokens with it)
LEASE_MS = 2000
KEEP_ALIVE = 4  # keep-alives per lease period
#: how long :func:`open_session` waits for the configured peers to answer
PEER_TIMEOUT_S = 5.0


@dataclass(frozen=True)
class TransportSettings:
    """How to open a session; the command-line options map onto this one to one."""

    listen: tuple[str, ...] = ()
    connect: tuple[str, ...] = ()
    config_file: str | None = None
    peer_timeout: float = PEER_TIMEOUT_S
    mode: str = "peer"


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
        raise TransportError(f"zenoh could not start: {_short(exc)}") from None
    targets = expected_peers(conf)
    if targets is not None and not _wait_for_peer(session, settings.peer_timeout):
        session.close()
        raise TransportError(
            f"no Zenoh peer or router answered at {targets} within {settings.peer_timeout:g} s "
            "(not running, wrong address, or credentials refused)"
        )
    return session


def expected_peers(conf: zenoh.Config) -> str | None:
    """A description of whom the session must reach, or None when it need reach nobody."""
    mode = json.loads(conf.get_json("mode") or "null") or "peer"
    endpoints = json.loads(conf.get_json("connect/endpoints") or "[]")
    if isinstance(endpoints, dict):  # per-mode lists
        endpoints = endpoints.get(mode, [])
    if endpoints:
        return ", ".join(endpoints)
    return "the configured router" if mode == "client" else None


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


def add_transport_arguments(parser: argparse.ArgumentParser, *, default_listen: bool,
                            default_endpoint: str = DEFAULT_ENDPOINT, listen_help: str = "",
                            connect_help: str = "") -> None:
    """The Zenoh options every command that opens a session shares."""
    g = parser.add_argument_group("zenoh transport")
    hint = f" (default: {default_endpoint} when nothing else is given)" if default_listen else ""
    g.add_argument("--listen", action="append", default=[], metavar="ENDPOINT",
                   help=listen_help or f"endpoint to listen on, e.g. {default_endpoint}; repeatable{hint}")
    g.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                   help=connect_help or "endpoint of a peer or router to connect to; repeatable")
    g.add_argument("--zenoh-config", metavar="FILE",
                   help="a zenoh JSON5 config used as is (router, TLS, user/password)")
    g.add_argument("--peer-timeout", type=float, default=PEER_TIMEOUT_S, metavar="S",
                   help=f"seconds to wait for configured peers (default {PEER_TIMEOUT_S:g})")


def settings_from_args(args: argparse.Namespace, *, default_listen: bool,
                       default_endpoint: str = DEFAULT_ENDPOINT, mode: str = "peer") -> TransportSettings:
    listen = tuple(args.listen)
    if default_listen and not (args.listen or args.connect or args.zenoh_config):
        listen = (default_endpoint,)
    return TransportSettings(listen=listen, connect=tuple(args.connect),
                             config_file=args.zenoh_config, peer_timeout=args.peer_timeout, mode=mode)


def part_settings(args: argparse.Namespace) -> TransportSettings:
    """A part of an episode that reaches the others through ``vap-bt sim``'s router: a client of
    ``--connect`` (default :data:`SIM_ENDPOINT`), or a peer when it ``--listen``s too."""
    connect = tuple(args.connect) or (() if args.zenoh_config else (SIM_ENDPOINT,))
    return TransportSettings(listen=tuple(args.listen), connect=connect, config_file=args.zenoh_config,
                             peer_timeout=args.peer_timeout, mode="peer" if args.listen else "client")
