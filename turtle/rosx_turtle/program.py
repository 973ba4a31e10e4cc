"""Running one of turtlesim's programs as a process: wait for the master, run until a signal.

As a roscpp node does, a program started before the master is up logs
``[registerPublisher] Failed to contact master at [host:port].  Retrying...`` once at ERROR,
keeps trying, and logs ``Connected to master at [host:port]`` when it gets through. SIGINT and
SIGTERM (handled when the program runs on the main thread) end it cleanly, as does a node
shutdown from outside (``rosnode kill``); the exit status is then 0.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Protocol, TypeVar
from urllib.parse import urlsplit

from rosx.master.client import MasterClient
from rosx.master.defaults import master_uri
from rosx.node import ERROR, INFO
from rosx.signals import stop_on_signals
from rosx.transport.errors import TransportError

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

    from rosx_turtle.console import Console

_RETRY_PERIOD = 0.5


class Running(Protocol):
    """A started program's node, as far as running it goes."""

    def shutdown(self, reason: str = "") -> None:
        """Leave the ROS graph."""

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """Block until shut down; False when ``timeout`` passed first."""


T = TypeVar("T", bound=Running)


def master_address(override: str | None, environ: Mapping[str, str]) -> str:
    """``host:port`` of the master (``__master:=``, else ``ROS_MASTER_URI``, else the default),
    as roscpp names it in its messages."""
    uri = master_uri(environ, override)
    return urlsplit(uri).netloc or uri


def start_when_master_is_up(
    start: Callable[[], T], console: Console, address: str, stop: threading.Event
) -> T | None:
    """``start()`` once the master at ``address`` answers (None if ``stop`` is set first)."""
    failed = False
    master = MasterClient(f"http://{address}/", "/rosx_turtle", timeout=_RETRY_PERIOD * 4)
    while not stop.is_set():
        up = master.answers()
        master.close()  # a fresh connection each time: the master may restart meanwhile
        if up:
            if failed:
                console.print(INFO, f"Connected to master at [{address}]")
            try:
                return start()
            except TransportError:  # the master went away meanwhile
                pass
        if not failed:
            console.print(
                ERROR, f"[registerPublisher] Failed to contact master at [{address}].  Retrying..."
            )
            failed = True
        stop.wait(_RETRY_PERIOD)
    return None


def run_until_stopped(start: Callable[[], T], console: Console, address: str) -> int:
    """Start the program's node, run it until a signal or a shutdown, stop it; exit status."""
    with stop_on_signals() as stop:
        running = start_when_master_is_up(start, console, address, stop)
        if running is None:
            return 0
        try:
            while not stop.is_set():
                if running.wait_for_shutdown(0.1):
                    break
        finally:
            running.shutdown("signal" if stop.is_set() else "")
    return 0
