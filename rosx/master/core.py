"""``roscore``: the master, its standard parameters and the core services, in one process.

`run_core` does what ROS 1's ``roscore`` does (roslaunch with ``roscore.xml``): it starts the
master on the given port, sets ``/rosversion``, ``/rosdistro``, ``/run_id`` and
``/roslaunch/uris/host_<host>__<port>``, starts the core services (the ``/rosout`` node, through
a hook), prints roscore's start-up summary, and runs until SIGINT, SIGTERM or a ``shutdown``
call. It prints what roscore prints, in the same order and words, except what rosx does not do:
no log files (so no "logging to" lines), and no separate roslaunch server (the master's own
URI stands for it). Bold, red and the terminal title are written only to a terminal.

Exit codes, as roscore's: 0 after a clean stop, 1 when the master cannot start (another master
already runs on the port, or the port is taken).
"""

from __future__ import annotations

import asyncio
import errno
import os
import signal
import uuid
from typing import TYPE_CHECKING, TextIO

from rosx.master.server import Master
from rosx.transport.aclient import AsyncXmlRpcClient
from rosx.transport.address import (
    address_warnings,
    advertised_host,
    bind_host,
    http_uri,
    is_local_host,
)
from rosx.transport.errors import FaultError, TransportError
from rosx.wire.xmlrpc_http import parse_http_uri

if TYPE_CHECKING:
    from collections.abc import Awaitable, Callable, Mapping

    from rosx.master.api import MasterApi

    #: A core service (the ``/rosout`` node): started with the master's URI once the master is
    #: up, on the master's event loop; returns a coroutine function that stops it, or None.
    CoreService = Callable[[str], Awaitable[Callable[[], Awaitable[None]] | None]]

#: What ROS 1 Noetic's roscore stores: the output of ``rosversion roslaunch`` and
#: ``rosversion -d``, trailing newline included.
ROSVERSION = "1.16.0\n"
ROSDISTRO = "noetic\n"
DEFAULT_MASTER_URI = "http://localhost:11311"
_LAUNCH_CALLER = "/roslaunch"


def host_param_name(host: str, port: int) -> str:
    """``/roslaunch/uris/host_<host>__<port>``: roslaunch's key, `host` made a legal name."""
    legal = "".join(c if c.isascii() and c.isalnum() else "_" for c in host.lower())
    return f"/roslaunch/uris/host_{legal}__{port}"


def set_core_params(api: MasterApi, run_id: str) -> None:
    """Set the parameters roscore sets: version, distribution, run id, launch URI."""
    host, port, _ = parse_http_uri(api.uri)
    api.call("setParam", _LAUNCH_CALLER, "/run_id", run_id)
    api.call("setParam", _LAUNCH_CALLER, host_param_name(host, port), api.uri)
    api.call("setParam", _LAUNCH_CALLER, "/rosversion", ROSVERSION)
    api.call("setParam", _LAUNCH_CALLER, "/rosdistro", ROSDISTRO)


def _summary_value(value: str) -> str:
    """A parameter value as roslaunch's summary shows it: short, printable, or ``<...>``."""
    if len(value) > 20:
        value = value[:17] + "..."
    if all(32 <= ord(char) <= 126 for char in value):
        return value
    stripped = value.rstrip()  # trailing whitespace such as rosversion's newline is dropped
    return stripped if all(32 <= ord(char) <= 126 for char in stripped) else "<...>"


class _Printer:
    """roslaunch's console output: plain lines, bold lines, red errors, the terminal title."""

    def __init__(self, stdout: TextIO, stderr: TextIO, color: bool, error_color: bool) -> None:
        self.stdout, self.stderr = stdout, stderr
        self.color, self.error_color = color, error_color

    def line(self, text: str = "") -> None:
        self.stdout.write(text + "\n")
        self.stdout.flush()

    def bold(self, text: str) -> None:
        self.line(f"\033[1m{text}\033[0m" if self.color else text)

    def title(self, text: str) -> None:
        if self.color:
            self.line(f"\033]2;{text}\007")

    def error(self, text: str) -> None:
        self.stderr.write((f"\033[31m{text}\033[0m" if self.error_color else text) + "\n")
        self.stderr.flush()


def _print_summary(out: _Printer) -> None:
    out.line(f"ros_comm version {ROSVERSION}")
    params = {"/rosdistro": ROSDISTRO, "/rosversion": ROSVERSION}
    lines = sorted(f" * {key}: {_summary_value(value)}" for key, value in params.items())
    out.line("\nSUMMARY\n========\n\nPARAMETERS\n" + "\n".join(lines) + "\n\nNODES\n")


def _master_uri_warning(environ: Mapping[str, str], port: int) -> str | None:
    uri = environ.get("ROS_MASTER_URI") or DEFAULT_MASTER_URI
    try:
        host, env_port, _ = parse_http_uri(uri)
    except ValueError:
        return None
    if not is_local_host(host):
        return f"WARNING: ROS_MASTER_URI [{uri}] host is not set to this machine"
    if env_port != port:
        return f"WARNING: ROS_MASTER_URI port [{env_port}] does not match this roscore [{port}]"
    return None


async def _master_answers(uri: str) -> bool:
    client = AsyncXmlRpcClient(timeout=3.0)
    try:
        await client.call(uri, "getPid", _LAUNCH_CALLER)
    except (TransportError, FaultError):
        return False
    finally:
        await client.close()
    return True


async def _refuse(out: _Printer, uri: str, port: int, exc: OSError) -> int:
    """Explain, as roscore does, why the master could not start; the exit code."""
    _print_summary(out)
    if exc.errno == errno.EADDRINUSE and await _master_answers(uri):
        out.error(
            "RLException: roscore cannot run as another roscore/master is already running. \n"
            "Please kill other roscore/master processes before relaunching.\n"
            f"The ROS_MASTER_URI is {uri}"
        )
        return 1
    out.line("auto-starting new master")
    out.bold(f"process[master]: started with pid [{os.getpid()}]")
    if exc.errno == errno.EADDRINUSE:
        out.line(f"ERROR: Unable to start XML-RPC server, port {port} is already in use")
    else:
        out.line(f"ERROR: Unable to start XML-RPC server: {exc.strerror or exc}")
    out.error(f"RLException: ERROR: could not contact master [{uri}]")
    return 1


class _StopSignals:
    """SIGINT and SIGTERM set `event` from the moment the core starts, so none is missed."""

    def __init__(self) -> None:
        self.event = asyncio.Event()
        self._loop = asyncio.get_running_loop()
        self._handled: list[signal.Signals] = []
        for sig in (signal.SIGINT, signal.SIGTERM):
            try:
                self._loop.add_signal_handler(sig, self.event.set)
                self._handled.append(sig)
            except (NotImplementedError, RuntimeError, ValueError):
                pass  # not the main thread, or no loop signal support: KeyboardInterrupt stops us

    def restore(self) -> None:
        for sig in self._handled:
            self._loop.remove_signal_handler(sig)


async def _wait_for_stop(master: Master, stop: asyncio.Event) -> str | None:
    """Wait for a stop signal or a ``shutdown`` call; the call's message (None for a signal)."""
    assert master.shutdown_requested is not None
    waits = [
        asyncio.ensure_future(stop.wait()),
        asyncio.ensure_future(master.shutdown_requested.wait()),
    ]
    try:
        await asyncio.wait(waits, return_when=asyncio.FIRST_COMPLETED)
    finally:
        for task in waits:
            task.cancel()
    return master.shutdown_message if master.shutdown_requested.is_set() else None


async def _core(
    port: int,
    environ: Mapping[str, str],
    out: _Printer,
    start_rosout: CoreService | None,
) -> int:
    for warning in address_warnings(environ):
        out.error(warning)
    host = advertised_host(environ)
    uri = http_uri(host, port)
    out.title("roscore")
    signals = _StopSignals()
    master = Master(host=bind_host(environ), port=port, advertised_host=host)
    try:
        await master.start()
    except OSError as exc:
        signals.restore()
        return await _refuse(out, uri, port, exc)
    try:
        run_id = str(uuid.uuid1())
        out.bold(f"started roslaunch server {master.uri}")
        _print_summary(out)
        uri_warning = _master_uri_warning(environ, master.port)
        if uri_warning:
            out.error(uri_warning)
        out.line("auto-starting new master")
        out.bold(f"process[master]: started with pid [{os.getpid()}]")
        out.bold(f"ROS_MASTER_URI={master.uri}")
        out.title(f"roscore {master.uri}")
        set_core_params(master.api, run_id)
        out.bold(f"setting /run_id to {run_id}")
        stop_rosout = None
        if start_rosout is not None:
            stop_rosout = await start_rosout(master.uri)
            out.bold(f"process[rosout-1]: started with pid [{os.getpid()}]")
            out.line("started core service [/rosout]")
        message = await _wait_for_stop(master, signals.event)
        if message is not None:
            # rosmaster's words, misspelling included, for a shutdown call without a message.
            out.line(f"shutdown request: {message}" if message else "shutdown requst")
        if start_rosout is not None:
            out.line("[rosout-1] killing on exit")
        out.line("[master] killing on exit")
        out.line("shutting down processing monitor...")
        if stop_rosout is not None:
            await stop_rosout()
    finally:
        await master.close()
        signals.restore()
    out.line("... shutting down processing monitor complete")
    out.bold("done")
    return 0


def run_core(
    port: int,
    environ: Mapping[str, str],
    stdout: TextIO,
    stderr: TextIO | None = None,
    *,
    start_rosout: CoreService | None = None,
    color: bool | None = None,
) -> int:
    """Run roscore on `port` until SIGINT, SIGTERM or a ``shutdown`` call; the exit code.

    Args:
        port: The master's port (roscore's ``-p``; 11311 by default there).
        environ: The environment (ROS_IP, ROS_HOSTNAME, ROS_MASTER_URI are read).
        stdout: Where the start-up summary and progress go.
        stderr: Where errors and warnings go (`stdout` if not given).
        start_rosout: The ``/rosout`` node's starter (see `CoreService`); none if not given.
        color: Bold, red and terminal title; by default each stream gets them if it is a
            terminal.

    Must run in the main thread for SIGINT and SIGTERM to be caught (elsewhere only a
    ``shutdown`` call stops it).
    """
    errors = stderr if stderr is not None else stdout
    out = _Printer(
        stdout,
        errors,
        stdout.isatty() if color is None else color,
        errors.isatty() if color is None else color,
    )
    try:
        return asyncio.run(_core(port, environ, out, start_rosout))
    except KeyboardInterrupt:
        return 0
