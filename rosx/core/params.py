"""The parameters roscore sets: version, distribution, run id and the launch server's URI."""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx.wire.xmlrpc_http import parse_http_uri

if TYPE_CHECKING:
    from rosx.master.api import MasterApi

#: What ROS 1 Noetic's roscore stores: the output of ``rosversion roslaunch`` and
#: ``rosversion -d``, trailing newline included.
ROSVERSION = "1.16.0\n"
ROSDISTRO = "noetic\n"
#: The caller id roslaunch sets them with.
LAUNCH_CALLER = "/roslaunch"


def host_param_name(host: str, port: int) -> str:
    """``/roslaunch/uris/host_<host>__<port>``: roslaunch's key, `host` made a legal name."""
    legal = "".join(c if c.isascii() and c.isalnum() else "_" for c in host.lower())
    return f"/roslaunch/uris/host_{legal}__{port}"


async def set_core_params(api: MasterApi, run_id: str) -> None:
    """Set roscore's parameters on the master behind `api` (on the master's event loop)."""
    host, port, _ = parse_http_uri(api.uri)
    api.call("setParam", LAUNCH_CALLER, "/run_id", run_id)
    api.call("setParam", LAUNCH_CALLER, host_param_name(host, port), api.uri)
    api.call("setParam", LAUNCH_CALLER, "/rosversion", ROSVERSION)
    api.call("setParam", LAUNCH_CALLER, "/rosdistro", ROSDISTRO)
