"""The master watch: a process's nodes register again with a master that restarted.

ROS 1 nodes register with the master once; a roscore restarted on the same URI knows nothing
of them, so ``rostopic list`` comes back empty and new subscribers never find the running
publishers. rosx nodes survive that: one `MasterWatch` per event loop (the process's, see
`rosx.transport.loop_thread`) — a task on the loop, not a thread per node — watches each
master its nodes use while at least one node is alive.

The rules:

* Every `POLL_INTERVAL` seconds the watch asks each master ``getPid`` and ``getParam
  /run_id`` (two calls on one kept-alive connection). The pair is the master's identity: a
  restarted roscore gets a new ``/run_id`` (and a new PID), even in a container that reuses
  PIDs.
* When the identity differs from the last one seen, or the master answers after it did not,
  every node of that master registers again, as `reregister` does: its publishers, its
  subscribers (the publishers the master lists are connected, none dropped), its services and
  its parameter subscriptions (the cache takes the new master's values). The master sends
  ``publisherUpdate`` to subscribers as usual, so new subscribers find the old publishers and
  old ones the new.
* A node added since the last poll is looked up (``lookupNode``) once, so a restart between
  its start and the first poll is not missed.
* Established TCPROS connections between nodes never depend on the master: they keep flowing
  while it is away. For `RECOVERY_GRACE` seconds after a re-registration, a subscriber treats
  ``publisherUpdate`` as additive, since the master's list lacks publishers of other
  processes that have not registered again yet; it must not drop their working connections.
* A registration the node withdrew meanwhile is withdrawn again; a node shut down is skipped.

The watch never imports the node (it only reads what `rosx.node.node.Node` exposes) and
never blocks the loop: its calls are the loop's asynchronous XML-RPC calls.
"""

from __future__ import annotations

import asyncio
import logging
import threading
import time
import weakref
from typing import TYPE_CHECKING, Any

from rosx.master.client import MasterError, reply_value
from rosx.transport.aclient import AsyncXmlRpcClient
from rosx.transport.errors import FaultError, TransportError

if TYPE_CHECKING:
    from rosx.node.node import Node
    from rosx.transport.loop_thread import LoopThread

_log = logging.getLogger(__name__)

#: Seconds between two looks at each master: a restarted master sees the graph again within
#: about this long (plus the registrations themselves), for two tiny calls a second.
POLL_INTERVAL = 1.0
#: Seconds a look may take: a master that answers later counts as away for that round.
POLL_TIMEOUT = 1.0
#: Seconds after a re-registration during which ``publisherUpdate`` adds, never drops.
RECOVERY_GRACE = 5.0
_CALL_TIMEOUT = 3.0
_UNREACHED = (TransportError, FaultError, MasterError, OSError)

Identity = tuple[object, object]


class _Master:
    """What the watch knows of one master URI."""

    def __init__(self, uri: str) -> None:
        self.uri = uri
        self.nodes: dict[int, Node] = {}
        self.fresh: set[int] = set()
        self.identity: Identity | None = None
        self.reachable = True


class MasterWatch:
    """Watches the masters of the nodes on one loop (see the module docstring)."""

    def __init__(self, io: LoopThread) -> None:
        self.io = io
        self._masters: dict[str, _Master] = {}
        self._client = AsyncXmlRpcClient(timeout=_CALL_TIMEOUT)
        self._task: asyncio.Task[None] | None = None
        #: How many times nodes registered again (for tests and diagnostics).
        self.recoveries = 0

    def add(self, node: Node) -> None:
        """Watch ``node``'s master for it (from any thread)."""
        if self.io.running:
            self.io.call_soon(self._add, node)

    def remove(self, node: Node) -> None:
        """Stop watching for ``node`` (from any thread)."""
        if self.io.running:
            self.io.call_soon(self._remove, node)

    def _add(self, node: Node) -> None:
        master = self._masters.get(node.master_uri)
        if master is None:
            master = self._masters[node.master_uri] = _Master(node.master_uri)
        master.nodes[id(node)] = node
        master.fresh.add(id(node))
        if self._task is None or self._task.done():
            self._task = self.io.loop.create_task(self._run())

    def _remove(self, node: Node) -> None:
        master = self._masters.get(node.master_uri)
        if master is None:
            return
        master.nodes.pop(id(node), None)
        master.fresh.discard(id(node))
        if not master.nodes:
            del self._masters[node.master_uri]

    async def _run(self) -> None:
        try:
            while self._masters:
                await asyncio.sleep(POLL_INTERVAL)
                await asyncio.gather(*(self._look(m) for m in list(self._masters.values())))
        finally:
            await self._client.close()

    async def _look(self, master: _Master) -> None:
        caller = next(iter(master.nodes.values()), None)
        if caller is None:
            return
        try:
            identity = await self._identity(master.uri, caller.name)
        except _UNREACHED:
            master.reachable = False
            return
        restarted = not master.reachable or (
            master.identity is not None and identity != master.identity
        )
        master.identity, master.reachable = identity, True
        fresh, master.fresh = master.fresh, set()
        for key, node in list(master.nodes.items()):
            if restarted or (key in fresh and not await self._known(master.uri, node)):
                try:
                    await reregister(node, self._client)
                except _UNREACHED as exc:
                    master.reachable = False  # try again on the next round
                    _log.debug("registering %s again failed: %s", node.name, exc)
                    return
                self.recoveries += 1

    async def _identity(self, uri: str, caller_id: str) -> Identity:
        pid = reply_value(await self._client.call(uri, "getPid", caller_id, timeout=POLL_TIMEOUT))
        try:
            run_id = reply_value(
                await self._client.call(uri, "getParam", caller_id, "/run_id", timeout=POLL_TIMEOUT)
            )
        except MasterError:
            run_id = None  # a master without roscore's parameters: its PID alone
        return pid, run_id

    async def _known(self, uri: str, node: Node) -> bool:
        try:
            found = reply_value(await self._client.call(uri, "lookupNode", node.name, node.name))
        except MasterError:
            return False
        return bool(found == node.uri)


async def reregister(node: Node, client: AsyncXmlRpcClient) -> None:
    """Register everything ``node`` has with its master again (on the loop).

    Raises:
        TransportError, FaultError, MasterError: the master did not take a registration.
    """

    async def call(method: str, *params: object) -> Any:
        reply = await client.call(node.master_uri, method, node.name, *params)
        return reply_value(reply)

    if node.is_shutdown() or not node.uri:
        return
    for topic, publication in list(node.publications.items()):
        await call("registerPublisher", topic, publication.info.type, node.uri)
        if node.publications.get(topic) is not publication or node.is_shutdown():
            await call("unregisterPublisher", topic, node.uri)
    grace = time.monotonic() + RECOVERY_GRACE
    for topic, subscription in list(node.subscriptions.items()):
        subscription.keep_until = grace
        uris = await call("registerSubscriber", topic, subscription.type, node.uri)
        if node.subscriptions.get(topic) is not subscription or node.is_shutdown():
            await call("unregisterSubscriber", topic, node.uri)
            continue
        subscription.set_publishers([str(u) for u in uris], additive=True)
    for name, server in list(node.services.items()):
        await call("registerService", name, server.uri, node.uri)
        if node.services.get(name) is not server or node.is_shutdown():
            await call("unregisterService", name, server.uri)
    for key in node.param_cache.subscribed():
        value = await call("subscribeParam", node.uri, key)
        node.param_cache.set(key, value)


_watches: weakref.WeakKeyDictionary[LoopThread, MasterWatch] = weakref.WeakKeyDictionary()
_lock = threading.Lock()


def master_watch(io: LoopThread) -> MasterWatch:
    """The watch of the nodes on ``io`` (created on first use)."""
    with _lock:
        watch = _watches.get(io)
        if watch is None:
            watch = _watches[io] = MasterWatch(io)
        return watch
