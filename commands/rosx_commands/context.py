"""What a command needs from the outside world, passed in rather than read deep in the stack."""

from __future__ import annotations

import os
import sys
from collections.abc import Mapping
from enum import IntEnum

from rosx.terminal import is_terminal

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import TextIO

    from rosx.master.client import MasterClient
    from rosx.names.remap_args import RemapArgs

#: Seconds a tool waits for the master before saying it is not there (ROS 1 may take minutes).
MASTER_TIMEOUT = 2.0


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
        """Whether stdout is a terminal (colours and live redraws only then)."""
        return is_terminal(self.stdout)

    @property
    def stderr_isatty(self) -> bool:
        """Whether stderr is a terminal."""
        return is_terminal(self.stderr)

    @property
    def master_uri(self) -> str:
        """The master the command talks to (``ROS_MASTER_URI``, or the default)."""
        from rosx.master.defaults import master_uri  # noqa: PLC0415 - only tools that need it

        return master_uri(self.environ)

    def master(self, caller_id: str) -> MasterClient:
        """A client of the master, calling as ``caller_id``."""
        from rosx.master.client import MasterClient  # noqa: PLC0415 - only tools that need it

        return MasterClient(self.master_uri, caller_id, timeout=MASTER_TIMEOUT)

    def out(self, text: str = "") -> None:
        """Print a line to stdout."""
        self.stdout.write(text + "\n")

    def err(self, text: str = "") -> None:
        """Print a line to stderr."""
        self.stderr.write(text + "\n")


class CommandError(Exception):
    """A user's mistake: ``message`` goes to stderr as is, the command exits with ``status``."""

    def __init__(self, message: str, status: int = ExitStatus.ERROR) -> None:
        super().__init__(message)
        self.message = message
        self.status = status
