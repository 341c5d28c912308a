"""Reading a user's YAML file into a pydantic model, each mistake one clear error.

Task files and perception profiles are written by hand. Whatever is wrong with one — it is
missing, it is not YAML, it is not a mapping, a field has the wrong shape — is one
:class:`~vap_bt.errors.InputError` naming the file and the line (YAML) or the field (pydantic),
so that the command line can print it in one line and exit with code 2.
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable, TypeVar

import yaml
from pydantic import BaseModel, ValidationError

from vap_bt.errors import InputError, read_text

M = TypeVar("M", bound=BaseModel)


def read_model(path: str | Path, model: type[M], what: str, shape: str,
               check: Callable[[dict], None] | None = None) -> M:
    """``path`` read as ``model``; ``what`` names the kind of file ("task file"), ``shape`` says
    what its mapping holds, ``check`` may refuse the raw mapping before pydantic reads it."""
    path = Path(path)
    if not path.is_file():
        raise InputError(str(path), f"no such {what}")
    text = read_text(path)
    try:
        raw = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        raise _yaml_error(path, text, exc) from None
    if not isinstance(raw, dict):
        raise InputError(str(path), f"a {what} is a mapping ({shape})")
    if check is not None:
        check(raw)
    try:
        return model.model_validate(raw)
    except ValidationError as exc:
        err = exc.errors()[0]
        field = ".".join(str(x) for x in err["loc"]) or "(top level)"
        raise InputError(f"{path}: field {field}", err["msg"]) from None


def _yaml_error(path: Path, text: str, exc: yaml.YAMLError) -> InputError:
    """The YAML parser's complaint in one line, at the line it names (a character YAML does not
    allow, a ``\\x00``, has a position instead of a mark)."""
    mark = getattr(exc, "problem_mark", None)
    position = getattr(exc, "position", None)
    line = mark.line + 1 if mark else text.count("\n", 0, position) + 1 if position is not None else None
    problem = " ".join(str(getattr(exc, "problem", None) or str(exc).splitlines()[0]).split())
    return InputError(f"{path}:{line}" if line else str(path), f"not valid YAML: {problem}")
