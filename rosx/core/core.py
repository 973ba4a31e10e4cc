"""`Core`: the master, the parameter server with roscore's parameters, and ``/rosout``.

What ROS 1's roscore starts (roslaunch with ``roscore.xml``), hosted in this process on the
process's event loop (`rosx.transport.loop_thread.process_loop`), where the process's other
nodes run too: `Core.start` starts the master on the port (0 picks a free one), sets
``/run_id``, ``/rosversion``, ``/rosdistro`` and ``/roslaunch/uris/host_<host>__<port>``, and
starts the ``/rosout`` node. It listens where ``ROS_IP``/``ROS_HOSTNAME`` say (loopback
otherwise) and names itself by them in its URI.

The core runs until `Core.stop`. A ``shutdown`` call to the master does not stop it: it ends
`Core.wait` (as `Core.interrupt` does), and the owner decides, as roscore does. `start` and
`stop` may be called from any thread but the event loop's, and `stop` from several at once: it
returns once the port is free. Printing, signals and exit codes belong to the program that owns
the core.
"""

from __future__ import annotations

import threading
import uuid
from typing import TYPE_CHECKING

from rosx.core.errors import refusal
from rosx.core.params import set_core_params
from rosx.core.rosout import start_rosout
from rosx.master.server import MasterThread
from rosx.signals import wait
from rosx.transport.address import advertised_host, bind_host, http_uri

if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.node import Node


class Core:
    """roscore's master, parameters and ``/rosout`` in this process (see the module docstring).

    Args:
        port: The master's port (0: a free one, see `port` once started).
        environ: The environment (``ROS_IP`` and ``ROS_HOSTNAME`` are read).

    Attributes:
        uri: The master's URI (``http://<host>:<port>/``).
        port: The master's port.
        run_id: The ``/run_id`` the core sets, a fresh UUID.
    """

    def __init__(self, port: int, environ: Mapping[str, str]) -> None:
        self.port = port
        self.environ = environ
        self.run_id = str(uuid.uuid1())
        self.uri = http_uri(advertised_host(environ), port)
        self._lock = threading.Lock()
        self._ended = threading.Event()
        self._stopped = False
        self._master: MasterThread | None = None
        self._rosout: Node | None = None
        self._shutdown_message: str | None = None

    def start(self) -> str:
        """Start the master, set roscore's parameters, start ``/rosout``; the master's URI.

        Raises:
            PortInUseError: the master cannot listen on the port.
            RuntimeError: the core has been stopped, or failed to start, before.
        """
        with self._lock:
            if self._stopped:
                raise RuntimeError("this core has been stopped; start a new one")
            if self._master is not None:
                return self.uri
            master = MasterThread(
                port=self.port,
                host=bind_host(self.environ),
                advertised_host=advertised_host(self.environ),
                on_shutdown=self._shutdown_called,
            )
            try:
                self.uri = master.start()
            except OSError as exc:
                self._stopped = True
                self._ended.set()
                raise refusal(self.uri, self.port, exc) from None
            self._master = master
            self.port = master.master.port
            try:
                master.run(set_core_params(master.master.api, self.run_id))
                self._rosout = start_rosout(self.uri, self.environ)
            except BaseException:
                self._stopped = True
                self._close()
                raise
            return self.uri

    def wait(self, timeout: float | None = None) -> str | None:
        """Block until `stop` or a ``shutdown`` call to the master (or ``timeout`` seconds).

        Returns:
            The ``shutdown`` call's message (maybe empty), or None when there was none.
        """
        wait(self._ended, timeout)
        return self._shutdown_message

    def interrupt(self) -> None:
        """End `wait` now (it returns None) with the core still running: its owner stops it."""
        self._ended.set()

    def stop(self) -> None:
        """Stop ``/rosout`` and the master (idempotent); the port is free when it returns."""
        with self._lock:
            self._stopped = True
            self._close()

    def _close(self) -> None:
        rosout, self._rosout = self._rosout, None
        master, self._master = self._master, None
        try:
            if rosout is not None:
                rosout.shutdown("core shutting down")
        finally:
            if master is not None:
                master.close()
            self._ended.set()

    def _shutdown_called(self, message: str) -> None:
        self._shutdown_message = message
        self._ended.set()

    def __enter__(self) -> Core:
        self.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()
