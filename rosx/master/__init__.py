"""The ROS master: Master API and Parameter API (ROS wiki Master_API, Parameter Server API).

- `registry`: nodes, publishers, subscribers, services, topic types and parameter subscriptions,
  as plain data; changes return the calls owed to nodes (`actions`).
- `params`: the parameter tree, ``searchParam``'s rules, which subscribers hear of a change.
- `validation`: rosmaster's argument checks and its name resolution against the caller id.
- `api`: each XML-RPC method as rosmaster answers it, over the registry and the tree; no I/O.
- `notifier`: delivers ``publisherUpdate``, ``paramUpdate`` and ``shutdown`` to nodes.
- `server`: `Master` (the API behind an XML-RPC server) and `MasterThread`.
- `client`: `MasterClient`, the one client of a master (and of nodes' Slave APIs) that the
  tools, the node runtime and the client API share; `MasterError`, `MasterUnreachable`,
  `DEFAULT_MASTER_URI` (from `defaults`).
- `defaults`: the master's default port and URI, and ``ROS_MASTER_URI``'s rule (`master_uri`).

roscore's whole core (this master, its parameters and ``/rosout``) is `rosx.core.Core`.

Layering: this package uses `rosx.transport`, `rosx.wire`, `rosx.names` and the standard
library only.
"""
