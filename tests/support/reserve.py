"""What the descriptor-exhaustion tests share: enough descriptors in the test process for more
idle connections than the server's limit, and counting the ones the server closed."""

from __future__ import annotations

import contextlib
import errno
import resource
import select
import socket
import time
from collections.abc import Iterator, Sequence

import pytest

#: Idle connections opened against a server limited to 1 024 descriptors.
CONNECTIONS = 1100
#: Words of the one warning a server logs when it first closes idle connections.
IDLE_WARNING = "oldest idle connections to keep serving"


@contextlib.contextmanager
def enough_descriptors(needed: int = CONNECTIONS + 200) -> Iterator[None]:
    """Raise this process's soft descriptor limit to ``needed`` for the block (skip if the
    hard limit is lower)."""
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    if soft >= needed or soft == resource.RLIM_INFINITY:
        yield
        return
    if hard != resource.RLIM_INFINITY and hard < needed:
        pytest.skip(f"needs {needed} file descriptors; the hard limit is {hard}")
    resource.setrlimit(resource.RLIMIT_NOFILE, (needed, hard))
    try:
        yield
    finally:
        resource.setrlimit(resource.RLIMIT_NOFILE, (soft, hard))


def closed_by_peer(sockets: Sequence[socket.socket]) -> int:
    """How many of ``sockets`` the other end has closed (readable with nothing to read)."""
    poller = select.poll()  # not select(): descriptors here go past FD_SETSIZE
    by_fd = {sock.fileno(): sock for sock in sockets}
    for fd in by_fd:
        poller.register(fd, select.POLLIN)
    closed = 0
    for fd, events in poller.poll(0):
        if events & (select.POLLHUP | select.POLLERR):
            closed += 1
            continue
        try:
            closed += by_fd[fd].recv(1, socket.MSG_PEEK | socket.MSG_DONTWAIT) == b""
        except OSError:
            closed += 1
    return closed


@contextlib.contextmanager
def idle_connections(
    address: str | tuple[str, int], count: int = CONNECTIONS, timeout: float = 30.0
) -> Iterator[list[socket.socket]]:
    """``count`` connections to ``address`` (a TCP address or an abstract Unix one, ``@name``)
    that send nothing, all connected, closed after the block.

    They are opened at once, not one by one: a server a little slower to accept than a client
    to connect fills its backlog, and each blocking connect that then finds it full waits a
    second for the kernel to send its SYN again.
    """
    family = socket.AF_UNIX if isinstance(address, str) else socket.AF_INET
    target = "\0" + address[1:] if isinstance(address, str) else address
    sockets: list[socket.socket] = []
    try:
        poller = select.poll()
        for _ in range(count):
            sock = socket.socket(family, socket.SOCK_STREAM)
            sockets.append(sock)
            sock.setblocking(False)
            code = sock.connect_ex(target)
            if code not in (0, errno.EINPROGRESS, errno.EAGAIN):
                raise OSError(code, f"cannot connect to {address}")
            poller.register(sock.fileno(), select.POLLOUT)
        pending = len(sockets)
        deadline = time.monotonic() + timeout
        while pending:
            if time.monotonic() > deadline:
                raise TimeoutError(f"{pending} of {count} connections to {address} still pending")
            for fd, _ in poller.poll(100):
                poller.unregister(fd)
                pending -= 1
        for sock in sockets:
            error = sock.getsockopt(socket.SOL_SOCKET, socket.SO_ERROR)
            if error:
                raise OSError(error, f"cannot connect to {address}")
        yield sockets
    finally:
        for sock in sockets:
            sock.close()
