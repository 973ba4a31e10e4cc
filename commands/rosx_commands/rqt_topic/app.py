"""`TopicPane`: rqt_topic in the terminal; `TopicApp` runs it alone, ``rosx rqt`` as a tab.

Every published topic is a row of a tree: whether it is monitored, its name, type, bandwidth
and rate. As in rqt_topic, a topic is measured only while it is monitored (``space`` toggles,
rqt_topic's check box), and then its latest message is the row's subtree (``enter`` expands
and collapses). The topic list is read from the master every `TOPICS_PERIOD` seconds on a
worker thread; the monitored rows are updated every `READING_PERIOD` seconds, and a subtree
only while it is expanded. ``q`` or ``ctrl+c`` quit.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, ClassVar

from rich.text import Text
from textual.app import ComposeResult  # noqa: TID253 - TUI code
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Vertical  # noqa: TID253 - TUI code
from textual.widgets import Static, Tree  # noqa: TID253 - TUI code

from rosx_commands.paneapp import PaneApp
from rosx_commands.rqt_topic.monitor import (
    Field,
    LiveTopicSource,
    Reading,
    bytes_per_second,
    fields,
)

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual.widgets.tree import TreeNode

    from rosx_commands.context import Environment
    from rosx_commands.rqt_topic.monitor import TopicSource

#: Seconds between two readings of the topic list.
TOPICS_PERIOD = 2.0
#: Seconds between two updates of the monitored topics (rqt_topic's is one).
READING_PERIOD = 1.0
MONITORED, UNMONITORED = "☑", "☐"


class TopicTree(Tree[str]):
    """The topics and their latest messages; ``space`` toggles monitoring of a topic."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("space", "monitor", "Monitor"),
    ]

    def action_monitor(self) -> None:
        """Space: start or stop monitoring the topic under the cursor (or the topic of the field
        there)."""
        node = self.cursor_node
        while node is not None and node.parent is not None and node.parent is not self.root:
            node = node.parent
        if node is not None and node.data is not None:
            pane = next(a for a in self.ancestors if isinstance(a, TopicPane))
            pane.toggle(node.data)


class TopicPane(Vertical):
    """The header, the tree of topics and a status line."""

    DEFAULT_CSS = """
    TopicPane #topic-header { height: 1; background: $boost; text-style: bold; padding-left: 4; }
    TopicPane #topics { height: 1fr; }
    TopicPane #topic-status { height: 1; background: $boost; }
    """

    def __init__(self, source: TopicSource, *, periodic: bool = True, id: str | None = None):
        super().__init__(id=id)
        self.source = source
        self.periodic = periodic
        self.types: dict[str, str] = {}
        self.monitored: set[str] = set()
        self.readings: dict[str, Reading] = {}
        self.error: str | None = None
        self._rows: dict[str, TreeNode[str]] = {}

    @override
    def compose(self) -> ComposeResult:
        yield Static(id="topic-header")
        tree = TopicTree("topics", id="topics")
        tree.show_root = False
        tree.guide_depth = 2
        yield tree
        yield Static(id="topic-status")

    @property
    def topic_tree(self) -> TopicTree:
        """The tree of topics and, under monitored ones, their fields."""
        return self.query_one(TopicTree)

    def on_mount(self) -> None:
        """Focus the tree and read the topics; refresh the list every `TOPICS_PERIOD` seconds and
        the monitored readings every `READING_PERIOD`."""
        self.topic_tree.focus()
        self.refresh_topics()
        if self.periodic:
            self.set_interval(TOPICS_PERIOD, self.refresh_topics)
            self.set_interval(READING_PERIOD, self.update_readings)
        self._status()

    # -- the topic list ----------------------------------------------------------------------

    def refresh_topics(self) -> None:
        """Read the published topics on a worker thread, unless a read is still under way."""
        if not any(w.group == "topics" and w.is_running for w in self.workers):
            self.run_worker(self._read_topics, thread=True, group="topics")

    def _read_topics(self) -> None:
        try:
            topics = self.source.topics()
        except Exception as error:
            self.app.call_from_thread(self._failed, error)
            return
        self.app.call_from_thread(self.show_topics, topics)

    def _failed(self, error: Exception) -> None:
        from rosx_commands.errors import error_line  # noqa: PLC0415 - this tool's parts load only when used

        self.error = error_line(error)
        self._status()

    def show_topics(self, topics: list[tuple[str, str]]) -> None:
        """Show ``topics`` (sorted ``(name, type)``): new ones added in place, gone ones
        dropped (and no longer monitored)."""
        self.error = None
        self.types = dict(topics)
        for topic in [t for t in self._rows if t not in self.types]:
            self._rows.pop(topic).remove()
            if topic in self.monitored:
                self.toggle(topic)
        names = [t for t, _ in topics]
        for index, topic in enumerate(names):
            if topic in self._rows:
                continue
            after = self._rows.get(names[index - 1]) if index else None
            if after is None and self._rows:
                first = next(iter(self.topic_tree.root.children), None)
                node = self.topic_tree.root.add(topic, topic, before=first)
            else:
                node = self.topic_tree.root.add(topic, topic, after=after)
            self._rows[topic] = node
        self._relabel()
        self._status()

    # -- monitoring --------------------------------------------------------------------------

    def toggle(self, topic: str) -> None:
        """Start or stop monitoring ``topic`` (its subtree goes with it)."""
        node = self._rows.get(topic)
        if topic in self.monitored:
            self.monitored.discard(topic)
            self.readings.pop(topic, None)
            self.run_worker(lambda: self.source.unmonitor(topic), thread=True)
            if node is not None:
                node.remove_children()
        else:
            self.monitored.add(topic)
            type_name = self.types.get(topic, "*")
            self.run_worker(lambda: self._monitor(topic, type_name), thread=True)
        self._relabel()
        self._status()

    def _monitor(self, topic: str, type_name: str) -> None:
        try:
            self.source.monitor(topic, type_name)
        except Exception as error:
            self.app.call_from_thread(self._failed, error)

    def update_readings(self) -> None:
        """Read the monitored topics' figures and latest messages into the tree."""
        for topic in sorted(self.monitored):
            reading = self.source.reading(topic)
            previous = self.readings.get(topic)
            self.readings[topic] = reading
            node = self._rows.get(topic)
            if node is None or reading.message is None:
                continue
            new = previous is None or previous.count != reading.count
            if (new and node.is_expanded) or not node.children:
                _sync(node, fields(reading.message))
        self._relabel()

    def on_tree_node_expanded(self, event: Tree.NodeExpanded[str]) -> None:
        """Fill an expanded topic's fields from its latest message."""
        reading = self.readings.get(event.node.data or "")
        if event.node.parent is self.topic_tree.root and reading and reading.message is not None:
            _sync(event.node, fields(reading.message))

    # -- text --------------------------------------------------------------------------------

    def _relabel(self) -> None:
        names = max((len(t) for t in self._rows), default=5)
        types = max((len(t) for t in self.types.values()), default=4)
        header = f"{'Topic':<{names}}  {'Type':<{types}}  {'Bandwidth':>10}  {'Hz':>8}"
        self.query_one("#topic-header", Static).update(Text(header, no_wrap=True))
        for topic, node in self._rows.items():
            on = topic in self.monitored
            reading = self.readings.get(topic, Reading())
            rate = f"{reading.rate:.2f}" if reading.rate is not None else ""
            label = Text(f"{MONITORED if on else UNMONITORED} ", style="bold" if on else "dim")
            label.append(f"{topic:<{names}}  ", style="bold" if on else "")
            label.append(f"{self.types.get(topic, ''):<{types}}  ", style="cyan")
            label.append(f"{bytes_per_second(reading.bandwidth):>10}  {rate:>8}")
            node.set_label(label)

    def _status(self) -> None:
        text = f" {len(self._rows)} topics, {len(self.monitored)} monitored"
        text += " │ space: monitor, enter: expand"
        if self.error:
            text += f" │ {self.error}"
        self.query_one("#topic-status", Static).update(Text(text, no_wrap=True))

    def on_unmount(self) -> None:
        """Close the source (its node)."""
        self.source.close()


def _sync(node: TreeNode[str], rows: tuple[Field, ...]) -> None:
    """Make ``node``'s children show ``rows``: labels updated in place while the fields are
    the same (expanded rows stay expanded), rebuilt when they differ."""
    children = list(node.children)
    if [child.data for child in children] != [row.name for row in rows]:
        node.remove_children()
        for row in rows:
            if row.children:
                _sync(node.add(_label(row), row.name), row.children)
            else:
                node.add_leaf(_label(row), row.name)
        return
    for child, row in zip(children, rows, strict=True):
        child.set_label(_label(row))
        if row.children:
            _sync(child, row.children)


def _label(row: Field) -> Text:
    text = Text(row.name)
    if row.value:
        text.append(": ")
        text.append(row.value, style="bold")
    return text


class TopicApp(PaneApp[TopicPane]):
    """``rosx rqt_topic`` on its own: the pane and a footer."""


def make_topic_app(source: TopicSource, *, periodic: bool = True) -> TopicApp:
    """The app the CLI runs and the tests drive (``periodic=False``: no timers, the test
    calls `TopicPane.update_readings` and `TopicPane.refresh_topics` itself)."""
    return TopicApp(TopicPane(source, periodic=periodic))


def topic_tab(env: Environment) -> TopicPane:
    """rqt_topic as a tab of ``rosx rqt``."""
    return TopicPane(LiveTopicSource(env))
