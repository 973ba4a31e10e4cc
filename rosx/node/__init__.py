"""The node runtime: ROS 1 nodes that speak the Slave API, TCPROS and ROSRPC, many per process.

    from rosx.node import Node
    from rosx.msg.codec.classes import get_message_class

    Twist = get_message_class("geometry_msgs/Twist")
    with Node("talker", master_uri="http://localhost:11311/") as node:
        pub = node.advertise("cmd_vel", Twist, queue_size=10)
        pub.publish(Twist())

Modules, one concept each:

- `node`: `Node`, the synchronous facade; `handles`: the `Publisher`, `Subscriber` and
  `ServiceHandle` it returns.
- `tcpros_server`: a node's TCPROS port. Sockets are served on the process's event loop
  (`rosx.transport.loop_thread`); handlers and callbacks run on the node's own threads.
- `publication` and `outgoing`: publishing a topic and the per-subscriber frame streams.
- `subscription`, `incoming` and `receiver`: subscribing, the per-publisher streams, the
  reader threads, the drop-oldest queue and the callbacks.
- `service` and `service_client`: ROSRPC servers and the one service client (also
  ``rosservice``'s).
- `slave_api`: the Slave API handlers. Calls to the master go through
  `rosx.master.client.MasterClient`.
- `watchdog`: the process's master watch, which registers its nodes again with a restarted
  master.
- `params`: the parameter client and cache. `clock`: time, sleep, `Rate`.
- `rosout`: log levels and console lines; `log_services`: ``/rosout`` and the logger services.
- `errors`: the exceptions. (Signal handling is `rosx.signals`; `install_signal_handlers` is
  served here too.)
- `stats`: what a subscriber measures of a topic (rate, bandwidth, delay), as ``rostopic
  hz``/``bw``/``delay`` and rqt_topic report it.

The names below are loaded on first use (PEP 562), so ``from rosx.node.service_client import
ServiceClient`` costs a command-line tool that module alone, not the I/O loop and the rest.
This package imports `rosx.wire`, `rosx.names`, `rosx.msg`, `rosx.transport` and
`rosx.master.client`, nothing above.
"""

from __future__ import annotations

from rosx._lazy import lazy_names

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx.master.client import MasterError
    from rosx.node.clock import Rate, now, sleep
    from rosx.node.errors import NodeError, NodeShutdownError, ServiceError
    from rosx.node.handles import Publisher, ServiceHandle, Subscriber
    from rosx.node.node import Node
    from rosx.node.rosout import DEBUG, ERROR, FATAL, INFO, WARN
    from rosx.node.service_client import ServiceClient
    from rosx.node.subscription import RawMessage
    from rosx.signals import install_signal_handlers

#: Each public name and the module that defines it.
_HOMES = {
    "DEBUG": "rosx.node.rosout",
    "ERROR": "rosx.node.rosout",
    "FATAL": "rosx.node.rosout",
    "INFO": "rosx.node.rosout",
    "WARN": "rosx.node.rosout",
    "MasterError": "rosx.master.client",
    "Node": "rosx.node.node",
    "NodeError": "rosx.node.errors",
    "NodeShutdownError": "rosx.node.errors",
    "Publisher": "rosx.node.handles",
    "Rate": "rosx.node.clock",
    "RawMessage": "rosx.node.subscription",
    "ServiceClient": "rosx.node.service_client",
    "ServiceError": "rosx.node.errors",
    "ServiceHandle": "rosx.node.handles",
    "Subscriber": "rosx.node.handles",
    "install_signal_handlers": "rosx.signals",
    "now": "rosx.node.clock",
    "sleep": "rosx.node.clock",
}

__all__ = [
    "DEBUG",
    "ERROR",
    "FATAL",
    "INFO",
    "WARN",
    "MasterError",
    "Node",
    "NodeError",
    "NodeShutdownError",
    "Publisher",
    "Rate",
    "RawMessage",
    "ServiceClient",
    "ServiceError",
    "ServiceHandle",
    "Subscriber",
    "install_signal_handlers",
    "now",
    "sleep",
]


__getattr__ = lazy_names(__name__, _HOMES)
