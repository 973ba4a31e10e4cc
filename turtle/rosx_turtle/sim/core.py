"""`SimCore`: what roscore hosts, in ``rosx sim``'s process: master, parameters, ``/rosout``.

The master listens on the port asked for (11311 unless ``--port`` says otherwise) and gets the
parameters roscore sets (``/run_id``, ``/rosversion``, ``/rosdistro``, the launch URI); the
``/rosout`` node gathers every node's log on ``/rosout_agg``. When the port is taken, starting
fails with `PortBusyError`, whose text is roscore's for the same case.
"""

from __future__ import annotations

import errno
import uuid
from typing import TYPE_CHECKING

from rosx.master.core import set_core_params
from rosx.master.server import MasterThread
from rosx.node.aggregator import start_aggregator
from rosx.transport.address import advertised_host, bind_host, http_uri
from rosx.transport.client import XmlRpcClient
from rosx.transport.errors import FaultError, TransportError

if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.node import Node


class PortBusyError(Exception):
    """The master's port is taken; the message is what roscore prints then."""


def refusal(uri: str, port: int, exc: OSError) -> str:
    """roscore's words for a master that cannot listen at ``uri``."""
    if exc.errno == errno.EADDRINUSE and _master_answers(uri):
        return (
            "RLException: roscore cannot run as another roscore/master is already running. \n"
            "Please kill other roscore/master processes before relaunching.\n"
            f"The ROS_MASTER_URI is {uri}"
        )
    if exc.errno == errno.EADDRINUSE:
        return f"ERROR: Unable to start XML-RPC server, port {port} is already in use"
    return f"ERROR: Unable to start XML-RPC server: {exc.strerror or exc}"


def _master_answers(uri: str) -> bool:
    client = XmlRpcClient(timeout=3.0)
    try:
        client.call(uri, "getPid", "/roslaunch")
    except (TransportError, FaultError, OSError):
        return False
    finally:
        client.close()
    return True


class SimCore:
    """The master on ``port`` with roscore's parameters and the ``/rosout`` node."""

    def __init__(self, port: int, environ: Mapping[str, str]) -> None:
        self.port = port
        self.environ = environ
        host = advertised_host(environ)
        self.uri = http_uri(host, port)
        self._master = MasterThread(port=port, host=bind_host(environ), advertised_host=host)
        self._rosout: Node | None = None

    def start(self) -> str:
        """Start the master and ``/rosout``; the master's URI.

        Raises:
            PortBusyError: the port is taken (by another master or anything else).
        """
        try:
            self.uri = self._master.start()
        except OSError as exc:
            raise PortBusyError(refusal(self.uri, self.port, exc)) from None
        try:
            self._master.run(self._set_params(str(uuid.uuid1())))
            self._rosout = start_aggregator(self.uri, self.environ)
        except BaseException:
            self.stop()
            raise
        return self.uri

    async def _set_params(self, run_id: str) -> None:
        set_core_params(self._master.master.api, run_id)

    def stop(self) -> None:
        """Stop ``/rosout`` and the master."""
        if self._rosout is not None:
            self._rosout.shutdown("core shutting down")
            self._rosout = None
        self._master.close()
