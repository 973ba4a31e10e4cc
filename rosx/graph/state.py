"""`GraphState`: what the master and the nodes report of the graph, before any filtering.

The master's ``getSystemState`` gives who publishes and subscribes to what (ROS wiki
Master_API); each node's ``getBusInfo`` gives the connections it actually holds (ROS wiki
Slave_API). A node whose ``getBusInfo`` failed has ``None`` as its links; rqt_graph calls such a
node unreachable.

`registrations` is the one way a tool reads the master's graph (``rostopic list``, ``rosnode
list``, completion…); `rosx.graph.fetch.fetch_state` adds the types and asks every node.
Cheap to import (no dataclasses): short commands read the graph here.
"""

from __future__ import annotations

from rosx.record import Record

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Iterable, Mapping
    from typing import Any

    from rosx.master.client import MasterClient


class BusLink(Record):
    """One connection a node reports: its topic, the peer (a node name or a URI) and the
    direction, ``"o"`` (the node publishes to the peer) or ``"i"`` (it subscribes)."""

    __match_args__ = ("topic", "peer", "direction")
    __slots__ = __match_args__
    topic: str
    peer: str
    direction: str

    def __init__(self, topic: str, peer: str, direction: str) -> None:
        super().__init__(topic=topic, peer=peer, direction=direction)


class GraphState(Record):
    """The raw graph: topic → nodes maps (in the master's order), node URIs and, when asked,
    each node's bus info.

    ``bus_info`` is ``None`` when nobody asked the nodes; then the registrations stand in for
    the live connections.
    """

    __match_args__ = (
        "publishers",
        "subscribers",
        "services",
        "topic_types",
        "node_uris",
        "bus_info",
    )
    __slots__ = __match_args__
    publishers: Mapping[str, tuple[str, ...]]
    subscribers: Mapping[str, tuple[str, ...]]
    services: Mapping[str, tuple[str, ...]]
    topic_types: Mapping[str, str]
    node_uris: Mapping[str, str]
    bus_info: Mapping[str, tuple[BusLink, ...] | None] | None

    def __init__(
        self,
        publishers: Mapping[str, tuple[str, ...]] | None = None,
        subscribers: Mapping[str, tuple[str, ...]] | None = None,
        services: Mapping[str, tuple[str, ...]] | None = None,
        topic_types: Mapping[str, str] | None = None,
        node_uris: Mapping[str, str] | None = None,
        bus_info: Mapping[str, tuple[BusLink, ...] | None] | None = None,
    ) -> None:
        super().__init__(
            publishers={} if publishers is None else publishers,
            subscribers={} if subscribers is None else subscribers,
            services={} if services is None else services,
            topic_types={} if topic_types is None else topic_types,
            node_uris={} if node_uris is None else node_uris,
            bus_info=bus_info,
        )

    @property
    def nodes(self) -> list[str]:
        """Every node named by a registration, sorted."""
        names: set[str] = set()
        for section in (self.publishers, self.subscribers, self.services):
            for nodes in section.values():
                names.update(nodes)
        return sorted(names)

    @property
    def topics(self) -> list[str]:
        """Every topic with a publisher or a subscriber, sorted."""
        return sorted({*self.publishers, *self.subscribers})

    def unreachable(self, node: str) -> bool:
        """Whether ``node`` was asked for its bus info and did not answer."""
        return self.bus_info is not None and node in self.bus_info and self.bus_info[node] is None

    @staticmethod
    def from_system_state(
        system_state: Iterable[Iterable[Any]],
        topic_types: Mapping[str, str] | None = None,
    ) -> GraphState:
        """A state from a ``getSystemState`` value (``[pubs, subs, services]``)."""

        def section(rows: Iterable[Any]) -> dict[str, tuple[str, ...]]:
            return {str(name): tuple(str(node) for node in nodes) for name, nodes in rows}

        pubs, subs, srvs = system_state
        return GraphState(section(pubs), section(subs), section(srvs), dict(topic_types or {}))


def registrations(master: MasterClient, *, types: bool = False) -> GraphState:
    """What the master says of the graph (``getSystemState``): who publishes, subscribes to
    and provides what, in the master's order; with ``types``, every topic's type too
    (``getTopicTypes``). No node is asked.

    Raises:
        MasterUnreachable: the master does not answer.
        MasterError: it refused.
    """
    system = master.system_state()
    return GraphState.from_system_state(system, master.topic_types() if types else None)


__all__ = ["BusLink", "GraphState", "registrations"]
