"""Topic connections between rosx nodes of one machine over Unix domain sockets (``UNIXROS``).

Over loopback TCP a small message takes 17-18 µs from one process's ``send`` to another's
``recv`` on a 2-core VM, most of it the kernel's TCP stack; over a Unix stream socket it takes
about 6 µs (bench/README.md), and large messages move faster too. So when a rosx subscriber
and a rosx publisher run on the same machine, the connection is a Unix socket carrying exactly
what TCPROS carries: the same headers, then the same length-prefixed frames.

The negotiation uses the Slave API's protocol list (ROS wiki ROS/Slave_API ``requestTopic``):

* a rosx subscriber offers ``["UNIXROS", machine]`` before ``["TCPROS"]``; ROS 1 publishers
  skip a protocol they do not know (rospy and roscpp both do) and answer with TCPROS, so
  nothing changes for them;
* a rosx publisher whose `machine` is the same answers ``["UNIXROS", address]``: the Linux
  abstract socket its node listens on, written with ``@`` for the leading NUL (XML-RPC strings
  cannot carry a NUL);
* a subscriber that cannot connect to that address (another network namespace, say) asks
  again with TCPROS alone.

``getBusInfo`` (``rosnode info``) names the transport ``UNIXROS``; ``ROSX_UNIXROS=0`` in a
process's environment makes its nodes neither offer nor accept it (`ENABLED`).
"""

from __future__ import annotations

import contextlib
import functools
import os
import secrets
import socket
import struct
import sys
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable

#: The protocol's name in ``requestTopic`` and ``getBusInfo``.
PROTOCOL = "UNIXROS"

#: Whether this process's nodes use Unix sockets among themselves (Linux only).
ENABLED = sys.platform.startswith("linux") and os.environ.get("ROSX_UNIXROS", "1") != "0"

#: A publisher's send buffer on a UNIXROS connection: what Linux lets loopback TCP grow to by
#: default (``tcp_wmem``'s maximum). A Unix socket counts every queued ``send`` as a whole
#: kernel buffer, so with the default (208 KiB) a subscriber a moment behind a Twist flood
#: holds a few hundred messages where TCP holds tens of thousands. The kernel caps it at
#: ``net.core.wmem_max``.
SEND_BUFFER = 4 * 1024 * 1024

_BOOT_ID = "/proc/sys/kernel/random/boot_id"
_CREDENTIALS = struct.Struct("3i")  # struct ucred: pid, uid, gid
#: Linux's ``SIOCOUTQ`` (``TIOCOUTQ``): a socket's bytes sent and not yet taken by the peer.
_SIOCOUTQ = 0x5411


@functools.cache
def machine() -> str:
    """What identifies this machine's kernel (``""``: unknown, so never offered)."""
    try:
        return Path(_BOOT_ID).read_text(encoding="ascii").strip()
    except OSError:
        return ""


def offer() -> list[str] | None:
    """The protocol entry a subscriber offers before TCPROS; None when not offered."""
    ident = machine() if ENABLED else ""
    return [PROTOCOL, ident] if ident else None


def accepts(protocol: object) -> bool:
    """Whether a subscriber's offered ``protocol`` entry is UNIXROS from this machine."""
    return (
        ENABLED
        and isinstance(protocol, list)
        and len(protocol) >= 2
        and protocol[0] == PROTOCOL
        and bool(machine())
        and protocol[1] == machine()
    )


def new_address() -> str:
    """A fresh abstract socket address for a node to listen on, written ``@name``."""
    return f"@rosx-{os.getpid()}-{secrets.token_hex(8)}"


def socket_address(address: str) -> str:
    """The address ``socket.bind``/``connect`` take for ``@name``."""
    return "\0" + address[1:]


def parse_reply(params: object) -> str | None:
    """The address in a ``requestTopic`` answer ``["UNIXROS", "@name"]``; None if not one."""
    if not isinstance(params, list) or len(params) != 2 or params[0] != PROTOCOL:
        return None
    address = params[1]
    if not isinstance(address, str) or not address.startswith("@") or len(address) < 2:
        return None
    return address


def listen(address: str) -> socket.socket:
    """A non-blocking listening socket at ``address`` (``@name``)."""
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    try:
        sock.bind(socket_address(address))
        sock.listen(128)
        sock.setblocking(False)
    except OSError:
        sock.close()
        raise
    return sock


def configure_publisher(sock: socket.socket) -> None:
    """Size a publisher's end of a UNIXROS connection (`SEND_BUFFER`)."""
    with contextlib.suppress(OSError):
        if sock.getsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF) < SEND_BUFFER:
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, SEND_BUFFER)


def unread_probe(sock: socket.socket) -> Callable[[], int] | None:
    """A function giving the bytes this end of a Unix stream socket has sent and the peer has
    not read yet (``SIOCOUTQ``); None where that cannot be asked.

    Over a Unix socket what is sent waits in the peer's receive queue, charged to the sender
    until the peer reads it: a non-zero answer says the peer has frames still to read (over
    TCP, the same question says what the peer's kernel has not acknowledged, not read).
    """
    if not sys.platform.startswith("linux") or sock.family != socket.AF_UNIX:
        return None
    try:
        import fcntl  # noqa: PLC0415 - POSIX only: asked of Unix sockets on Linux alone
    except ImportError:
        return None
    ioctl = fcntl.ioctl
    fileno = sock.fileno()
    answer = bytearray(4)
    from_bytes = int.from_bytes

    def unread() -> int:
        try:
            ioctl(fileno, _SIOCOUTQ, answer, True)
        except OSError:
            return 0
        return from_bytes(answer, "little")

    return unread


def peer_pid(sock: socket.socket) -> int:
    """The process id at the other end of a connected Unix socket (0 if unknown)."""
    option = getattr(socket, "SO_PEERCRED", None)
    if option is None:
        return 0
    try:
        pid, _, _ = _CREDENTIALS.unpack(
            sock.getsockopt(socket.SOL_SOCKET, option, _CREDENTIALS.size)
        )
    except OSError:
        return 0
    return int(pid)


def transport_info(address: str, sock: socket.socket, fileno: int) -> str:
    """The description ``getBusInfo`` gives of a UNIXROS connection.

    It has rospy's shape, which ROS 1's ``rosnode info`` parses (port, peer, socket): no port,
    the publisher's socket address and the process at the other end.
    """
    return f"UNIXROS connection on port 0 to [{address} (pid {peer_pid(sock)}) on socket {fileno}]"
