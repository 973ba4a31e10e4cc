"""rosx rviz's speed: frames a second with a map, a laser and tf; CPU when nothing changes; a
1 MiB PointCloud2 at 10 Hz.

rviz itself draws with OpenGL, so there is no ROS 1 figure beside these; they are held against
DESIGN.md's targets (>= 20 frames/s on screen with a 10 Hz 1 081-beam scan, a 4 000 x 4 000
map and 50 frames of tf; <= 15 % of one core when nothing changes; a 1 MiB PointCloud2 at
10 Hz drawn without falling behind). Three parts:

* **draw**: the app, headless, fed by hand: each frame a new scan and all 50 frames moved,
  waited on until the frame is drawn, with the view's cap of 30 frames/s lifted: how many
  frames a second it could draw (the cap then gives what a terminal shows). Also the first
  picture of the map (reducing it for the zoom) and a zoom step (the next reduction).
* **live**: a master and a publisher in other processes (``rosx roscore``; a node publishing
  the latched map, tf for 50 frames at 30 Hz and the scan at 10 Hz), the app in this process on
  a live source, headless at 120x40: frames drawn a second and this process's CPU, then with
  only the latched map and static tf (``idle``): CPU.
* **cloud**: the same with a 1 MiB cloud (65 536 points of x, y, z, rgb) at 10 Hz: clouds
  drawn a second, the lag of the newest one drawn, CPU.

    python bench/bench_rviz.py [--seconds 10] [--python ros1|current|PATH]
"""

from __future__ import annotations

import argparse
import asyncio
import math
import os
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "turtle"), str(ROOT / "commands")]
os.environ.setdefault("TEXTUAL_FPS", "1000")  # textual's own cap on repaints, lifted

from bench import interpreter  # noqa: E402 - after the path is set
from tests.support.procs import free_port  # noqa: E402

MAP_SIDE = 4000
BEAMS = 1081
FRAMES = 50
CLOUD_POINTS = 65536  # x 16 bytes: 1 MiB
CONFIG = """\
Visualization Manager:
  Displays:
    - {Class: rviz/Grid, Name: Grid}
    - {Class: rviz/Map, Name: Map, Topic: /map}
    - {Class: rviz/LaserScan, Name: Scan, Topic: /scan}
    - {Class: rviz/TF, Name: TF, Show Names: false}
    - {Class: rviz/PointCloud2, Name: Cloud, Topic: /cloud}
  Global Options: {Fixed Frame: map}
  Views: {Current: {Class: rviz/TopDownOrtho, Scale: 80}}
"""


# -- the world ---------------------------------------------------------------------------------


def message(type_name: str) -> Any:
    from rosx.msg.codec.classes import get_message_class

    return get_message_class(type_name)()


def occupancy() -> Any:
    """A 4 000 x 4 000 map at 5 cm (200 m a side): rooms of 10 m, unknown outside a disc."""
    import numpy as np

    cells = np.zeros((MAP_SIDE, MAP_SIDE), dtype=np.int8)
    cells[::200, :] = 100
    cells[:, ::200] = 100
    y, x = np.mgrid[0:MAP_SIDE, 0:MAP_SIDE]
    cells[(x - 2000) ** 2 + (y - 2000) ** 2 > 1900**2] = -1
    msg = message("nav_msgs/OccupancyGrid")
    msg.header.frame_id = "map"
    msg.info.width = msg.info.height = MAP_SIDE
    msg.info.resolution = 0.05
    msg.info.origin.position.x = msg.info.origin.position.y = -100.0
    msg.info.origin.orientation.w = 1.0
    msg.data = cells.ravel()
    return msg


def transforms(t: float, stamp: Any) -> list[Any]:
    """base_link moving on a circle in odom, and 49 frames around it (a ring of sensors)."""
    out = []

    def link(parent: str, child: str, x: float, y: float, yaw: float) -> None:
        tf = message("geometry_msgs/TransformStamped")
        tf.header.frame_id, tf.header.stamp, tf.child_frame_id = parent, stamp, child
        tf.transform.translation.x, tf.transform.translation.y = x, y
        tf.transform.rotation.z, tf.transform.rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        out.append(tf)

    link("odom", "base_link", 3 * math.cos(t / 5), 3 * math.sin(t / 5), t / 5 + math.pi / 2)
    link("base_link", "laser", 0.2, 0.0, 0.0)
    for i in range(FRAMES - 3):  # map, odom, base_link, laser and these: 50 frames
        a = i * math.tau / (FRAMES - 3) + t
        link("base_link", f"sensor_{i}", 0.5 * math.cos(a), 0.5 * math.sin(a), a)
    return out


def scan(stamp: Any, t: float) -> Any:
    import numpy as np

    msg = message("sensor_msgs/LaserScan")
    msg.header.frame_id, msg.header.stamp = "laser", stamp
    msg.angle_min, msg.angle_max = -2.356, 2.356
    msg.angle_increment = 4.712 / (BEAMS - 1)
    msg.range_min, msg.range_max = 0.1, 30.0
    msg.ranges = (4.0 + np.sin(np.arange(BEAMS) / 40 + t)).astype(np.float32)
    return msg


def cloud(stamp: Any, t: float) -> Any:
    import numpy as np

    field = message("sensor_msgs/PointField").__class__
    msg = message("sensor_msgs/PointCloud2")
    msg.header.frame_id, msg.header.stamp = "base_link", stamp
    msg.height, msg.width, msg.point_step = 1, CLOUD_POINTS, 16
    msg.row_step = 16 * CLOUD_POINTS
    msg.fields = [field(name=n, offset=4 * i, datatype=7, count=1) for i, n in enumerate("xyz")]
    msg.fields.append(field(name="rgb", offset=12, datatype=7, count=1))
    points = np.zeros((CLOUD_POINTS, 4), dtype=np.float32)
    a = np.linspace(0, 40 * math.pi, CLOUD_POINTS) + t
    points[:, 0], points[:, 1] = np.cos(a) * a / 20, np.sin(a) * a / 20
    points[:, 3] = np.frombuffer(np.full(CLOUD_POINTS, 0x40A0FF, np.uint32).tobytes(), np.float32)
    msg.data = points.tobytes()
    return msg


def publish(master: str, mode: str) -> None:
    """The publisher process: ``scene`` (map, moving tf, scan), ``idle`` (map and static tf),
    ``cloud`` (scene's tf and a 1 MiB cloud)."""
    from rosx.node import Node
    from rosx.node.clock import now
    from rosx.tf.broadcaster import StaticTransformBroadcaster, TransformBroadcaster

    node = Node("/bench_world", master_uri=master, environ={}).start()
    grid = occupancy()
    node.advertise("/map", type(grid), queue_size=1, latch=True).publish(grid)
    odom = message("geometry_msgs/TransformStamped")
    odom.header.frame_id, odom.child_frame_id = "map", "odom"
    odom.transform.rotation.w = 1.0
    statics = StaticTransformBroadcaster(node=node)
    if mode == "idle":
        statics.sendTransform([odom, *transforms(0.0, now())])
        node.wait_for_shutdown()
        return
    statics.sendTransform(odom)
    moving = TransformBroadcaster(node=node)
    scans = node.advertise("/scan", type(scan(now(), 0)), queue_size=2)
    clouds = node.advertise("/cloud", type(cloud(now(), 0)), queue_size=2)
    start = time.monotonic()
    tick = 0
    while not node.is_shutdown():
        t = time.monotonic() - start
        stamp = now()
        moving.sendTransform(transforms(t, stamp))
        if tick % 3 == 0:
            (clouds.publish(cloud(stamp, t)) if mode == "cloud" else scans.publish(scan(stamp, t)))
        tick += 1
        time.sleep(max(0.0, start + tick / 30 - time.monotonic()))


# -- measuring ---------------------------------------------------------------------------------


def spawn(argv: list[str], env: dict[str, str]) -> subprocess.Popen[bytes]:
    return subprocess.Popen(
        [sys.executable, *argv], env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        start_new_session=True,
    )  # fmt: skip


def stop(proc: subprocess.Popen[bytes]) -> None:
    proc.terminate()
    try:
        proc.wait(10)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


def draw_capacity(size: tuple[int, int], frames: int) -> tuple[float, float, float]:
    """Frames/s drawn when fed by hand; seconds of the first map picture and of a zoom step."""
    from rosx.tf.core import BufferCore
    from rosx_commands.rviz import viewport
    from rosx_commands.rviz.app import make_rviz_app
    from rosx_commands.rviz.config import parse_config
    from rosx_commands.rviz.manager import Manager
    from rosx_commands.rviz.pane import RvizSettings
    from rosx_commands.rviz.tools import TOOLS
    from rosx_commands.rviz.view import View
    from rosx_commands.rviz.viewport import Viewport

    capped, viewport.FPS = viewport.FPS, 1e6
    config = parse_config(CONFIG, "bench.rviz")
    core = BufferCore()
    core.set("map", "odom", 0, (0, 0, 0, 0, 0, 0, 1), is_static=True)
    manager = Manager(config, core)

    class Still:
        def start(self, *_: object) -> None: ...
        def sync(self) -> None: ...
        def advertise(self, *_: object) -> None: ...
        def publish(self, *_: object) -> str:
            return ""

        def param(self, name: str) -> None: ...
        def close(self) -> None: ...

    settings = RvizSettings(Path("/nonexistent"), Path("/nonexistent"))
    app = make_rviz_app(config, manager, Still(), View.from_spec(config.view), TOOLS, settings)
    stamp = message("std_msgs/Header").stamp

    def feed(t: float) -> None:
        for tf in transforms(t, stamp):
            r, v = tf.transform.rotation, tf.transform.translation
            core.set(tf.header.frame_id, tf.child_frame_id, int(t * 1e9) + 1,
                     (v.x, v.y, v.z, r.x, r.y, r.z, r.w))  # fmt: skip
        manager.receive(manager.displays[2], scan(stamp, t), t)

    async def run() -> tuple[float, float, float]:
        async with app.run_test(size=size) as pilot:
            view = app.query_one(Viewport)
            feed(0.0)
            grid = occupancy()
            start = time.perf_counter()
            manager.receive(manager.displays[1], grid, 0.0)
            view.redraw()
            first_map = time.perf_counter() - start
            start = time.perf_counter()
            app.view.zoom(-3)  # 1.25³ ≈ 2: the next reduction of the map
            view.redraw()
            zoom = time.perf_counter() - start
            await pilot.pause()
            drawn = view.frames
            start = time.perf_counter()
            for n in range(frames):
                feed(0.05 * (n + 1))
                app.changed()
                while view.frames <= drawn + n:
                    await asyncio.sleep(0)
            return frames / (time.perf_counter() - start), first_map, zoom

    try:
        return asyncio.run(run())
    finally:
        viewport.FPS = capped


def live(mode: str, seconds: float) -> dict[str, float]:
    """Run the publisher in ``mode`` and the app in this process on a live source."""
    from rosx_commands.context import Environment
    from rosx_commands.rviz.config import parse_config
    from rosx_commands.rviz.run import live_app

    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    env = {**os.environ, "ROS_MASTER_URI": uri, "PYTHONPATH": os.pathsep.join(sys.path)}
    core = spawn(["-m", "rosx_commands", "roscore", "-p", str(port)], env)
    world = None
    try:
        time.sleep(1.5)
        world = spawn([__file__, "--publish", mode, "--master", uri], env)
        app = live_app(
            Environment(environ={"ROS_MASTER_URI": uri, "HOME": "/nonexistent"}),
            parse_config(CONFIG, "bench.rviz"),
            None,
            Path("/nonexistent/x.rviz"),
        )

        async def run() -> dict[str, float]:
            async with app.run_test(size=(120, 40)) as pilot:
                manager = app.manager
                scan_or_cloud = manager.displays[4 if mode == "cloud" else 2]
                deadline = time.monotonic() + 60
                while time.monotonic() < deadline and not (
                    manager.displays[1].messages
                    and (mode == "idle" or scan_or_cloud.messages > 3)
                    and len(manager.frames.frames()) >= FRAMES
                ):
                    await asyncio.sleep(0.1)
                await asyncio.sleep(1.0)
                frames0, got0 = app.viewport.frames, scan_or_cloud.messages
                cpu0, wall0 = time.process_time(), time.monotonic()
                await asyncio.sleep(seconds)
                cpu1, wall1 = time.process_time(), time.monotonic()
                lag = 0.0
                clouds = getattr(scan_or_cloud, "clouds", None)
                if clouds:
                    lag = time.time() - clouds[-1].stamp / 1e9
                await pilot.pause()
                wall = wall1 - wall0
                return {
                    "fps": (app.viewport.frames - frames0) / wall,
                    "cpu": (cpu1 - cpu0) / wall,
                    "messages": (scan_or_cloud.messages - got0) / wall,
                    "lag": lag,
                    "map": float(manager.displays[1].messages),
                }

        return asyncio.run(run())
    finally:
        if world is not None:
            stop(world)
        stop(core)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--frames", type=int, default=200)
    parser.add_argument("--publish", help=argparse.SUPPRESS)
    parser.add_argument("--master", help=argparse.SUPPRESS)
    interpreter.add_option(parser)
    args = parser.parse_args()
    if args.publish:
        publish(args.master, args.publish)
        return 0
    interpreter.run_on(args.python)
    print(f"draw: map {MAP_SIDE}x{MAP_SIDE}, {BEAMS}-beam scan and {FRAMES} frames new each frame")
    for size in ((80, 24), (120, 40), (200, 60)):
        fps, first, zoom = draw_capacity(size, args.frames)
        verdict = "ok" if fps >= 20 else "MISSED"
        print(
            f"  {size[0]}x{size[1]}: {fps:.0f} frames/s could be drawn (shown: at most 30); "
            f"first map picture {first * 1000:.0f} ms, a zoom step {zoom * 1000:.0f} ms  {verdict}"
        )
    scene = live("scene", args.seconds)
    print(
        f"live 120x40, tf at 30 Hz, scan at 10 Hz: {scene['fps']:.1f} frames/s on screen "
        f"(target >= 20), {scene['messages']:.1f} scans/s, {scene['cpu'] * 100:.0f} % of a core"
    )
    idle = live("idle", args.seconds)
    print(
        f"live 120x40, latched map and static tf only: {idle['cpu'] * 100:.1f} % of a core "
        f"(target <= 15 %), {idle['fps']:.1f} frames/s"
    )
    clouds = live("cloud", args.seconds)
    print(
        f"live 120x40, 1 MiB PointCloud2 at 10 Hz: {clouds['messages']:.1f} clouds/s received, "
        f"{clouds['fps']:.1f} frames/s, newest drawn {clouds['lag'] * 1000:.0f} ms old, "
        f"{clouds['cpu'] * 100:.0f} % of a core"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
