"""A fixed graph source for rqt_graph's pane (no master, no network)."""

from __future__ import annotations

from rosx.graph.state import GraphState
from rosx.graph.view import Vertex


class StaticSource:
    """A graph that changes only when a test says so."""

    def __init__(self, state: GraphState) -> None:
        self.state = state
        self.closed = False

    def snapshot(self) -> GraphState:
        return self.state

    def describe(self, vertex: Vertex) -> str:
        return f"Node [{vertex.label}]" if vertex.kind == "node" else f"Type: x ({vertex.label})"

    def rate(self, topic: str) -> str:
        return "average rate: 10.000 Hz"

    def close(self) -> None:
        self.closed = True
