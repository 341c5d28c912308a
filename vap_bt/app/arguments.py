"""Command-line arguments derived from the settings' declarations (:mod:`vap_bt.settings`).

Each field of a settings model that names a command in its :class:`~vap_bt.settings.Option`
becomes one ``argparse`` argument of that command: the flag and metavar from the option, the help
text from the field's description, the choices from a ``Literal`` type, and for numbers a type
check that applies the field's own bounds (``--claim-risk 0.7`` is refused by argparse, in one
line naming the flag, exactly as a task file's ``options:`` or the config itself refuse it). Flags
are never written twice: a new field is a new flag.
"""

from __future__ import annotations

import argparse
import types
import typing
from typing import Any, Callable, Literal

from pydantic import TypeAdapter, ValidationError
from pydantic.fields import FieldInfo

from vap_bt.settings import Option, settings_fields


def add_settings(parser: argparse.ArgumentParser, command: str, *models: type) -> None:
    """Add to ``parser`` the arguments ``command`` takes from ``models`` (in their titled groups)."""
    places: dict[str, Any] = {}
    for model in models:
        for name, info, option in settings_fields(model):
            if option is not None and option.flag is not None and command in option.commands:
                place = _place(parser, option, places)
                place.add_argument(*_names(option), **_keywords(name, info, option, command))


def _place(parser: argparse.ArgumentParser, option: Option, places: dict[str, Any]):
    """Where an option is added: its titled group (one per title), a mutually exclusive group
    with its partners, or the parser itself."""
    if option.exclusive:
        key = f"exclusive {option.exclusive}"
        if key not in places:
            places[key] = parser.add_mutually_exclusive_group()
        return places[key]
    if option.group:
        if option.group not in places:
            existing = [g for g in parser._action_groups if g.title == option.group]
            places[option.group] = existing[0] if existing else parser.add_argument_group(option.group)
        return places[option.group]
    return parser


def _names(option: Option) -> tuple[str, ...]:
    return (option.short, option.flag) if option.short else (option.flag,)


def _keywords(name: str, info: FieldInfo, option: Option, command: str) -> dict[str, Any]:
    kw: dict[str, Any] = {"help": option.help(command, info.description)}
    if not info.is_required():  # a required positional takes no default
        kw["default"] = _default(info, option)
    if option.flag.startswith("-"):
        kw["dest"] = name
    elif option.flag != name:
        raise ValueError(f"a positional argument is named for its field: {option.flag!r} is not {name!r}")
    base = _plain(info.annotation)
    if base is bool:  # given, the flag says the opposite of the default (--no-injection, --json)
        return {**kw, "action": "store_const", "const": not info.default}
    if typing.get_origin(_optional(info.annotation)) is list and not option.nargs:
        kw["action"] = "append"  # a repeatable flag (--connect A --connect B)
    if typing.get_origin(base) is Literal:
        kw["choices"] = list(typing.get_args(base))
    elif base in (int, float):
        kw["type"] = _checked(base, info, option)
    if option.metavar:
        kw["metavar"] = option.metavar
    if option.nargs:
        kw["nargs"] = option.nargs
    return kw


def _default(info: FieldInfo, option: Option) -> Any:
    """None (not given) for what a task file may state, so its word stands unless the flag is given;
    else the command's own default, else the field's."""
    if option.cli_default is not None:
        return option.cli_default
    if option.in_task:
        return None
    return info.get_default(call_default_factory=True)


def _optional(annotation: Any) -> Any:
    """``X`` of ``X | None``."""
    if isinstance(annotation, types.UnionType) or typing.get_origin(annotation) is typing.Union:
        return next(a for a in typing.get_args(annotation) if a is not type(None))
    return annotation


def _plain(annotation: Any) -> Any:
    """``X`` of ``X | None``; ``list[X]`` (a repeatable flag, or one with nargs) as ``X``."""
    annotation = _optional(annotation)
    if typing.get_origin(annotation) is list:
        annotation = typing.get_args(annotation)[0]
    return annotation


def _checked(base: type, info: FieldInfo, option: Option) -> Callable[[str], Any]:
    """An argparse type: ``base`` read from the text, then the field's own bounds applied (argparse
    names the option in the one line it says)."""
    bounds = [m for m in info.metadata if not isinstance(m, Option)]
    adapter = TypeAdapter(typing.Annotated[base, *bounds]) if bounds else None

    def check(text: str):
        try:
            value = base(text)
        except ValueError:
            if option.expects is None:
                raise  # argparse says "invalid int value: 'abc'"
            raise argparse.ArgumentTypeError(f"{text!r} is not {option.expects}") from None
        if adapter is None:
            return value
        try:
            return adapter.validate_python(value)
        except ValidationError as exc:
            raise argparse.ArgumentTypeError(f"{text!r} is not {option.expects}" if option.expects
                                             else f"{text!r}: {exc.errors()[0]['msg'].lower()}") from None

    check.__name__ = base.__name__
    return check
