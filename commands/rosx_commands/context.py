"""What a command needs from the outside world, passed in rather than read deep in the stack."""

from __future__ import annotations

import os
import sys
from collections.abc import Mapping
from enum import IntEnum
from typing import TYPE_CHECKING, TextIO

if TYPE_CHECKING:
    from rosx.names.remap_args import RemapArgs


class ExitStatus(IntEnum):
    """Exit codes, as ROS 1's tools use them."""

    OK = 0
    ERROR = 1
    USAGE = 2  # optparse's status for a bad option or argument
    NOT_FOUND = 3  # rosrun: no such executable
    EX_USAGE = 64  # rostopic/rosnode/rosservice/rosmsg: unknown or missing sub-command


class Environment:
    """Streams and environment variables of one command run (the process's by default)."""

    # A plain class: importing dataclasses would cost every command ~15 ms of start-up.
    def __init__(
        self,
        stdout: TextIO | None = None,
        stderr: TextIO | None = None,
        stdin: TextIO | None = None,
        environ: Mapping[str, str] | None = None,
    ) -> None:
        self.stdout = sys.stdout if stdout is None else stdout
        self.stderr = sys.stderr if stderr is None else stderr
        self.stdin = sys.stdin if stdin is None else stdin
        self.environ = dict(os.environ) if environ is None else environ
        #: The command line's remapping arguments (``__name:=``, ``from:=to``, ``_param:=``),
        #: for a tool that runs as a node, as rospy's ``init_node`` reads them.
        self.remap_args: RemapArgs | None = None

    @property
    def stdout_isatty(self) -> bool:
        isatty = getattr(self.stdout, "isatty", None)
        return bool(isatty and isatty())

    @property
    def stderr_isatty(self) -> bool:
        isatty = getattr(self.stderr, "isatty", None)
        return bool(isatty and isatty())

    def out(self, text: str = "") -> None:
        """Print a line to stdout."""
        self.stdout.write(text + "\n")

    def err(self, text: str = "") -> None:
        """Print a line to stderr."""
        self.stderr.write(text + "\n")


class CommandError(Exception):
    """A user's mistake: ``message`` goes to stderr as is, the command exits with ``status``.

    ``hint`` (what to do about it) follows the message only when stderr is a terminal, so that
    scripts and ROS 1's tests reading stderr see ROS 1's text alone.
    """

    def __init__(self, message: str, status: int = ExitStatus.ERROR, *, hint: str = "") -> None:
        super().__init__(message)
        self.message = message
        self.status = status
        self.hint = hint

    def report(self, env: Environment) -> None:
        """Print the message (and, on a terminal, the hint) to ``env``'s stderr."""
        if self.message:
            env.err(self.message)
        if self.hint and env.stderr_isatty:
            env.err(self.hint)
