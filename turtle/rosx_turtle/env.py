"""What turtlesim's programs need from the outside world, passed in rather than read deep down.

`Env` is structural: the CLI's own environment object (streams and variables) fits it, and so
does `ProcessEnv`, the process's own.
"""

from __future__ import annotations

import os
import sys
from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    from collections.abc import Mapping
    from typing import TextIO


class Env(Protocol):
    """Streams and environment variables of one program run."""

    stdout: TextIO
    stderr: TextIO
    stdin: TextIO
    environ: Mapping[str, str]


class ProcessEnv:
    """The process's streams and environment."""

    def __init__(self) -> None:
        self.stdout: TextIO = sys.stdout
        self.stderr: TextIO = sys.stderr
        self.stdin: TextIO = sys.stdin
        self.environ: Mapping[str, str] = dict(os.environ)
