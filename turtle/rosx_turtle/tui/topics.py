"""`TopicsPanel`: the live topic list with types and publisher/subscriber counts."""

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


class TopicsPanel(GraphTable):
    """Every topic (``rostopic list``) with its type and how many nodes publish and subscribe."""

    COLUMNS = ("topic", "type", "pub", "sub")
    NOUN = "topics"

    DEFAULT_CSS = """
    TopicsPanel { height: 1fr; }
    """

    def __init__(self, feed: Feed[Graph] | None = None, *, id: str | None = None) -> None:
        super().__init__("Topics", feed, id=id)

    @override
    def rows_of(self, graph: Graph) -> Iterator[tuple[str, ...]]:
        for topic in graph.topics:
            counts = str(len(topic.publishers)), str(len(topic.subscribers))
            yield topic.name, topic.type or "?", *counts
