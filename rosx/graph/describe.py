"""What the graph tools say about one node or topic, and the graph's lists, computed once.

``rosnode info`` and ``rostopic info`` print these texts (ROS 1's, byte for byte); rqt_graph's
details panel shows the same texts for the selected box, and ``rosx sim``'s panels list the
summaries of a `rosx.graph.state.GraphState`.

- `node_description`: the master's view of a node (publications with their types,
  subscriptions, services); `node_connections`: what the node says of itself (``getPid``,
  ``getBusInfo``, ROS wiki Slave_API), each peer named as the master knows it; `node_info`:
  both, as ``rosnode info`` prints them for one node.
- `topic_description`: a topic's type, publishers and subscribers with their URIs.
- `topic_summaries`, `node_summaries`: one row per topic or node of a graph state.

The texts' failures are typed (`UnknownTopicError`, `NodeContactError`, and the master
client's errors); their words for a user are the CLI's (`rosx_commands.errors`).
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any, NamedTuple

from rosx.master.client import MasterError
from rosx.transport.errors import FaultError, InvalidUriError, TransportError

if TYPE_CHECKING:
    from rosx.graph.state import GraphState
    from rosx.master.client import MasterClient

#: Seconds a node has to answer ``getPid`` and ``getBusInfo`` (rosnode's socket timeout).
NODE_TIMEOUT = 5.0
_CONNECTION = re.compile(r"\w+ connection on port (\d+) to \[(.*) on socket (\d+)\]")
_DIRECTIONS = {"i": "    * direction: inbound", "o": "    * direction: outbound"}


class UnknownTopicError(LookupError):
    """No node publishes or subscribes to ``topic``."""

    def __init__(self, topic: str) -> None:
        super().__init__(f"Unknown topic {topic}")
        self.topic = topic


class NodeContactError(Exception):
    """The node at ``uri`` did not answer its Slave API."""

    def __init__(self, uri: str) -> None:
        super().__init__(f"Communication with node[{uri}] failed!")
        self.uri = uri


class InvalidNodeUriError(NodeContactError):
    """The node registered a URI that cannot be called (``http://host:1²/``): none was tried."""


# -- nodes -------------------------------------------------------------------------------------


def node_description(master: MasterClient, node: str) -> str:
    """The master's view of ``node``: publications, subscriptions, services (``rosnode info``'s
    first part)."""
    pubs_state, subs_state, srvs_state = master.system_state()
    published = master.published_topics("/")
    text = f"Node [{node}]"
    for title, state in (("Publications", pubs_state), ("Subscriptions", subs_state)):
        topics = sorted(t for t, nodes in state if node in nodes)
        if topics:
            rows = (f" * {t} [{published.get(t, 'unknown type')}]" for t in topics)
            text += f"\n{title}: \n" + "\n".join(rows) + "\n"
        else:
            text += f"\n{title}: None\n"
    services = sorted(s for s, nodes in srvs_state if node in nodes)
    if services:
        text += "\nServices: \n" + "\n".join(f" * {s}" for s in services) + "\n"
    else:
        text += "\nServices: None\n"
    return text


def node_connections(master: MasterClient, uri: str) -> str:
    """What the node at ``uri`` says of itself: its PID and its live connections.

    Raises:
        NodeContactError: the node does not answer (`InvalidNodeUriError`: it cannot be called).
        MasterError: the node refused (``remote call failed: …``).
    """
    state = master.system_state()
    try:
        pid = master.node_call(uri, "getPid", timeout=NODE_TIMEOUT)
        bus_info = master.node_call(uri, "getBusInfo", timeout=NODE_TIMEOUT)
    except InvalidUriError:
        raise InvalidNodeUriError(uri) from None
    except (TransportError, FaultError):
        raise NodeContactError(uri) from None
    except MasterError as error:
        raise MasterError(error.code, f"remote call failed: {error.status}") from None
    text = f"Pid: {pid}\n"
    if not bus_info:
        return text
    text += "Connections:\n"
    uris: dict[str, str | None] = {}
    for info in bus_info:
        dest, direction, transport, topic = info[1], info[2], info[3], info[4]
        if len(info) > 5 and not info[5]:
            continue  # no longer connected
        text += f" * topic: {topic}\n"
        text += f"    * to: {_peer(master, state, topic, dest, uris)}\n"
        text += _DIRECTIONS.get(direction, "    * direction: unknown")
        if len(info) > 6:
            match = _CONNECTION.match(info[6])
            if match is not None:
                text += " ({} - {}) [{}]".format(*match.groups())
        text += f"\n    * transport: {transport}\n"
    return text


def node_info(master: MasterClient, node: str) -> str:
    """``rosnode info``'s text for ``node`` (without its dashed line): the master's view, then,
    after ``contacting node …``, what the node says of itself.

    Raises:
        NodeContactError: the node does not answer.
        MasterError: the master or the node refused a call.
    """
    text = node_description(master, node)
    uri = master.lookup_node(node)
    if uri is None:
        return text + f"\ncannot contact [{node}]: unknown node\n"
    return text + f"\n\ncontacting node {uri} ...\n" + node_connections(master, uri)


def _peer(
    master: MasterClient, state: Any, topic: str, dest: str, uris: dict[str, str | None]
) -> str:
    """``dest`` (a node's URI) as ``/name (uri)`` when a node of ``topic`` has that URI."""
    for section in state[:2]:
        for name, nodes in section:
            if name != topic:
                continue
            for node in nodes:
                if node not in uris:
                    uris[node] = master.lookup_node(node)
                if uris[node] == dest:
                    return f"{node} ({dest})"
    return dest


# -- topics ------------------------------------------------------------------------------------


def topic_description(master: MasterClient, topic: str) -> str:
    """What ``rostopic info`` prints of ``topic``: its type, publishers and subscribers.

    Raises:
        UnknownTopicError: no node publishes or subscribes to it.
    """
    publishers, subscribers, _ = master.system_state()
    pubs = [n for name, nodes in publishers if name == topic for n in nodes]
    subs = [n for name, nodes in subscribers if name == topic for n in nodes]
    if not pubs and not subs:
        raise UnknownTopicError(topic)
    types = master.topic_types()
    lines = [f"Type: {types.get(topic, 'unknown type')}", ""]
    for title, nodes in (("Publishers", pubs), ("Subscribers", subs)):
        if nodes:
            lines.append(f"{title}: ")
            lines.extend(f" * {node} ({master.lookup_node(node)})" for node in nodes)
        else:
            lines.append(f"{title}: None")
        lines.append("")
    return "\n".join(lines) + "\n"


# -- summaries of a graph state ----------------------------------------------------------------


class TopicSummary(NamedTuple):
    """A topic with its type (``""`` when unknown) and the nodes at either end, sorted."""

    name: str
    type: str
    publishers: tuple[str, ...]
    subscribers: tuple[str, ...]


class NodeSummary(NamedTuple):
    """A node with how many topics it publishes and subscribes to."""

    name: str
    publications: int
    subscriptions: int


def topic_summaries(state: GraphState) -> tuple[TopicSummary, ...]:
    """Every topic of ``state`` (``rostopic list``), sorted by name."""
    return tuple(
        TopicSummary(
            topic,
            state.topic_types.get(topic, ""),
            tuple(sorted(state.publishers.get(topic, ()))),
            tuple(sorted(state.subscribers.get(topic, ()))),
        )
        for topic in state.topics
    )


def node_summaries(state: GraphState) -> tuple[NodeSummary, ...]:
    """Every node of ``state`` (``rosnode list``), sorted, with its topic counts."""
    return tuple(
        NodeSummary(
            node,
            sum(node in nodes for nodes in state.publishers.values()),
            sum(node in nodes for nodes in state.subscribers.values()),
        )
        for node in state.nodes
    )
