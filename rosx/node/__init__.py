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
- `loop`: the process's I/O loop thread. `tcpros_server`: a node's TCPROS port.
- `publication` and `outgoing`: publishing a topic and the per-subscriber frame streams.
- `subscription`, `incoming` and `receiver`: subscribing, the per-publisher streams, the
  reader threads, the drop-oldest queue and the callbacks.
- `service` and `service_client`: ROSRPC servers and clients.
- `slave_api`: the Slave API handlers. `master_proxy`: calls to the master.
- `params`: the parameter client and cache. `clock`: time, sleep, `Rate`.
- `rosout`: log levels and console lines; `log_services`: ``/rosout`` and the logger services.
- `signals`: optional SIGINT/SIGTERM handling. `errors`: the exceptions.

This package imports `rosx.wire`, `rosx.names`, `rosx.msg` and `rosx.transport`, nothing above.
"""

from __future__ import annotations

from rosx.node.clock import Rate, now, sleep
from rosx.node.errors import MasterError, NodeError, NodeShutdownError, ServiceError
from rosx.node.handles import Publisher, ServiceHandle, Subscriber
from rosx.node.node import Node
from rosx.node.rosout import DEBUG, ERROR, FATAL, INFO, WARN
from rosx.node.service_client import ServiceClient
from rosx.node.signals import install_signal_handlers
from rosx.node.subscription import RawMessage

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
