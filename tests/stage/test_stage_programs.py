"""stageros, map_server and map_saver as ``rosx rosrun`` starts them: processes of their own on
the test's master, their log lines, their topics and files, and a clean exit on SIGINT."""

from __future__ import annotations

import contextlib
import re
import signal
import subprocess
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx.packages.crawl import bundled_packages
from rosx_turtle.stage.world.images import parse_pgm
from tests.support.cli import clean_environ, rosx
from tests.support.procs import stop, wait_for
from tests.support.stage_worlds import room

ROSRUN = [sys.executable, "-m", "rosx_commands", "rosrun"]
ARENA = bundled_packages()["turtlebot3_stage"]


def start(args: list[str], master: str, cwd: Path) -> subprocess.Popen[str]:
    """``rosx rosrun ARGS`` on ``master`` (its output a pipe: log lines, no drawing)."""
    return subprocess.Popen(
        [*ROSRUN, *args], env=clean_environ(ROS_MASTER_URI=master), cwd=cwd, text=True,
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True,
    )  # fmt: skip


@contextlib.contextmanager
def stopped_after(process: subprocess.Popen[str]) -> Iterator[None]:
    """Stop ``process`` if the block fails (its test goes on to `interrupted` otherwise)."""
    try:
        yield
    except BaseException:
        stop(process)
        raise


def interrupted(process: subprocess.Popen[str]) -> tuple[int, str]:
    """SIGINT, as Ctrl-C sends it; the exit status and everything printed."""
    process.send_signal(signal.SIGINT)
    try:
        out, _ = process.communicate(timeout=30)
    finally:
        stop(process)
    return process.returncode, out


def test_stageros_runs_headless_publishes_and_stops_on_sigint(
    master: str, make_node: Callable[[str], Node], tmp_path: Path
) -> None:
    (tmp_path / "room.world").write_text(room())
    process = start(["stage_ros", "stageros", "room.world"], master, tmp_path)
    scans: list[Any] = []
    make_node("/probe").subscribe(
        "/base_scan", get_message_class("sensor_msgs/LaserScan"), scans.append
    )
    with stopped_after(process):
        wait_for(lambda: scans, timeout=60, what="a scan")
        assert len(scans[0].ranges) == 181 and scans[0].header.frame_id == "base_laser_link"
    status, out = interrupted(process)
    assert status == 0, out
    assert 'Subscribed to Stage position model "r0"' in out
    assert "Robot r0 provided 1 rangers and 0 cameras" in out
    assert "Traceback" not in out


def test_map_server_serves_and_map_saver_writes_the_same_files(
    master: str, make_node: Callable[[str], Node], tmp_path: Path
) -> None:
    maps = ARENA / "maps"
    probe = make_node("/probe")
    # On simulated time map_server waits for /clock; stageros (an earlier test on this module's
    # master) sets /use_sim_time, as ROS 1's does.
    if probe.params.has("/use_sim_time"):
        probe.params.delete("/use_sim_time")
    server = start(
        ["map_server", "map_server", str(maps / "turtlebot3_world.yaml")], master, tmp_path
    )
    grids: list[Any] = []
    probe.subscribe("/map", get_message_class("nav_msgs/OccupancyGrid"), grids.append)
    with stopped_after(server):
        wait_for(lambda: grids, timeout=60, what="the latched map")
        assert (grids[0].info.width, grids[0].info.height) == (112, 98)
        saver = subprocess.run(
            [*ROSRUN, "map_server", "map_saver", "-f", "saved"],
            env=clean_environ(ROS_MASTER_URI=master),
            cwd=tmp_path, capture_output=True, text=True, timeout=60, check=False,
        )  # fmt: skip
        assert saver.returncode == 0, saver.stdout + saver.stderr
        said = saver.stdout + saver.stderr
        assert "Received a 112 X 98 map @ 0.050 m/pix" in said
        assert "Writing map occupancy data to saved.pgm" in said
        saved = (tmp_path / "saved.pgm").read_bytes()
        assert saved.startswith(b"P5\n# CREATOR: map_saver.cpp 0.050 m/pix\n112 98\n255\n")
        original = (maps / "turtlebot3_world.pgm").read_bytes()
        assert np.array_equal(parse_pgm(saved), parse_pgm(original))
        assert (
            (tmp_path / "saved.yaml")
            .read_text()
            .startswith(
                "image: saved.pgm\nresolution: 0.050000\norigin: [-2.800000, -2.450000, 0.000000]\n"
            )
        )
    status, out = interrupted(server)
    assert status == 0, out
    assert "Read a 112 X 98 map @ 0.050 m/cell" in out


def test_map_server_of_an_image_and_a_resolution_is_the_deprecated_form(
    master: str, make_node: Callable[[str], Node], tmp_path: Path
) -> None:
    """``map_server IMAGE RESOLUTION``: the image at the origin with map_server's thresholds,
    after its warning; its node anonymous, as map_server's ``ros::init`` asks."""
    (tmp_path / "tiny.pgm").write_bytes(b"P5\n2 2\n255\n\x00\xfe\xfe\x00")
    probe = make_node("/probe")
    if probe.params.has("/use_sim_time"):  # set by stageros's test on this module's master
        probe.params.delete("/use_sim_time")
    server = start(["map_server", "map_server", "tiny.pgm", "0.5"], master, tmp_path)
    grids: list[Any] = []
    probe.subscribe("/map", get_message_class("nav_msgs/OccupancyGrid"), grids.append)
    with stopped_after(server):
        wait_for(lambda: grids, timeout=60, what="the latched map")
        info = grids[0].info
        assert (info.width, info.height, info.resolution) == (2, 2, 0.5)
        assert (info.origin.position.x, info.origin.position.y, info.origin.orientation.w) == (
            0,
            0,
            1,
        )
        assert list(grids[0].data) == [0, 100, 100, 0]  # rows from the bottom; black is occupied
        nodes = rosx("rosnode", "list", environ=clean_environ(ROS_MASTER_URI=master)).out.split()
        assert any(re.fullmatch(r"/map_server_\d{19}", name) for name in nodes), nodes
    status, out = interrupted(server)
    assert status == 0, out
    assert re.search(
        r"^\[ WARN\] \[[\d.]+\]: Using deprecated map server interface\. "
        r"Please switch to new interface\.$",
        out,
        re.MULTILINE,
    ), out


def test_map_saver_that_cannot_write_its_file_says_so_and_exits_1(
    master: str, make_node: Callable[[str], Node], tmp_path: Path
) -> None:
    # ROS 1's logs the error and waits for another map, which a latched /map never sends.
    grid_class = get_message_class("nav_msgs/OccupancyGrid")
    grid = grid_class()
    grid.info.width, grid.info.height, grid.info.resolution = 2, 1, 0.05
    grid.data = [0, 100]
    make_node("/map_source").advertise("/map", grid_class, latch=True).publish(grid)
    saver = subprocess.run(
        [*ROSRUN, "map_server", "map_saver", "-f", "maps/lab"], env=clean_environ(ROS_MASTER_URI=master),
        cwd=tmp_path, capture_output=True, text=True, timeout=60, check=False,
    )  # fmt: skip
    assert saver.returncode == 1, saver.stdout + saver.stderr
    assert saver.stderr.rstrip().endswith("]: Couldn't save map file to maps/lab.pgm")
    assert "Traceback" not in saver.stderr
