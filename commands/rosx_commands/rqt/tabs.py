"""The registry of ``rosx rqt``'s tabs: one `Tab` per rqt tool, in the order they appear.

Each rqt tool keeps its view in its own module as a pane (a textual widget) and gives
``rosx rqt`` a factory: a function taking the command's `Environment` and returning the pane,
live on the master ``ROS_MASTER_URI`` names. The pane owns what it started (nodes,
subscriptions) and releases it when unmounted. A tool joins ``rosx rqt`` with one line in
`TABS`, naming its factory as ``"module:function"``: the factory is imported only when its tab
is first opened, so no tool module imports another one, and a tab costs nothing until used.

To add a tool: write ``def my_tab(env: Environment) -> Widget`` next to the tool's app and
register it here as ``Tab("name", "Title", "rosx_commands.my_tool.app:my_tab")``.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from textual.widget import Widget

    from rosx_commands.context import Environment

Factory = Callable[["Environment"], "Widget"]


@dataclass(frozen=True)
class Tab:
    """One tool as a tab: its name (``rosx rqt -s NAME``), its title and its factory (a
    ``"module:function"`` path, or the function itself)."""

    name: str
    title: str
    factory: str | Factory

    def load(self) -> Factory:
        """The factory, imported on first use when it is given as a path."""
        if not isinstance(self.factory, str):
            return self.factory
        module, _, function = self.factory.partition(":")
        loaded: Factory = getattr(importlib.import_module(module), function)
        return loaded


TABS: tuple[Tab, ...] = (
    Tab("graph", "Graph", "rosx_commands.rqt_graph.app:graph_tab"),
    Tab("plot", "Plot", "rosx_commands.rqt_plot.app:plot_tab"),
    Tab("topic", "Topics", "rosx_commands.rqt_topic.app:topic_tab"),
    Tab("console", "Console", "rosx_commands.rqt_console.app:console_tab"),
    Tab("logger_level", "Logger levels", "rosx_commands.rqt_logger_level.app:logger_level_tab"),
    Tab("rviz", "rviz", "rosx_commands.rviz.run:rviz_tab"),
    Tab("tf_tree", "TF tree", "rosx_commands.rqt_tf_tree.app:tf_tree_tab"),
)
