"""The network shell over `rosx.wire`'s XML-RPC codec: servers, clients, addresses.

Import the module you need; this package imports none of them eagerly, so a command-line tool
that only calls the master pays for the blocking client alone (no asyncio).

- `errors`: `TransportError` (`ConnectError`, `CallTimeoutError`, `BadReplyError`) and
  `FaultError`.
- `client`: `XmlRpcClient`, `ServerProxy` and `call`, blocking, with kept-alive connections.
- `aclient`: `AsyncXmlRpcClient`, the same for asyncio code, with short default timeouts.
- `server`: `XmlRpcServer`, an asyncio HTTP/1.1 XML-RPC server, and `EncodedResponse`.
- `loop_thread`: the process's event loop (`process_loop`, a `LoopThread`), and `Hosted` /
  `ServerThread` to serve on it from synchronous code.
- `descriptors`: accepting connections (`Listener`) with a reserve of file descriptors kept by
  closing the process's oldest idle connections.
- `address`: the host to bind and to advertise, from ROS_IP / ROS_HOSTNAME (ROS 1's rules).
- `exchange`: what both clients share: request bytes, reply interpretation.

Layering: this package uses `rosx.wire`, `rosx.names` and the standard library only.
"""
