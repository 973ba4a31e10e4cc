"""`NodesPanel`: the live node list, with how many topics each publishes and subscribes to."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from rosx_turtle.tui.graph_table import GraphTable

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Iterator

    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.graph import Graph


class NodesPanel(GraphTable):
    """Every node (``rosnode list``), with its publication and subscription counts."""

    COLUMNS = ("node", "pub", "sub")
    NOUN = "nodes"

    DEFAULT_CSS = """
    NodesPanel { height: 8; }
    """

    def __init__(self, feed: Feed[Graph] | None = None, *, id: str | None = None) -> None:
        super().__init__("Nodes", feed, id=id)

    @override
    def rows_of(self, graph: Graph) -> Iterator[tuple[str, ...]]:
        for node in graph.nodes:
            yield node.name, str(node.publications), str(node.subscriptions)
