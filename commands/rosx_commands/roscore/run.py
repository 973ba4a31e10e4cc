"""`run_roscore`: a `rosx.core.Core` run as ROS 1's ``roscore`` runs, with what it prints.

roscore (roslaunch with ``roscore.xml``) prints its start-up summary, starts the master, sets
its parameters, starts ``/rosout``, then runs until SIGINT, SIGTERM or a ``shutdown`` call. This
prints the same, in the same order and words (the run's log folder and ``... logging to`` line
come from `rosx.workspace.logdir`, as roslaunch's), except what rosx does not do: no separate
roslaunch server (the master's own URI stands for it). Bold, red and the terminal title are
written only to a terminal.

Exit codes, as roscore's: 0 after a clean stop, 1 when the master cannot start (another master
already runs on the port, or the port is taken).
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, TextIO

from rosx.core import Core, PortInUseError
from rosx.core.params import ROSDISTRO, ROSVERSION
from rosx.launch.run.console import LaunchConsole
from rosx.master.defaults import master_uri
from rosx.signals import STOP_SIGNALS, handling, soon
from rosx.transport.address import address_warnings, foreign_address_warning, is_local_host
from rosx.wire.xmlrpc_http import parse_http_uri
from rosx.workspace.logdir import announce_run_log

if TYPE_CHECKING:
    from collections.abc import Mapping


def _summary_value(value: str) -> str:
    """A parameter value as roslaunch's summary shows it: short, printable, or ``<...>``."""
    if len(value) > 20:
        value = value[:17] + "..."
    if all(32 <= ord(char) <= 126 for char in value):
        return value
    stripped = value.rstrip()  # trailing whitespace such as rosversion's newline is dropped
    return stripped if all(32 <= ord(char) <= 126 for char in stripped) else "<...>"


def _print_summary(out: LaunchConsole) -> None:
    out.line(f"ros_comm version {ROSVERSION}")
    params = {"/rosdistro": ROSDISTRO, "/rosversion": ROSVERSION}
    lines = sorted(f" * {key}: {_summary_value(value)}" for key, value in params.items())
    out.line("\nSUMMARY\n========\n\nPARAMETERS\n" + "\n".join(lines) + "\n\nNODES\n")


def _master_uri_warning(environ: Mapping[str, str], port: int) -> str | None:
    uri = master_uri(environ)
    try:
        host, env_port, _ = parse_http_uri(uri)
    except ValueError:
        return None
    if not is_local_host(host):
        return f"WARNING: ROS_MASTER_URI [{uri}] host is not set to this machine"
    if env_port != port:
        return f"WARNING: ROS_MASTER_URI port [{env_port}] does not match this roscore [{port}]"
    return None


def _refuse(out: LaunchConsole, refused: PortInUseError) -> int:
    """Explain, as roscore does, why the master could not start; the exit code. Called while
    `PortInUseError` is handled: its traceback goes to the log, as roslaunch's does."""
    _print_summary(out)
    if refused.another_master:
        out.error(refused.message)
    else:
        out.line("auto-starting new master")
        out.bold(f"process[master]: started with pid [{os.getpid()}]")
        out.line(refused.message)
        out.error(f"RLException: ERROR: could not contact master [{refused.uri}]")
    if out.logging:
        out.error("The traceback for the exception was written to the log file")
        out.log_traceback()
    return 1


def _print_started(out: LaunchConsole, core: Core) -> None:
    out.bold(f"started roslaunch server {core.uri}")
    _print_summary(out)
    uri_warning = _master_uri_warning(core.environ, core.port)
    if uri_warning:
        out.error(uri_warning)
    out.line("auto-starting new master")
    out.bold(f"process[master]: started with pid [{os.getpid()}]")
    out.bold(f"ROS_MASTER_URI={core.uri}")
    out.title(f"roscore {core.uri}")
    out.bold(f"setting /run_id to {core.run_id}")
    out.bold(f"process[rosout-1]: started with pid [{os.getpid()}]")
    out.line("started core service [/rosout]")


def _print_stopping(out: LaunchConsole, message: str | None) -> None:
    if message is not None:
        # rosmaster's words, misspelling included, for a shutdown call without a message.
        out.line(f"shutdown request: {message}" if message else "shutdown requst")
    out.line("[rosout-1] killing on exit")
    out.line("[master] killing on exit")
    out.line("shutting down processing monitor...")


class _StopSignals:
    """SIGINT and SIGTERM stop roscore from the moment it starts. One that comes while the core
    starts or the summary prints is kept until `wait`, so roscore's start-up lines and its
    shutdown lines are always printed whole. The handler notes the signal and has a thread of
    its own end the core's wait (`rosx.signals.soon`): raised into the main thread as it waits,
    an exception may leave the wait's lock held, and roscore hung as it stopped."""

    def __init__(self, core: Core) -> None:
        self.received = False
        self._core = core
        self._handling = handling(STOP_SIGNALS, self._handle)

    def __enter__(self) -> _StopSignals:
        self._handling.__enter__()
        return self

    def __exit__(self, *exc: object) -> None:
        self._handling.__exit__(None, None, None)

    def _handle(self, signum: int) -> None:
        self.received = True
        soon(self._core.interrupt)

    def wait(self) -> str | None:
        """Wait for a stop signal or a ``shutdown`` call; the call's message (None for a
        signal)."""
        message = self._core.wait()
        return None if self.received else message


def run_roscore(
    port: int,
    environ: Mapping[str, str],
    stdout: TextIO,
    stderr: TextIO | None = None,
    *,
    color: bool | None = None,
) -> int:
    """Run roscore on `port` until SIGINT, SIGTERM or a ``shutdown`` call; the exit code.

    Args:
        port: The master's port (roscore's ``-p``; 11311 by default there).
        environ: The environment (ROS_IP, ROS_HOSTNAME, ROS_MASTER_URI are read).
        stdout: Where the start-up summary and progress go.
        stderr: Where errors and warnings go (`stdout` if not given).
        color: Bold, red and terminal title; by default each stream gets them if it is a
            terminal.

    Signals are caught only on the main thread (elsewhere only a ``shutdown`` call stops it).
    """
    out = LaunchConsole(stdout, stderr if stderr is not None else stdout, color=color)
    for warning in address_warnings(environ):
        out.error(warning)
    foreign = foreign_address_warning(environ)
    if foreign is not None:
        out.error(foreign)
    core = Core(port, environ)
    log = announce_run_log(environ, core.run_id, out=out.line, err=out.error)
    if log is not None:
        out.open_log(log)
    try:
        out.title("roscore")
        with _StopSignals(core) as signals:
            try:
                core.start()
            except PortInUseError as refused:
                return _refuse(out, refused)
            try:
                _print_started(out, core)
                _print_stopping(out, signals.wait())
            finally:
                core.stop()
        out.line("... shutting down processing monitor complete")
        out.bold("done")
        return 0
    finally:
        out.close()
