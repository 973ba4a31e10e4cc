"""Delivers the master's calls to nodes (ROS wiki Slave_API: ``publisherUpdate``,
``paramUpdate``, ``shutdown``) without ever holding up registration.

rosmaster queues these calls on three threads with no timeout, so a few hung nodes stall every
later notification (ros/ros_comm#1555). Here:

* each node (XML-RPC URI) has its own queue, drained by its own task, so calls reach a node in
  the order they were made while nodes are served independently of each other;
* every call has a short timeout, and at most `max_concurrency` calls are in flight;
* a queued update that a newer one makes obsolete (same topic, or same parameter key, for the
  same node) is replaced by it, so a slow node's queue stays as short as what it must learn;
* a node that refuses connections has the rest of its queue dropped: it is gone.

`submit` is called on the event loop's thread and returns at once.
"""

from __future__ import annotations

import asyncio
import logging
from typing import TYPE_CHECKING

from rosx.master.actions import ParamUpdate, PublisherUpdate, ShutdownNode
from rosx.transport.aclient import AsyncXmlRpcClient
from rosx.transport.errors import ConnectError, FaultError, TransportError

if TYPE_CHECKING:
    from collections.abc import Iterable

    from rosx.master.actions import Action

_log = logging.getLogger(__name__)
MASTER_CALLER_ID = "/master"

#: Seconds a node has to answer one notification.
DEFAULT_TIMEOUT = 2.0


def _slot(action: Action) -> tuple[str, str]:
    """What a newer action of the same slot makes obsolete."""
    if isinstance(action, PublisherUpdate):
        return "publisherUpdate", action.topic
    if isinstance(action, ParamUpdate):
        return "paramUpdate", action.key
    return "shutdown", ""


class Notifier:
    """Sends actions to nodes from the running event loop."""

    def __init__(
        self,
        client: AsyncXmlRpcClient | None = None,
        *,
        timeout: float = DEFAULT_TIMEOUT,
        max_concurrency: int = 32,
    ) -> None:
        self._client = client if client is not None else AsyncXmlRpcClient(timeout)
        self._timeout = timeout
        self._slots = asyncio.Semaphore(max_concurrency)
        self._queues: dict[str, dict[tuple[str, str], Action]] = {}
        self._workers: dict[str, asyncio.Task[None]] = {}
        self._idle = asyncio.Event()
        self._idle.set()
        self.delivered = 0
        self.failed = 0

    def submit(self, actions: Iterable[Action]) -> None:
        """Queue `actions` for delivery (from the event loop's thread)."""
        for action in actions:
            queue = self._queues.setdefault(action.api, {})
            slot = _slot(action)
            queue.pop(slot, None)  # the newer one goes last, after what the node hears before
            queue[slot] = action
            if action.api not in self._workers:
                self._idle.clear()
                self._workers[action.api] = asyncio.ensure_future(self._drain(action.api))

    async def wait_idle(self) -> None:
        """Wait until every queued action has been delivered or given up on."""
        await self._idle.wait()

    async def close(self) -> None:
        """Drop what is queued, stop the deliveries under way and close connections."""
        self._queues.clear()
        workers = list(self._workers.values())
        for worker in workers:
            worker.cancel()
        await asyncio.gather(*workers, return_exceptions=True)
        await self._client.close()

    async def _drain(self, api: str) -> None:
        try:
            queue = self._queues[api]
            while queue:
                slot = next(iter(queue))
                action = queue.pop(slot)
                async with self._slots:
                    gone = await self._deliver(action)
                if gone:
                    queue.clear()
        finally:
            del self._workers[api]
            self._queues.pop(api, None)
            if not self._workers:
                self._idle.set()

    async def _deliver(self, action: Action) -> bool:
        """Make one call; True if the node is unreachable."""
        if isinstance(action, PublisherUpdate):
            args: tuple[object, ...] = ("publisherUpdate", action.topic, action.publishers)
        elif isinstance(action, ParamUpdate):
            args = ("paramUpdate", action.key, action.value)
        else:
            assert isinstance(action, ShutdownNode)
            args = ("shutdown", action.message)
        method, *params = args
        try:
            await self._client.call(
                action.api, str(method), MASTER_CALLER_ID, *params, timeout=self._timeout
            )
        except ConnectError as exc:
            self.failed += 1
            _log.debug("%s to %s: %s", method, action.api, exc)
            return True
        except (TransportError, FaultError, ValueError) as exc:
            self.failed += 1
            _log.debug("%s to %s: %s", method, action.api, exc)
            return False
        self.delivered += 1
        return False
