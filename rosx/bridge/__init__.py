"""Bridges to the browser: the rosbridge v2 protocol and the Foxglove WebSocket protocol.

Web tools (roslibjs and roslibpy pages, webviz, Foxglove Studio, Lichtblick) reach the ROS
graph through a WebSocket server that is a ROS node. Each protocol is a sans-I/O core and a
thin shell over `websockets`' sans-I/O protocol:

- `protocol` (rosbridge v2, one client's session: frames in, frames and `ops` events out),
  `convert` (messages as rosbridge's JSON/CBOR values), `outgoing` (a message encoded once
  for every client), `fragments`, `png`, `safety` (Origin allow-list, tokens).
- `graph_side`: the events carried out on the graph through one node (`rosx.node`'s public
  API); `rosapi`: rosapi's services.
- `websocket` (the WebSocket server both protocols stand on: sockets, handshakes, a reserve
  of file descriptors), `connection` (one client: reading on the loop, per-client bounded
  queues, writes from the thread that has the message), `wsframes` (server frames as bytes),
  `jsontext` (messages straight to JSON text).
- `server` (the rosbridge server), `foxglove` (the Foxglove WebSocket protocol's core) and
  `foxglove_server` (its server).
- `app`: `Bridge`, the nodes and servers of ``rosx rosbridge`` together.

This package sits at the top of the core's layers, beside launch and bag.
"""

from __future__ import annotations

from rosx._lazy import lazy_names

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx.bridge.app import Bridge, BridgeOptions
    from rosx.bridge.protocol import Session

_HOMES = {
    "Bridge": "rosx.bridge.app",
    "BridgeOptions": "rosx.bridge.app",
    "Session": "rosx.bridge.protocol",
}

__all__ = ["Bridge", "BridgeOptions", "Session"]

__getattr__ = lazy_names(__name__, _HOMES)
