"""`GraphState`: what the master and the nodes report of the graph, before any filtering.

The master's ``getSystemState`` gives who publishes and subscribes to what (ROS wiki
Master_API); each node's ``getBusInfo`` gives the connections it actually holds (ROS wiki
Slave_API). A node whose ``getBusInfo`` failed has ``None`` as its links; rqt_graph calls such a
node unreachable.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field


@dataclass(frozen=True)
class BusLink:
    """One connection a node reports: its topic, the peer (a node name or a URI) and the
    direction, ``"o"`` (the node publishes to the peer) or ``"i"`` (it subscribes)."""

    topic: str
    peer: str
    direction: str


@dataclass(frozen=True)
class GraphState:
    """The raw graph: topic → nodes maps, node URIs and, when asked, each node's bus info.

    ``bus_info`` is ``None`` when nobody asked the nodes; then the registrations stand in for
    the live connections.
    """

    publishers: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    subscribers: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    services: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    topic_types: Mapping[str, str] = field(default_factory=dict)
    node_uris: Mapping[str, str] = field(default_factory=dict)
    bus_info: Mapping[str, tuple[BusLink, ...] | None] | None = None

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
        system_state: list[list[list[object]]], topic_types: Mapping[str, str] | None = None
    ) -> GraphState:
        """A state from a ``getSystemState`` value (``[pubs, subs, services]``)."""

        def section(rows: list[list[object]]) -> dict[str, tuple[str, ...]]:
            return {str(row[0]): tuple(str(n) for n in row[1]) for row in rows}  # type: ignore[attr-defined]

        pubs, subs, srvs = system_state
        return GraphState(section(pubs), section(subs), section(srvs), dict(topic_types or {}))
