"""``tf_monitor [FRAME_A FRAME_B]``: who broadcasts each frame, how often, and how late.

As ROS 1's: every frame's broadcaster and its average and largest delay (now minus the
transform's stamp; 0 for static ones), every broadcaster's rate and delays, and with two frames
the chain between them and the delay of their lookup, printed about five times a second. Each
broadcaster is named (``<node>``, ``<node>(static)`` for a static frame), where ROS 1's prints
``unknown_publisher`` and ``unknown_publisher(static)``.
"""

from __future__ import annotations

import threading
from collections import deque
from typing import TYPE_CHECKING, Any

from rosx.names.anonymous import roscpp_anonymous_name

if TYPE_CHECKING:
    from collections.abc import Callable, Sequence

    from rosx.node import Node
    from rosx.tf import Buffer
    from rosx_commands.context import Environment

#: ROS 1 keeps the last 1000 samples of each series.
_KEEP = 1000


class Stats:
    """What tf_monitor has heard: delays per frame, delays and arrival times per broadcaster."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.authority: dict[str, str] = {}
        self.delays: dict[str, deque[float]] = {}
        self.broadcaster_delays: dict[str, deque[float]] = {}
        self.arrivals: dict[str, deque[float]] = {}

    def heard(self, message: Any, static: bool, now: float) -> None:
        """Account one TFMessage (``now``: ROS time in seconds, ``/clock``'s under sim time)."""
        header = getattr(message, "_connection_header", None) or {}
        who = header.get("callerid", "unknown_publisher") + ("(static)" if static else "")
        total = 0.0
        with self.lock:
            for t in message.transforms:
                child = t.child_frame_id
                self.authority[child] = who
                delay = 0.0 if static else now - t.header.stamp.to_sec()
                total += delay
                self.delays.setdefault(child, deque(maxlen=_KEEP)).append(delay)
            average = total / max(1, len(message.transforms))
            self.broadcaster_delays.setdefault(who, deque(maxlen=_KEEP)).append(average)
            self.arrivals.setdefault(who, deque(maxlen=_KEEP)).append(now)

    def report(self, chain: list[str] | None) -> tuple[str, str]:
        """The frames' lines (stdout) and the broadcasters' header (stderr) and lines."""
        with self.lock:
            frames = []
            for frame in sorted(self.delays):
                if chain is not None and frame not in chain:
                    continue
                series = self.delays[frame]
                average = _g(sum(series) / len(series))
                frames.append(
                    f"Frame: {frame} published by {self.authority.get(frame, '')} "
                    f"Average Delay: {average} Max Delay: {_g(_max(series))}\n"
                )
            nodes = []
            for who in sorted(self.broadcaster_delays):
                series = self.broadcaster_delays[who]
                arrivals = self.arrivals[who]
                rate = len(arrivals) / max(0.00000001, arrivals[-1] - arrivals[0])
                nodes.append(
                    f"Node: {who} {_g(rate)} Hz, Average Delay: {_g(sum(series) / len(series))} "
                    f"Max Delay: {_g(_max(series))}\n"
                )
        return "".join(frames), "".join(nodes)


def _max(series: deque[float]) -> float:
    return max(0.0, *series)


def _g(value: float) -> str:
    """A double as C++'s default stream format prints it (``%g``)."""
    return f"{value:g}"


def tf_monitor(argv: Sequence[str], env: Environment) -> int:
    """Run ``tf_monitor ARGV…``; its exit status (255 for a wrong command line)."""
    from rosx.node import INFO  # noqa: PLC0415 - the node runtime loads with the first node
    from rosx_turtle.console import Console  # noqa: PLC0415 - turtlesim's parts load only when used
    from rosx_turtle.roscpp import NodeArgs  # noqa: PLC0415 - turtlesim's parts load only when used

    args = NodeArgs.parse(argv, roscpp_anonymous_name("tf_monitor"))
    words = list(args.argv)
    if len(words) not in (0, 2):
        Console(env.stdout, env.stderr, env.environ).print(
            INFO, "TF_Monitor: usage: tf_monitor framea frameb"
        )
        return 255

    def body(node: Node) -> None:
        from rosx.tf import Buffer, TransformListener  # noqa: PLC0415 - tf code loads only when used

        buffer = Buffer(node=node, debug=False)
        TransformListener(buffer, node=node)
        monitor(node, buffer, words[0] if words else None, words[1] if words else None, env)

    from rosx_commands.tf_tools.running import run_node  # noqa: PLC0415 - this tool's parts load only when used

    return run_node(args, env, body)


def monitor(
    node: Node, buffer: Buffer, frame_a: str | None, frame_b: str | None, env: Environment
) -> None:
    """tf_monitor's loop: report every 21 lookups 10 ms apart, until the node shuts down."""
    from rosx.client.timing import Time  # noqa: PLC0415 - the rospy API loads only when used
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use
    from rosx.node.errors import NodeShutdownError  # noqa: PLC0415 - with the node runtime
    from rosx.tf import TransformException  # noqa: PLC0415 - tf code loads only when used

    out = env.stdout
    chain: list[str] | None = None
    if frame_a is not None and frame_b is not None:
        out.write(
            f"Waiting for transform chain to become available between {frame_a} and {frame_b} "
        )
        out.flush()
        while not node.is_shutdown() and not buffer.can_transform(frame_a, frame_b, Time(), 1.0):
            out.write(".")
            out.flush()
        out.write("\n")
        try:
            chain = buffer.chain(frame_b, 0, frame_a, 0, frame_b)
        except TransformException as error:
            env.stderr.write(f"Transform Exception {error}\n")
            return
    stats = Stats()
    tf_message = get_message_class("tf2_msgs/TFMessage")
    clock = node.clock
    try:  # under simulated time, delays are measured once /clock has come (not from 0)
        clock.sleep(0.0, shutdown=node.shutdown_event)
    except NodeShutdownError:
        return

    def heard(static: bool) -> Callable[[Any], None]:
        return lambda message: stats.heard(message, static, clock.now().to_sec())

    node.subscribe("tf", tf_message, heard(False), queue_size=100)
    node.subscribe("tf_static", tf_message, heard(True), queue_size=100)
    average = largest = 0.0
    counter = 0
    while not node.is_shutdown():
        counter += 1
        if chain is not None:
            try:
                stamp, _ = buffer.lookup(frame_a or "", frame_b or "", 0)
                delay = clock.now().to_sec() - stamp / 1e9
                average = 0.01 * delay + 0.99 * average
                largest = max(largest, delay)
            except TransformException:
                pass
        if node.wait_for_shutdown(0.01):
            break
        if counter <= 20:
            continue
        counter = 0
        _print_report(stats, chain, (frame_a, frame_b, average, largest), env)


def _print_report(
    stats: Stats, chain: list[str] | None, net: tuple[Any, Any, float, float], env: Environment
) -> None:
    """One of tf_monitor's reports (the broadcasters' header on stderr, as ROS 1's)."""
    out = env.stdout
    if chain is not None:
        frame_a, frame_b, average, largest = net
        out.write(f"\n\n\nRESULTS: for {frame_a} to {frame_b}\n")
        out.write(f"Chain is: {' -> '.join(chain)}\n")
        out.write(f"Net delay     avg = {_g(average)}: max = {_g(largest)}\n")
    else:
        out.write("\n\n\nRESULTS: for all Frames\n")
    frames, nodes = stats.report(chain)
    out.write(f"\nFrames:\n{frames}")
    out.flush()
    env.stderr.write("\nAll Broadcasters:\n")
    env.stderr.flush()
    out.write(nodes)
    out.flush()


__all__ = ["Stats", "monitor", "tf_monitor"]
