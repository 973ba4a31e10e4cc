"""``map_server MAP.yaml``: the map latched on ``map`` and ``map_metadata``, and the
``static_map`` service (nav_msgs/GetMap), as map_server serves them; ``~frame_id`` ("map").
The map is stamped with ROS time when it is loaded: under ``/use_sim_time`` map_server waits for
the first ``/clock``, as roscpp's ``ros::Time::waitForValid``."""

from __future__ import annotations

import math
import threading
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.names.anonymous import roscpp_anonymous_name
from rosx.node import ERROR, INFO, WARN
from rosx.node.simtime import follow_sim_time
from rosx_turtle import roscpp
from rosx_turtle.console import Console, NodeLog
from rosx_turtle.env import ProcessEnv
from rosx_turtle.maps.files import MapFileError, MapSpec, occupancy, parse_map_yaml
from rosx_turtle.program import master_address, run_until_stopped
from rosx_turtle.roscpp import NodeArgs, atof

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

    from rosx.node import Node
    from rosx_turtle.env import Env

USAGE = (
    "\nUSAGE: map_server <map.yaml>\n"
    "  map.yaml: map description file\n"
    "DEPRECATED USAGE: map_server <map> <resolution>\n"
    "  map: image file to load\n"
    "  resolution: map resolution [meters/pixel]"
)


def load_map(path: Path, log: Any, deprecated: MapSpec | None = None) -> Any:
    """The nav_msgs/OccupancyGrid of the map described at ``path``; None after logging why not.
    With ``deprecated`` (``map_server IMAGE RESOLUTION``), ``path`` is the image itself."""
    from rosx_turtle.stage.world.images import ImageError, read_channels  # noqa: PLC0415 - turtlesim's parts load only when used

    if deprecated is None:
        try:
            text = path.read_text(encoding="utf-8")
        except OSError:
            log(ERROR, f"Map_server could not open {path}.")
            return None
        try:
            spec = parse_map_yaml(text)
        except MapFileError as exc:
            log(ERROR, str(exc))
            return None
        image = Path(spec.image) if spec.image.startswith("/") else path.parent / spec.image
    else:
        spec, image = deprecated, path
    log(INFO, f'Loading map from image "{image}"')
    try:
        pixels = read_channels(image)
    except ImageError as exc:
        # SDL_image's words, which map_server reads its images with.
        why = f"Couldn't open {image}" if exc.missing else "Unsupported image format"
        log(ERROR, f'failed to open image file "{image}": {why}')
        return None
    grid = get_message_class("nav_msgs/OccupancyGrid")()
    info = grid.info
    info.height, info.width = pixels.shape[:2]
    info.resolution = spec.resolution
    info.origin.position.x, info.origin.position.y = spec.origin[0], spec.origin[1]
    info.origin.orientation.z = math.sin(spec.origin[2] / 2)
    info.origin.orientation.w = math.cos(spec.origin[2] / 2)
    grid.data = occupancy(pixels, spec).ravel()
    log(INFO, f"Read a {info.width} X {info.height} map @ {spec.resolution:.3f} m/cell")
    return grid


class MapServerNode:
    """map_server as a library object: `start` publishes and serves the map."""

    def __init__(
        self, args: NodeArgs, grid: Any, *, environ: Mapping[str, str], console: Console | None
    ) -> None:
        self.args = args
        self.grid = grid
        self.node: Node = args.make_node(environ)
        self._log = NodeLog(self.node, console, logger="ros.map_server")

    def start(self) -> MapServerNode:
        """Register, then latch ``map`` and ``map_metadata`` and serve ``static_map``: at once
        on the wall clock; under ``/use_sim_time`` once the first ``/clock`` has come (a
        thread waits for it, as map_server's ``ros::Time::waitForValid()`` does, until the node
        shuts down)."""
        node = self.node
        node.start()
        self.args.set_private_params(node)
        frame = node.params.get("~frame_id", "map")
        if not follow_sim_time(node):
            self._serve_map(frame)
            return self
        threading.Thread(target=self._serve_in_time, args=(frame,), daemon=True).start()
        return self

    def _serve_in_time(self, frame: object) -> None:
        node = self.node
        if not node.clock.wait_for_valid(shutdown=node.shutdown_event):
            return
        try:
            self._serve_map(frame)
        except Exception:
            if not node.is_shutdown():  # shut down while it advertised: nothing to serve
                raise

    def _serve_map(self, frame: object) -> None:
        node = self.node
        stamp = node.clock.now()
        grid = self.grid
        grid.header.frame_id = frame if isinstance(frame, str) else "map"
        grid.header.stamp = stamp
        grid.info.map_load_time = stamp
        roscpp.advertise_service(
            node, "static_map", get_service_class("nav_msgs/GetMap"), self._serve, self._log
        )
        metadata = node.advertise(
            "map_metadata", get_message_class("nav_msgs/MapMetaData"), queue_size=1, latch=True
        )
        metadata.publish(grid.info)
        node.advertise(
            "map", get_message_class("nav_msgs/OccupancyGrid"), queue_size=1, latch=True
        ).publish(grid)

    def _serve(self, request: Any) -> object:
        self._log(INFO, "Sending map")
        return {"map": self.grid}

    def shutdown(self, reason: str = "") -> None:
        """Leave the ROS graph."""
        self.node.shutdown(reason)

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """Block until the node shuts down; False if ``timeout`` passed first."""
        return self.node.wait_for_shutdown(timeout)


def _deprecated_spec(words: Sequence[str], params: Mapping[str, Any]) -> MapSpec:
    """``map_server IMAGE RESOLUTION``: the image at the origin, its thresholds and ``negate``
    from the private parameters given on the command line (``_negate:=1``), else
    map_server's defaults."""

    def number(name: str, default: float) -> float:
        value = params.get(name, default)
        return float(value) if isinstance(value, (int, float)) else default

    return MapSpec(
        words[0],
        atof(words[1]),
        (0.0, 0.0, 0.0),
        bool(number("negate", 0)),
        number("occupied_thresh", 0.65),
        number("free_thresh", 0.196),
    )


def run_map_server(argv: Sequence[str], env: Env | None = None) -> int:
    """Run map_server until a signal or a shutdown; the exit status (255 as ``exit(-1)``)."""
    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, roscpp_anonymous_name("map_server"))
    console = Console(env.stdout, env.stderr, env.environ)
    words = list(args.argv)
    if len(words) not in (1, 2):
        console.print(ERROR, USAGE)
        return 255
    deprecated = None
    if len(words) == 2:
        console.print(
            WARN, "Using deprecated map server interface. Please switch to new interface."
        )
        deprecated = _deprecated_spec(words, args.params)
    grid = load_map(Path(words[0]), console.print, deprecated)
    if grid is None:
        return 255

    def start() -> MapServerNode:
        return MapServerNode(args, grid, environ=env.environ, console=console).start()

    return run_until_stopped(start, console, master_address(args.master_uri, env.environ))
