"""What the master must tell nodes after a change: the calls it makes out (ROS wiki Slave_API).

The registry and the parameter tree return these as data; `rosx.master.notifier` makes the
calls. Each names the node's XML-RPC URI (`api`) it goes to.
"""

from __future__ import annotations

from typing import Any, NamedTuple, TypeAlias


class PublisherUpdate(NamedTuple):
    """``publisherUpdate('/master', topic, publishers)`` to a subscriber of `topic`."""

    api: str
    topic: str
    publishers: list[str]


class ParamUpdate(NamedTuple):
    """``paramUpdate('/master', key, value)`` to node `caller_id`, subscribed to `key`.

    `key` ends with ``/``, as rosmaster sends it; `value` is ``{}`` for a deleted parameter.
    """

    api: str
    caller_id: str
    key: str
    value: Any


class ShutdownNode(NamedTuple):
    """``shutdown('/master', '[<caller_id>] Reason: <reason>')`` to a node replaced by another."""

    api: str
    caller_id: str
    reason: str

    @property
    def message(self) -> str:
        """The message rosmaster sends with the call."""
        return f"[{self.caller_id}] Reason: {self.reason}"


Action: TypeAlias = PublisherUpdate | ParamUpdate | ShutdownNode
