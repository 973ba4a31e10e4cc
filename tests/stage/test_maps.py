"""map_server's conventions (`rosx_turtle.maps.files`), map_server and map_saver in this process,
and the bundled arena whose world and map are one bitmap."""

from __future__ import annotations

import io
import re
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any, TextIO

import numpy as np
import pytest

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node
from rosx.packages.crawl import PREFIX
from rosx_turtle.console import Console
from rosx_turtle.maps.files import (
    MapFileError,
    MapSpec,
    occupancy,
    parse_map_yaml,
    saved_pgm,
    saved_yaml,
)
from rosx_turtle.maps.saver import save_map
from rosx_turtle.maps.server import MapServerNode, load_map, run_map_server
from rosx_turtle.roscpp import NodeArgs
from rosx_turtle.stage.world.images import format_pgm, parse_pgm
from rosx_turtle.stage.world.load import load_world
from tests.support.procs import wait_for

ARENA = PREFIX / "share" / "turtlebot3_stage"


def test_the_yaml_and_its_errors_in_map_servers_words() -> None:
    spec = parse_map_yaml(
        "image: m.pgm\nresolution: 0.05\norigin: [-1, -2.5, 0.5]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"
    )
    assert spec == MapSpec("m.pgm", 0.05, (-1.0, -2.5, 0.5), False, 0.65, 0.196, "trinary")
    assert (
        parse_map_yaml(
            "image: m.png\nresolution: 1\norigin: [0, 0, 0]\nnegate: 1\noccupied_thresh: 0.6\nfree_thresh: 0.2\nmode: scale\n"
        ).mode
        == "scale"
    )
    for text, message in [
        ("image: m.pgm\n", "The map does not contain a resolution tag or it is invalid."),
        (
            "resolution: 1\nnegate: 0\noccupied_thresh: 0.6\nfree_thresh: 0.2\norigin: [0, 0]\nimage: a\n",
            "The map does not contain an origin tag or it is invalid.",
        ),
        (
            "resolution: 1\nnegate: 0\noccupied_thresh: 0.6\nfree_thresh: 0.2\nmode: fancy\n",
            'Invalid mode tag "fancy".',
        ),
        (
            "resolution: 1\nnegate: 0\noccupied_thresh: 0.6\nfree_thresh: 0.2\norigin: [0, 0, 0]\nimage: ''\n",
            "The image tag cannot be an empty string.",
        ),
    ]:
        with pytest.raises(MapFileError) as error:
            parse_map_yaml(text)
        assert str(error.value) == message


class Captured:
    """An `rosx_turtle.env.Env` whose streams are captured."""

    def __init__(self) -> None:
        self._out, self._err = io.StringIO(), io.StringIO()
        self.stdout: TextIO = self._out
        self.stderr: TextIO = self._err
        self.stdin: TextIO = io.StringIO()
        self.environ: Mapping[str, str] = {"ROS_MASTER_URI": "http://localhost:1/"}

    def printed(self) -> str:
        return self._out.getvalue() + self._err.getvalue()


def _refused(argv: list[str]) -> str:
    """What map_server prints (after its timestamps) refusing ``argv``; it exits 255."""
    env = Captured()
    assert run_map_server(argv, env) == 255
    lines = env.printed().splitlines()
    return "\n".join(re.sub(r"^\[(.....)\] \[[\d.]+\]: ", r"[\1] ", line) for line in lines)


def test_map_server_refuses_a_broken_map_in_its_words(tmp_path: Path) -> None:
    (tmp_path / "bad.yaml").write_text("image: x.pgm\nresolution: [0.05\n")
    assert _refused([str(tmp_path / "bad.yaml")]).startswith(
        "[ERROR] map_server exception: yaml-cpp: error at line 3, column 1: "
    )
    assert "\n" not in _refused([str(tmp_path / "bad.yaml")])
    spec = (
        "resolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.2\n"
    )
    (tmp_path / "text.yaml").write_text(spec + "image: text.yaml\n")
    assert _refused([str(tmp_path / "text.yaml")]) == (
        f'[ INFO] Loading map from image "{tmp_path}/text.yaml"\n'
        f'[ERROR] failed to open image file "{tmp_path}/text.yaml": Unsupported image format'
    )
    (tmp_path / "gone.yaml").write_text(spec + "image: nosuch.pgm\n")
    assert _refused([str(tmp_path / "gone.yaml")]).endswith(
        f'[ERROR] failed to open image file "{tmp_path}/nosuch.pgm": '
        f"Couldn't open {tmp_path}/nosuch.pgm"
    )
    assert _refused([str(tmp_path / "nosuch.yaml")]) == (
        f"[ERROR] Map_server could not open {tmp_path}/nosuch.yaml."
    )
    assert _refused([]).startswith("[ERROR] \nUSAGE: map_server <map.yaml>")


def test_pixels_become_occupancy_as_map_server_reads_them() -> None:
    grey = np.array([[0, 80, 127, 180, 230, 254, 255]], dtype=np.uint8)[:, :, None]
    spec = MapSpec("m", 1.0, (0.0, 0.0, 0.0))
    assert occupancy(grey, spec).tolist() == [[100, 100, -1, -1, 0, 0, 0]]
    scaled = occupancy(grey, MapSpec("m", 1.0, (0.0, 0.0, 0.0), mode="scale"))
    # occ = (255 - v) / 255; between 0.196 and 0.65: 1 + 98 * ratio, truncated.
    assert scaled.tolist() == [
        [
            100,
            100,
            int(1 + 98 * ((128 / 255) - 0.196) / (0.65 - 0.196)),
            int(1 + 98 * ((75 / 255) - 0.196) / (0.65 - 0.196)),
            0,
            0,
            0,
        ]
    ]
    negated = occupancy(grey, MapSpec("m", 1.0, (0.0, 0.0, 0.0), negate=True))
    assert negated.tolist() == [[0, -1, -1, 100, 100, 100, 100]]
    assert occupancy(grey, MapSpec("m", 1.0, (0.0, 0.0, 0.0), mode="raw")).view(
        np.uint8
    ).tolist() == [grey[0, :, 0].tolist()]
    two_rows = np.array([[[0]], [[255]]], dtype=np.uint8).reshape(2, 1, 1)
    assert occupancy(two_rows, spec).tolist() == [[0], [100]]  # the image's last row first


def test_map_saver_writes_what_ros1s_writes() -> None:
    data = np.array([0, 25, 26, 64, 65, 100, -1, 50], dtype=np.int8)
    image = saved_pgm(data, 4, 2, 0.05)
    assert image == b"P5\n# CREATOR: map_saver.cpp 0.050 m/pix\n4 2\n255\n" + bytes(
        [0, 0, 205, 205, 254, 254, 205, 205]
    )
    assert saved_yaml("map.pgm", 0.05, -2.8, -2.45, 0.0) == (
        "image: map.pgm\nresolution: 0.050000\norigin: [-2.800000, -2.450000, 0.000000]\n"
        "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n\n"
    )
    assert parse_pgm(format_pgm(np.array([[1, 2], [3, 4]], dtype=np.uint8))).tolist() == [
        [1, 2],
        [3, 4],
    ]


def test_map_server_latches_and_serves_and_map_saver_writes_it_back(
    master: str, make_node: Callable[..., Node], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = io.StringIO()
    console = Console(out, out, {})
    grid = load_map(ARENA / "maps" / "turtlebot3_world.yaml", console.print)
    server = MapServerNode(
        NodeArgs.parse([], "map_server"), grid, environ={"ROS_MASTER_URI": master}, console=console
    ).start()
    try:
        client = make_node("/probe")
        got: list[Any] = []
        client.subscribe("/map", get_message_class("nav_msgs/OccupancyGrid"), got.append)
        meta: list[Any] = []
        client.subscribe("/map_metadata", get_message_class("nav_msgs/MapMetaData"), meta.append)
        wait_for(lambda: got and meta, what="the latched map")
        grid_msg = got[0]
        assert (grid_msg.header.frame_id, grid_msg.info.width, grid_msg.info.height) == (
            "map",
            112,
            98,
        )
        assert grid_msg.header.seq == 0  # roscpp's first
        assert (meta[0].width, meta[0].height) == (112, 98)
        get_map = get_service_class("nav_msgs/GetMap")
        served = client.service_client("/static_map", get_map).call(
            get_map._request_class(), timeout=10
        )
        assert list(served.map.data) == list(grid_msg.data)
        assert "Read a 112 X 98 map @ 0.050 m/cell" in out.getvalue()
        monkeypatch.chdir(tmp_path)
        assert save_map(grid_msg, "saved", 65, 25, console.print)
        original = parse_pgm((ARENA / "maps" / "turtlebot3_world.pgm").read_bytes())
        assert np.array_equal(parse_pgm((tmp_path / "saved.pgm").read_bytes()), original)
        assert parse_map_yaml((tmp_path / "saved.yaml").read_text()).origin == (-2.8, -2.45, 0.0)
    finally:
        server.shutdown("test over")


def test_map_server_on_simulated_time_stamps_the_map_with_the_first_clock(
    master: str, make_node: Callable[..., Node]
) -> None:
    """As map_server after ``ros::Time::waitForValid()``: under ``/use_sim_time`` it waits for
    ``/clock`` and stamps the map with it, not with 0."""
    clock_node = make_node("/clock_source")
    clock_node.params.set("/use_sim_time", True)
    clock = clock_node.advertise("/clock", get_message_class("rosgraph_msgs/Clock"), queue_size=1)
    quiet = io.StringIO()
    grid = load_map(ARENA / "maps" / "turtlebot3_world.yaml", Console(quiet, quiet, {}).print)
    server = MapServerNode(
        NodeArgs.parse([], "map_server"), grid, environ={"ROS_MASTER_URI": master}, console=None
    ).start()
    try:
        wait_for(lambda: clock.get_num_connections() == 1, what="map_server on /clock")
        assert "/map" not in clock_node.master.published_topics()  # it waits for the time
        tick = get_message_class("rosgraph_msgs/Clock")()
        tick.clock.secs, tick.clock.nsecs = 84, 100_000_000
        clock.publish(tick)
        got: list[Any] = []
        probe = make_node("/probe")
        probe.subscribe("/map", get_message_class("nav_msgs/OccupancyGrid"), got.append)
        wait_for(lambda: got, what="the latched map")
        stamps = (got[0].header.stamp, got[0].info.map_load_time)
        assert [(t.secs, t.nsecs) for t in stamps] == [(84, 100_000_000)] * 2
    finally:
        server.shutdown("test over")
        clock_node.params.delete("/use_sim_time")  # the master is the module's


def test_the_arenas_world_and_map_agree() -> None:
    world, grid = load_world(ARENA / "worlds" / "turtlebot3_world.world")
    assert world.ignored == ()
    spec = parse_map_yaml((ARENA / "maps" / "turtlebot3_world.yaml").read_text())
    data = occupancy(
        parse_pgm((ARENA / "maps" / "turtlebot3_world.pgm").read_bytes())[:, :, None], spec
    )
    rows, cols = np.nonzero(data >= 0)
    x = spec.origin[0] + (cols.astype(np.float64) + 0.5) * spec.resolution
    y = spec.origin[1] + (rows.astype(np.float64) + 0.5) * spec.resolution
    solid = grid.solid_at(x, y)
    agree = solid == (data[rows, cols] == 100)
    assert agree.mean() > 0.97  # the grid is finer (0.02 m): only edge cells may differ
    (burger,) = world.robots
    assert burger.pose[:2] == (-2.0, -0.5)
    assert burger.lasers[0].samples == 360
