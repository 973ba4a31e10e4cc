"""`PortInUseError`: the core's master cannot listen on its port, with roscore's words for it.

roscore tells two cases apart. When a master already answers on the port it refuses to start a
second one (``RLException: roscore cannot run as another roscore/master is already
running…``); when anything else holds the port, or the system refuses it, it says it could not
start its XML-RPC server. `refusal` asks the port which case it is.
"""

from __future__ import annotations

import errno

from rosx.core.params import LAUNCH_CALLER
from rosx.master.client import master_is_online

#: How long a master already on the port has to answer ``getPid``.
_ANSWER_TIMEOUT = 3.0


class PortInUseError(Exception):
    """The master cannot listen on its port.

    Attributes:
        uri: The master's URI as it would have been.
        port: The port asked for.
        another_master: Whether a master answers there (else something else holds the port,
            or the system refused it).
        message: What roscore prints for the case (a master: its ``RLException``, three
            lines; else its ``ERROR: Unable to start XML-RPC server…`` line).
    """

    def __init__(self, uri: str, port: int, *, another_master: bool, message: str) -> None:
        super().__init__(message)
        self.uri = uri
        self.port = port
        self.another_master = another_master
        self.message = message


def refusal(uri: str, port: int, exc: OSError) -> PortInUseError:
    """Why a master could not listen at `uri` (`exc` is what binding raised), in roscore's
    words."""
    if exc.errno == errno.EADDRINUSE and master_is_online(uri, LAUNCH_CALLER, _ANSWER_TIMEOUT):
        message = (
            "RLException: roscore cannot run as another roscore/master is already running. \n"
            "Please kill other roscore/master processes before relaunching.\n"
            f"The ROS_MASTER_URI is {uri}"
        )
        return PortInUseError(uri, port, another_master=True, message=message)
    if exc.errno == errno.EADDRINUSE:
        message = f"ERROR: Unable to start XML-RPC server, port {port} is already in use"
    else:
        message = f"ERROR: Unable to start XML-RPC server: {exc.strerror or exc}"
    return PortInUseError(uri, port, another_master=False, message=message)
