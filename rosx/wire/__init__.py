"""Sans-I/O protocol code for ROS 1's wire: bytes in, typed events or bytes out.

Nothing in this package opens a socket, starts a thread, reads a clock or logs; the node runtime
and the master feed it the bytes they receive and send the bytes it returns.

Modules (import the one you need; this package imports none of them eagerly, so a command that
only speaks XML-RPC does not pay for the rest):

- `errors`: `ProtocolError` and its kinds, raised for input the protocols refuse.
- `header`: TCPROS connection headers (ROS wiki ROS/Connection Header).
- `framing`: uint32-length-prefixed frames and an incremental `FrameReader` (ROS/TCPROS).
- `tcpros`: the topic handshake between subscriber and publisher (ROS/TCPROS).
- `rosrpc`: the service handshake, request and response framing (ROS/TCPROS, services).
- `xmlrpc`: XML-RPC call, response and fault documents (the XML-RPC specification).
- `xmlrpc_http`: HTTP/1.1 request and response framing for XML-RPC.
- `reply`: ROS's ``[code, statusMessage, value]`` reply convention (ROS/Master_API, ROS/Slave_API).
"""
