"""turtlesim_view: every turtlesim of the graph, drawn side by side in one terminal.

Under ``rosx roslaunch`` several turtlesim_node processes share one terminal, so none draws
its pond (they log, as without a terminal). ``rosx rosrun turtlesim turtlesim_view``, in a
terminal of its own, shows them all: it finds every turtlesim on the graph (the nodes that
publish ``turtlesim/Pose`` topics, ``<ns>/<turtle>/pose``), subscribes to each turtle's pose and
colour sensor, and draws one pond per node with its name above and the poses below
(`rosx_turtle.view.remote` says how a pond is rebuilt from its topics and what it cannot show).
Turtlesims that start later appear within a second; those that go away leave.

Without a terminal it prints a line per pond as it appears (``pond /turtlesim1/sim: turtle1``)
and one when a turtle joins or leaves, until Ctrl-C. The viewer is a node itself, named
``/turtlesim_view_<anonymous part>``.
"""

from __future__ import annotations

import contextlib
import threading
from typing import TYPE_CHECKING, Any

from rosx.graph.state import registrations
from rosx.msg.codec.classes import get_message_class
from rosx.signals import stop_on_signals
from rosx.terminal import is_terminal
from rosx_turtle.console import Console
from rosx_turtle.env import ProcessEnv
from rosx_turtle.program import master_address, start_when_master_is_up
from rosx_turtle.roscpp import NodeArgs

if TYPE_CHECKING:
    from collections.abc import Callable, Iterable, Mapping, Sequence

    from rosx.node import Node
    from rosx_turtle.env import Env
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.view.remote import RemotePond
    from rosx_turtle.view.scene import Scene

POSE_TYPE = "turtlesim/Pose"
#: Seconds between two looks at the graph for turtlesims that came or went.
GRAPH_PERIOD = 1.0
#: Scenes offered to the view per second at most, per pond.
FRAME_RATE = 30.0


def find_ponds(
    topic_types: Sequence[Sequence[str]], publishers: Iterable[Sequence[Any]]
) -> dict[str, dict[str, str]]:
    """The turtlesims of a graph: node -> {turtle name -> its topics' prefix}.

    ``topic_types`` is the master's ``getTopicTypes`` answer, ``publishers`` each published
    topic with its nodes (`rosx.graph.state.GraphState.publishers`). A turtlesim is a node
    publishing ``<prefix>/pose`` of type ``turtlesim/Pose``; the turtle's name is the last part
    of the prefix.
    """
    poses = {topic for topic, kind in topic_types if kind == POSE_TYPE}
    ponds: dict[str, dict[str, str]] = {}
    for topic, nodes in publishers:
        if topic not in poses or not topic.endswith("/pose"):
            continue
        prefix = topic[: -len("/pose")]
        turtle = prefix.rsplit("/", 1)[-1]
        for node in nodes:
            ponds.setdefault(node, {})[turtle] = prefix
    return {node: dict(sorted(turtles.items())) for node, turtles in sorted(ponds.items())}


class _Pond:
    """One turtlesim watched: its remote pond, its feed and its subscriptions."""

    def __init__(self, name: str, pond: RemotePond, feed: Feed[Scene] | None) -> None:
        self.name = name
        self.pond = pond
        self.feed = feed
        self.handles: dict[str, list[Any]] = {}


class PondWatcher:
    """Keeps one `RemotePond` per turtlesim of the graph, through ``node``.

    ``on_pond(name, feed)`` is called (on the watcher's thread) for each turtlesim found,
    ``on_change(name, turtles)`` when its turtles change, ``on_gone(name)`` when it leaves.
    """

    def __init__(
        self,
        node: Node,
        *,
        on_pond: Callable[[str, Feed[Scene] | None], object],
        on_change: Callable[[str, list[str]], object] | None = None,
        on_gone: Callable[[str], object] | None = None,
        with_feeds: bool = True,
    ) -> None:
        self.node = node
        self.on_pond = on_pond
        self.on_change = on_change
        self.on_gone = on_gone
        self.with_feeds = with_feeds
        self.ponds: dict[str, _Pond] = {}
        self._stop = threading.Event()
        self._threads: list[threading.Thread] = []

    def start(self) -> PondWatcher:
        """Look at the graph at once and every `GRAPH_PERIOD`, and offer scenes at
        `FRAME_RATE`, on threads of its own."""
        for target, name in ((self._watch, "graph"), (self._frames, "frames")):
            thread = threading.Thread(target=target, name=f"turtlesim-view-{name}", daemon=True)
            thread.start()
            self._threads.append(thread)
        return self

    def stop(self) -> None:
        """Stop looking (the node's subscriptions end with the node)."""
        self._stop.set()
        for thread in self._threads:
            thread.join(timeout=2.0)

    def _watch(self) -> None:
        while True:
            with contextlib.suppress(Exception):  # the master went away: try again later
                self.refresh()
            if self._stop.wait(GRAPH_PERIOD):
                return

    def _frames(self) -> None:
        while not self._stop.wait(1.0 / FRAME_RATE):
            for watched in list(self.ponds.values()):
                if watched.feed is not None and watched.pond.dirty:
                    watched.feed.offer(watched.pond.scene())

    def refresh(self) -> None:
        """Look at the graph once: add, update and drop ponds."""
        topic_types = self.node.master.call("getTopicTypes")
        publishers = registrations(self.node.master).publishers.items()
        found = find_ponds(topic_types, publishers)
        for name in [n for n in self.ponds if n not in found]:
            self._drop(name)
        for name, turtles in found.items():
            watched = self.ponds.get(name) or self._add(name)
            self._follow(watched, turtles)

    def _add(self, name: str) -> _Pond:
        from rosx_turtle.view.remote import RemotePond  # noqa: PLC0415 - numpy

        background = [
            self._param(f"{name}/background_{c}", d) for c, d in zip("rgb", _DEFAULT, strict=True)
        ]
        feed: Feed[Scene] | None = None
        if self.with_feeds:
            from rosx_turtle.tui.feed import Feed  # noqa: PLC0415 - textual

            feed = Feed()
        watched = self.ponds[name] = _Pond(name, RemotePond(background), feed)
        self.on_pond(name, feed)
        return watched

    def _param(self, name: str, default: int) -> int:
        try:
            value = self.node.master.call("getParam", name)
        except Exception:  # not set: turtlesim's default
            return default
        return int(value) if isinstance(value, int) else default

    def _follow(self, watched: _Pond, turtles: Mapping[str, str]) -> None:
        before = sorted(watched.handles)
        pose_type = get_message_class(POSE_TYPE)
        colour_type = get_message_class("turtlesim/Color")
        for turtle in [t for t in watched.handles if t not in turtles]:
            for handle in watched.handles.pop(turtle):
                handle.unregister()
            watched.pond.forget(turtle)
        for turtle, prefix in turtles.items():
            if turtle in watched.handles:
                continue

            def on_pose(msg: Any, turtle: str = turtle, pond: RemotePond = watched.pond) -> None:
                from rosx_turtle.view.scene import TurtlePose  # noqa: PLC0415 - turtlesim's parts load only when used

                pose = TurtlePose(
                    turtle, msg.x, msg.y, msg.theta, msg.linear_velocity, msg.angular_velocity
                )
                pond.set_pose(turtle, pose)

            def on_colour(msg: Any, turtle: str = turtle, pond: RemotePond = watched.pond) -> None:
                pond.set_colour(turtle, (msg.r, msg.g, msg.b))

            watched.handles[turtle] = [
                self.node.subscribe(f"{prefix}/color_sensor", colour_type, on_colour, queue_size=1),
                self.node.subscribe(f"{prefix}/pose", pose_type, on_pose, queue_size=1),
            ]
        after = sorted(watched.handles)
        if after != before and self.on_change is not None:
            self.on_change(watched.name, after)

    def _drop(self, name: str) -> None:
        watched = self.ponds.pop(name)
        for handles in watched.handles.values():
            for handle in handles:
                handle.unregister()
        if self.on_gone is not None:
            self.on_gone(name)


_DEFAULT = (69, 86, 255)


def _text_mode(node: Node, env: Env, stop: threading.Event) -> None:
    lock = threading.Lock()

    def say(text: str) -> None:
        with lock:
            env.stdout.write(text + "\n")
            env.stdout.flush()

    watcher = PondWatcher(
        node,
        on_pond=lambda name, _: None,
        on_change=lambda name, turtles: say(f"pond {name}: {' '.join(turtles)}"),
        on_gone=lambda name: say(f"pond {name}: gone"),
        with_feeds=False,
    ).start()
    try:
        while not stop.is_set() and not node.wait_for_shutdown(0.1):
            pass
    finally:
        watcher.stop()


def _screen_mode(node: Node) -> None:
    from rosx_turtle.tui.factory import make_ponds_app  # noqa: PLC0415 - textual to draw
    from rosx_turtle.tui.running import run_app  # noqa: PLC0415 - turtlesim's parts load only when used

    watcher: PondWatcher | None = None

    def start() -> None:
        nonlocal watcher
        watcher = PondWatcher(
            node,
            on_pond=lambda name, feed: app.call_from_thread(app.add_pond, name, feed),
            on_gone=lambda name: app.call_from_thread(app.remove_pond, name),
        ).start()

    app = make_ponds_app(start)
    try:
        run_app(app, gone=node.wait_for_shutdown)
    finally:
        if watcher is not None:
            watcher.stop()


def run_turtlesim_view(argv: Sequence[str], env: Env | None = None) -> int:
    """Run turtlesim_view: the ponds on a terminal, their turtles as lines otherwise."""
    from rosx.names.anonymous import anonymous_name  # noqa: PLC0415 - name rules load only when used

    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, anonymous_name("turtlesim_view"))
    console = Console(env.stdout, env.stderr, env.environ)
    address = master_address(args.master_uri, env.environ)
    with stop_on_signals() as stop:
        node = start_when_master_is_up(
            lambda: args.make_node(env.environ).start(), console, address, stop
        )
        if node is None:
            return 0
        try:
            if is_terminal(env.stdout):
                _screen_mode(node)
            else:
                _text_mode(node, env, stop)
        finally:
            node.shutdown("viewer closed")
    return 0


__all__ = ["PondWatcher", "find_ponds", "run_turtlesim_view"]
