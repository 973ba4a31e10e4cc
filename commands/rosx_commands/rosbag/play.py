"""``rosbag play``: ROS 1's options, a `rosx.bag.player.Player` on an anonymous node.

Prints what ROS 1's player prints: the bags it opens, the wait after advertising, the keys,
and (unless ``-q``) a status line rewritten in place. On a terminal, space pauses and resumes,
``s`` steps one message while paused and ``t`` turns pausing on ``--pause-topics`` off and on;
anywhere, the ``~pause_playback`` service pauses and resumes. ``topic:=other`` arguments remap
topics.
"""

from __future__ import annotations

import contextlib
import optparse
import os
import sys
import threading
import time
from typing import TYPE_CHECKING, Any

from rosx.names.remap_args import strip_remap_args
from rosx.terminal import is_terminal
from rosx_commands.cli import ToolParser
from rosx_commands.context import Environment, ExitStatus
from rosx_commands.errors import unreachable

if TYPE_CHECKING:
    from collections.abc import Iterator

    from rosx.bag.player import Player
    from rosx.bag.reader import BagReader


def _collect(dest: str) -> Any:
    def callback(option: Any, opt_str: str, value: Any, parser: optparse.OptionParser) -> None:
        rargs: list[str] = parser.rargs or []
        taken = []
        for arg in rargs:
            if arg.startswith("-") and len(arg) > 1:
                break
            taken.append(arg)
        getattr(parser.values, dest).extend(taken)
        del rargs[: len(taken)]

    return callback


def build_parser(env: Environment) -> ToolParser:
    """ROS 1's ``rosbag play`` options, in its order and with its help texts."""
    p = ToolParser(env, "rosbag", "rosbag play BAGFILE1 [BAGFILE2 BAGFILE3 ...]")
    p.description = (
        "Play back the contents of one or more bag files in a time-synchronized fashion."
    )
    add = p.add_option
    add("-p", "--prefix", dest="prefix", default="", type="str", help="prefix all output topics")
    add(
        "-q",
        "--quiet",
        dest="quiet",
        default=False,
        action="store_true",
        help="suppress console output",
    )
    add(
        "-i",
        "--immediate",
        dest="immediate",
        default=False,
        action="store_true",
        help="play back all messages without waiting",
    )
    add("--pause", dest="pause", default=False, action="store_true", help="start in paused mode")
    add(
        "--queue",
        dest="queue",
        default=100,
        type="int",
        action="store",
        metavar="SIZE",
        help="use an outgoing queue of size SIZE (defaults to %default)",
    )
    add("--clock", dest="clock", default=False, action="store_true", help="publish the clock time")
    add(
        "--hz",
        dest="freq",
        default=100,
        type="float",
        action="store",
        metavar="HZ",
        help="use a frequency of HZ when publishing clock time (default: %default)",
    )
    add(
        "-d",
        "--delay",
        dest="delay",
        default=0.2,
        type="float",
        action="store",
        metavar="SEC",
        help="sleep SEC seconds after every advertise call (to allow subscribers to connect)",
    )
    add(
        "-r",
        "--rate",
        dest="rate",
        default=1.0,
        type="float",
        action="store",
        metavar="FACTOR",
        help="multiply the publish rate by FACTOR",
    )
    add(
        "-s",
        "--start",
        dest="start",
        default=0.0,
        type="float",
        action="store",
        metavar="SEC",
        help="start SEC seconds into the bag files",
    )
    add(
        "-u",
        "--duration",
        dest="duration",
        default=None,
        type="float",
        action="store",
        metavar="SEC",
        help="play only SEC seconds from the bag files",
    )
    add(
        "--skip-empty",
        dest="skip_empty",
        default=None,
        type="float",
        action="store",
        metavar="SEC",
        help="skip regions in the bag with no messages for more than SEC seconds",
    )
    add("-l", "--loop", dest="loop", default=False, action="store_true", help="loop playback")
    add(
        "-k",
        "--keep-alive",
        dest="keep_alive",
        default=False,
        action="store_true",
        help="keep alive past end of bag (useful for publishing latched topics)",
    )
    add(
        "--try-future-version",
        dest="try_future",
        default=False,
        action="store_true",
        help="still try to open a bag file, even if the version number is not known to the player",
    )
    add(
        "--topics",
        dest="topics",
        default=[],
        callback=_collect("topics"),
        action="callback",
        help="topics to play back",
    )
    add(
        "--pause-topics",
        dest="pause_topics",
        default=[],
        callback=_collect("pause_topics"),
        action="callback",
        help="topics to pause on during playback",
    )
    add("--bags", help="bags files to play back from")
    add(
        "--wait-for-subscribers",
        dest="wait_for_subscribers",
        default=False,
        action="store_true",
        help="wait for at least one subscriber on each topic before publishing",
    )
    add(
        "--rate-control-topic",
        dest="rate_control_topic",
        default="",
        type="str",
        help="watch the given topic, and if the last publish was more than "
        "<rate-control-max-delay> ago, wait until the topic publishes again to continue playback",
    )
    add(
        "--rate-control-max-delay",
        dest="rate_control_max_delay",
        default=1.0,
        type="float",
        help="maximum time difference from <rate-control-topic> before pausing",
    )
    return p


def _log(env: Environment, level: str, text: str) -> None:
    now = time.time_ns()
    line = f"[{level:>5}] [{now // 1_000_000_000}.{now % 1_000_000_000:09d}]: {text}\n"
    (env.stdout if level == "INFO" else env.stderr).write(line)
    (env.stdout if level == "INFO" else env.stderr).flush()


def _remaps(argv: list[str]) -> dict[str, str]:
    return dict(a.split(":=", 1) for a in argv if ":=" in a and not a.startswith("__"))


def play(argv: list[str], env: Environment) -> int:
    """Run ``rosbag play ARGV…``."""
    remaps = _remaps(argv)
    parser = build_parser(env)
    options, args = parser.parse(strip_remap_args(argv))
    if options.bags:
        args.append(options.bags)
    if not args:
        parser.error("You must specify at least 1 bag file to play back.")
    if not options.rate > 0:  # ROS 1's dies of a time overflow at 0, and below publishes at once
        _log(
            env,
            "FATAL",
            f"The rate (-r {options.rate:g}) must be greater than 0 "
            "(-i publishes without waiting, --pause starts paused)",
        )
        return ExitStatus.ERROR

    from rosx.bag.errors import BagError, BagUnindexedError, NotABagError  # noqa: PLC0415 - bag code loads only for bags
    from rosx.bag.player import Player, PlayOptions  # noqa: PLC0415 - bag code loads only for bags
    from rosx.bag.reader import BagReader  # noqa: PLC0415 - bag code loads only for bags
    from rosx.node import Node  # noqa: PLC0415 - the node runtime loads with the first node

    bags: list[BagReader] = []
    try:
        for path in args:
            _log(env, "INFO", f"Opening {path}")
            try:
                bags.append(BagReader(path))
            except BagUnindexedError:
                # ROS 1's words for a bag whose index was never written; also said of a bag
                # cut short, where ROS 1's reports a failed read instead (README.md).
                env.err(f"Bag file {path} is unindexed.  Run rosbag reindex.")
                return ExitStatus.ERROR
            except OSError:
                _log(env, "FATAL", f"Error opening file: {path}")
                return ExitStatus.ERROR
            except NotABagError:
                _log(env, "FATAL", "Error reading version line")
                return ExitStatus.ERROR
            except BagError as exc:
                _log(env, "FATAL", f"Error reading {path}: {exc}")
                return ExitStatus.ERROR
        uri = env.master_uri
        node = Node(
            f"play_{time.time_ns()}", master_uri=uri, environ=env.environ, remappings=remaps
        )
        try:
            node.start()
        except Exception:
            node.shutdown("start-up failed")
            raise unreachable(env, uri) from None
        try:
            player = Player(
                node,
                bags,
                PlayOptions(
                    prefix=options.prefix,
                    quiet=options.quiet,
                    immediate=options.immediate,
                    pause=options.pause,
                    queue_size=options.queue,
                    clock=options.clock,
                    hz=options.freq,
                    delay=options.delay,
                    rate=options.rate,
                    start=options.start,
                    duration=options.duration,
                    skip_empty=options.skip_empty,
                    loop=options.loop,
                    keep_alive=options.keep_alive,
                    topics=options.topics,
                    pause_topics=options.pause_topics,
                    rate_control_topic=options.rate_control_topic or "",
                    rate_control_max_delay=options.rate_control_max_delay,
                ),
                status=None if options.quiet else _writer(env),
                say=_writer(env),
            )
            return _run(player, options, env)
        finally:
            node.shutdown("rosbag play exited")
    finally:
        for bag in bags:
            bag.close()


def _writer(env: Environment) -> Any:
    def write(text: str) -> None:
        env.stdout.write(text)
        env.stdout.flush()

    return write


def _run(player: Player, options: optparse.Values, env: Environment) -> int:
    player.serve_pause()
    player.advertise()
    if not options.quiet:
        env.stdout.write("\n")  # ROS 1's status line's room, which -q does without
    if options.rate_control_topic:
        env.stdout.write("Creating rate control topic subscriber...")
        env.stdout.flush()
        player.watch_rate_control()
        env.stdout.write(" done.\n")
    env.stdout.write(f"Waiting {options.delay:g} seconds after advertising topics...")
    env.stdout.flush()
    time.sleep(max(options.delay, 0.0))
    env.stdout.write(" done.\n")
    env.stdout.write("\nHit space to toggle paused, or 's' to step.\n")
    env.stdout.flush()

    def play() -> None:
        if options.wait_for_subscribers:
            env.stdout.write("Waiting for subscribers.\n")
            env.stdout.flush()
            if not player.wait_for_subscribers():
                return
            env.stdout.write("Finished waiting for subscribers.\n")
            env.stdout.flush()
        player.run()

    from rosx.signals import STOP_SIGNALS, handling, soon  # noqa: PLC0415 - signal handling only where it is set up

    worker = threading.Thread(target=play, name="rosx-play", daemon=True)
    with handling(STOP_SIGNALS, lambda signum: soon(player.stop)), _keys(player, env):
        worker.start()
        while worker.is_alive():
            worker.join(0.1)
    env.stdout.write("\nDone.\n")
    env.stdout.flush()
    return ExitStatus.OK


@contextlib.contextmanager
def _keys(player: Player, env: Environment) -> Iterator[None]:
    """Space and ``s`` from a terminal on stdin, read without echo or line buffering."""
    stdin = env.stdin
    if not is_terminal(stdin) or sys.platform == "win32":
        yield
        return
    import select  # noqa: PLC0415 - select is not needed at start-up
    import termios  # noqa: PLC0415 - termios is not needed at start-up
    import tty  # noqa: PLC0415 - tty is not needed at start-up

    fd = stdin.fileno()
    saved = termios.tcgetattr(fd)
    tty.setcbreak(fd)
    done = threading.Event()

    def read_keys() -> None:
        while not done.is_set():
            ready, _, _ = select.select([fd], [], [], 0.1)
            if not ready:
                continue
            # The descriptor, not the text stream: keys typed together must not wait in its buffer.
            for key in os.read(fd, 64).decode(errors="replace"):
                if key == " ":
                    player.toggle_pause()
                elif key == "s":
                    player.step()
                elif key == "t":
                    player.toggle_pause_topics()

    reader = threading.Thread(target=read_keys, name="rosx-play-keys", daemon=True)
    reader.start()
    try:
        yield
    finally:
        done.set()
        reader.join()
        termios.tcsetattr(fd, termios.TCSADRAIN, saved)
