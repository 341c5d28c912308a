"""Errors a user can cause, each with its documented exit code.

Every error that reaches the command line is a :class:`VapBtError`: the CLI prints its one-line
message (naming the file, line or field at fault) and exits with its code, never a traceback.

====  =====================================================================
code  meaning
====  =====================================================================
0     the run succeeded (the executive's claim and the world agree)
1     the run ended without reaching the goal
2     bad input: a file, field or argument is wrong (:class:`InputError`)
3     no plan exists for the problem as given (:class:`UnsolvableError`)
4     the transport could not be brought up (:class:`TransportError`)
5     the planner ran out of time before it found a plan (:class:`PlanningTimeout`)
130   interrupted (Ctrl-C, SIGINT): a run still writes its report so far
====  =====================================================================
"""

from __future__ import annotations

from pathlib import Path

EXIT_OK = 0
EXIT_GOAL_NOT_REACHED = 1
EXIT_BAD_INPUT = 2
EXIT_UNSOLVABLE = 3
EXIT_TRANSPORT = 4
EXIT_PLANNING_TIMEOUT = 5
EXIT_INTERRUPTED = 130  # the shell's 128 + SIGINT


class VapBtError(Exception):
    """An error the user can cause: the CLI prints its message and exits with ``exit_code``, never a
    traceback."""

    exit_code = 1


class InputError(VapBtError):
    """Bad input; ``where`` names the file (and line or field) at fault."""

    exit_code = EXIT_BAD_INPUT

    def __init__(self, where: str, message: str) -> None:
        super().__init__(f"{where}: {message}")
        self.where = where


class UnsolvableError(VapBtError):
    """No plan reaches the goal: the planner proved it, or the search space is exhausted."""

    exit_code = EXIT_UNSOLVABLE


class PlanningTimeout(VapBtError):
    """The planner gave up at its time limit: a plan may exist, none was found in time."""

    exit_code = EXIT_PLANNING_TIMEOUT


class TransportError(VapBtError):
    """A process the run needs is not there: a server that never came up or said ready, or one that went
    away (a skill server, a VLM server, a simulator)."""

    exit_code = EXIT_TRANSPORT


def read_text(path: str | Path) -> str:
    """A file the user wrote (a task file, a PDDL file), as UTF-8 text; bytes that are not UTF-8
    (a file saved in another encoding) are an :class:`InputError` naming the file and line."""
    data = Path(path).read_bytes()
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        raise InputError(f"{path}:{line}", f"not UTF-8 text (byte {data[exc.start]:#04x}); "
                                           "save the file as UTF-8") from None
