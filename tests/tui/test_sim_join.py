"""``rosx sim`` (and ``rosx sim --robot``) where a master already runs: it says what runs there
and how to join it, and ``--join`` runs its nodes against that master, starting no core of its
own."""

from __future__ import annotations

import signal
import subprocess
import sys
import threading
from urllib.parse import urlsplit

import pytest

from rosx.master.client import MasterClient
from tests.support.cli import clean_environ, rosx_process
from tests.support.procs import free_port, stop, wait_for

LAB1_NODES = {"/turtlesim", "/teleop_turtle"}
ROBOT_LAB_NODES = {"/stageros", "/map_server", "/map_to_odom", "/teleop_twist_keyboard"}


def registered(uri: str) -> set[str]:
    """Every node that publishes, subscribes or serves on the master at ``uri``."""
    master = MasterClient(uri, "/sim_join_test", timeout=5.0)
    try:
        state = master.system_state()
    finally:
        master.close()
    return {node for section in state for _, nodes in section for node in nodes}


@pytest.mark.parametrize(
    ("lab", "what"), [([], "turtlesim and teleop"), (["--robot"], "the robot lab")]
)
def test_sim_on_a_port_a_master_holds_says_what_runs_there(
    master: str, lab: list[str], what: str
) -> None:
    port = urlsplit(master).port
    assert port is not None
    done = rosx_process("sim", *lab, "--port", str(port), "--headless", ROS_IP="127.0.0.1")
    assert done.status == 1
    command = " ".join(["rosx sim", *lab])
    assert done.err.splitlines() == [
        f"A ROS master is already running at {master}",
        "Nodes there: /rosout",
        f"Run `{command} --join --port {port}` to start {what} against it,",
        f"or `{command} --port PORT` for a master of its own on another port.",
    ]
    assert "RLException" not in done.err and "Traceback" not in done.err


def test_sim_join_without_a_master_says_so() -> None:
    uri = f"http://127.0.0.1:{free_port()}/"
    done = rosx_process("sim", "--join", "--headless", ROS_MASTER_URI=uri)
    assert done.status == 1
    assert done.err.splitlines() == [
        f"ERROR: Unable to communicate with master at {uri}",
        "Start one (rosx roscore), or run rosx sim without --join for its own.",
    ]


@pytest.mark.parametrize(
    ("lab", "nodes"), [([], LAB1_NODES), (["--robot"], ROBOT_LAB_NODES)], ids=["turtle", "robot"]
)
def test_sim_join_registers_its_nodes_on_the_running_master(
    master: str, lab: list[str], nodes: set[str]
) -> None:
    command = [sys.executable, "-m", "rosx_commands", "sim", *lab, "--join", "--headless"]
    sim = subprocess.Popen(
        command,
        env=clean_environ(ROS_MASTER_URI=master, ROS_IP="127.0.0.1"),
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    lines: list[str] = []
    assert sim.stdout is not None
    reader = threading.Thread(target=lambda: lines.extend(sim.stdout or ()), daemon=True)
    reader.start()
    try:
        wait_for(lambda: registered(master) >= nodes, timeout=60, what="the lab's nodes")
        # Started: it says which master it joined.
        wait_for(lambda: f"ROS_MASTER_URI={master}\n" in lines, timeout=60, what="the URI")
        sim.send_signal(signal.SIGINT)
        sim.wait(timeout=30)
        assert sim.stderr is not None
        err = sim.stderr.read()
    finally:
        stop(sim)
    reader.join(timeout=10)
    assert sim.returncode == 0, err
    assert "Traceback" not in err
    # It left the master it joined running, with its own nodes gone.
    wait_for(lambda: not (nodes & registered(master)), timeout=30, what="nodes unregistered")
    assert "/rosout" in registered(master)
