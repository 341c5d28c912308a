"""pybullet, imported without its banner.

pybullet's C extension writes "pybullet build time: …" to the process's standard error when it
is first imported — below the Python level, so neither ``-q`` nor the logging setup can keep it
off a command's output, where it reads like a warning. Every module of the pybullet world imports
the library from here: the first import runs with file descriptor 2 pointed at /dev/null for its
duration, and anything else the import wrote there would be lost with it (it writes nothing else).
"""

from __future__ import annotations

import os
import sys


def _quietly_import():
    sys.stderr.flush()
    saved = os.dup(2)
    try:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), 2)
            import pybullet
    finally:
        os.dup2(saved, 2)
        os.close(saved)
    return pybullet


pb = _quietly_import()
