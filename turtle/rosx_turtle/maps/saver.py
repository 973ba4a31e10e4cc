"""``map_saver [--occ N] [--free N] [-f NAME]``: the first map on ``map`` written as map_saver
writes it (``NAME.pgm`` and ``NAME.yaml``), then exit.

A file it cannot write gets map_saver's error, then exit status 1: ROS 1's logs the error and
waits for another map, which a latched ``/map`` never sends, so it hangs until Ctrl-C (a
folder that does not exist yet, ``-f ~/maps/lab``, is the usual cause)."""

from __future__ import annotations

import math
import threading
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class
from rosx.node import ERROR, INFO
from rosx.signals import stop_on_signals
from rosx_turtle.console import Console, NodeLog
from rosx_turtle.env import ProcessEnv
from rosx_turtle.maps.files import saved_pgm, saved_yaml
from rosx_turtle.program import master_address, start_when_master_is_up
from rosx_turtle.roscpp import NodeArgs

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx_turtle.env import Env

USAGE = (
    "Usage: \n  map_saver -h\n"
    "  map_saver [--occ <threshold_occupied>] [--free <threshold_free>] [-f <mapname>]"
    " [ROS remapping args]"
)


def _parse(words: list[str], console: Console, out: Any) -> tuple[str, int, int] | int:
    name, occupied, free = "map", 65, 25
    i = 0
    while i < len(words):
        word = words[i]
        if word == "-h":
            print(USAGE, file=out)
            return 0
        if word not in ("-f", "--occ", "--free") or i + 1 >= len(words):
            print(USAGE, file=out)
            return 1
        value = words[i + 1]
        i += 2
        if word == "-f":
            name = value
            continue
        number = int(value) if value.lstrip("+-").isdigit() else 0
        if word == "--occ":
            if not 1 <= number <= 100:
                console.print(ERROR, "threshold_occupied must be between 1 and 100")
                return 1
            occupied = number
        else:
            if not 0 <= number <= 100:
                console.print(ERROR, "threshold_free must be between 0 and 100")
                return 1
            free = number
    if occupied <= free:
        console.print(ERROR, "threshold_free must be smaller than threshold_occupied")
        return 1
    return name, occupied, free


def save_map(grid: Any, name: str, occupied: int, free: int, log: Any) -> bool:
    """Write ``grid`` as ``name.pgm`` and ``name.yaml``; False after logging a failure."""
    info = grid.info
    import numpy as np  # numpy only on this path

    log(INFO, f"Received a {info.width} X {info.height} map @ {info.resolution:.3f} m/pix")
    image = f"{name}.pgm"
    log(INFO, f"Writing map occupancy data to {image}")
    data = np.asarray(grid.data, dtype=np.int8)
    try:
        Path(image).write_bytes(
            saved_pgm(data, info.width, info.height, info.resolution, occupied, free)
        )
    except OSError:
        log(ERROR, f"Couldn't save map file to {image}")
        return False
    yaml = f"{name}.yaml"
    log(INFO, f"Writing map occupancy data to {yaml}")
    q = info.origin.orientation
    yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
    try:
        Path(yaml).write_text(
            saved_yaml(image, info.resolution, info.origin.position.x, info.origin.position.y, yaw)
        )
    except OSError:
        log(ERROR, f"Couldn't save map file to {yaml}")
        return False
    log(INFO, "Done\n")
    return True


class _Saver:
    def __init__(
        self, args: NodeArgs, env: Env, console: Console, name: str, occupied: int, free: int
    ) -> None:
        self.node = args.make_node(env.environ)
        self.log = NodeLog(self.node, console, logger="ros.map_server")
        self.done = threading.Event()
        self.failed = False
        self.target = (name, occupied, free)

    def start(self) -> _Saver:
        self.node.start()
        self.log(INFO, "Waiting for the map")
        self.node.subscribe(
            "map", get_message_class("nav_msgs/OccupancyGrid"), self._on_map, queue_size=1
        )
        return self

    def _on_map(self, grid: Any) -> None:
        if not self.done.is_set():
            self.failed = not save_map(grid, *self.target, self.log)
            self.done.set()

    def shutdown(self, reason: str = "") -> None:
        self.node.shutdown(reason)

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        return self.node.wait_for_shutdown(timeout)


def run_map_saver(argv: Sequence[str], env: Env | None = None) -> int:
    """Run map_saver: wait for one map, save it, exit 0 (or on a signal); 1 when it cannot."""
    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, "map_saver")
    console = Console(env.stdout, env.stderr, env.environ)
    parsed = _parse(list(args.argv), console, env.stdout)
    if isinstance(parsed, int):
        return parsed
    address = master_address(args.master_uri, env.environ)
    with stop_on_signals() as stop:
        saver = start_when_master_is_up(
            lambda: _Saver(args, env, console, *parsed).start(), console, address, stop
        )
        if saver is None:
            return 0
        try:
            while not stop.is_set() and not saver.done.wait(0.1):
                if saver.wait_for_shutdown(0):
                    break
        finally:
            saver.shutdown("map saved" if saver.done.is_set() else "signal")
    return 1 if saver.failed else 0
