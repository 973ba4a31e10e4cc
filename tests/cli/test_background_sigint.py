"""Long-running tools stop on SIGINT even when started with SIGINT ignored.

A POSIX shell starts ``cmd &`` with SIGINT ignored, so ``sh -c 'rosx rostopic echo /t & …;
kill -INT $!'`` leaves a tool that only relies on Python's default handler running forever.
ROS 1's tools install handlers of their own and stop; so must rosx's.
"""

from __future__ import annotations

import signal
import subprocess
from collections.abc import Callable
from pathlib import Path

import pytest

from rosx.transport.client import XmlRpcClient
from rosx.transport.errors import TransportError
from tests.support.cli import ROSX_COMMAND, clean_environ
from tests.support.procs import free_port, stop, wait_for

_RUN = ROSX_COMMAND


def _ignore_sigint() -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _nodes(master: str) -> set[str]:
    client = XmlRpcClient(timeout=2)
    try:
        code, _, state = client.call(master, "getSystemState", "/test")
    except TransportError:
        return set()
    finally:
        client.close()
    return {n for entries in state if code == 1 for _, nodes in entries for n in nodes}


def _registers(prefix: str) -> Callable[[str, subprocess.Popen[str]], bool]:
    """Ready once a node whose name starts with ``prefix`` is on the master."""
    return lambda master, _: any(n.startswith(prefix) for n in _nodes(master))


def _prints(_: str, process: subprocess.Popen[str]) -> bool:
    assert process.stdout is not None
    return bool(process.stdout.readline())


def _waits_for_the_topic(_: str, process: subprocess.Popen[str]) -> bool:
    assert process.stderr is not None
    return "does not appear to be published yet" in process.stderr.readline()


def _ignored_then_interrupted(
    argv: list[str], master: str, ready: Callable[[str, subprocess.Popen[str]], bool]
) -> tuple[int, str]:
    """Start ``rosx ARGV`` with SIGINT ignored, wait for ``ready``, SIGINT it: (status, stderr)."""
    process = subprocess.Popen(
        [*_RUN, *argv],
        env=clean_environ(ROS_MASTER_URI=master),
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        preexec_fn=_ignore_sigint,  # noqa: PLW1509 - the state a shell gives a background job
        start_new_session=True,
    )
    try:
        wait_for(lambda: ready(master, process), what=f"{argv[:2]} to start")
        process.send_signal(signal.SIGINT)
        try:
            _, err = process.communicate(timeout=15)
        except subprocess.TimeoutExpired:
            pytest.fail(f"{argv[:2]} still runs after SIGINT")
    finally:
        stop(process)
    return process.returncode, err


@pytest.mark.parametrize(
    ("argv", "ready"),
    [
        (["rostopic", "echo", "/chatter"], _waits_for_the_topic),
        (["rostopic", "hz", "/chatter"], _waits_for_the_topic),
        (["rostopic", "bw", "/chatter"], _waits_for_the_topic),
        (["rostopic", "pub", "-r", "5", "/chatter", "std_msgs/String", "hi"], _registers("/rostopic_")),
        (["rostopic", "pub", "/chatter", "std_msgs/String", "hi"], _registers("/rostopic_")),
        (["rosnode", "ping", "/pinged"], _prints),
        (["rosrun", "turtlesim", "turtlesim_node"], _registers("/turtlesim")),
    ],
    ids=["echo", "hz", "bw", "pub-rate", "pub-latched", "ping", "turtlesim"],
)  # fmt: skip
def test_a_background_tool_stops_on_sigint(
    master: str, argv: list[str], ready: Callable[[str, subprocess.Popen[str]], bool]
) -> None:
    from rosx.node import Node

    pinged = Node("/pinged", master_uri=master, environ={}).start()
    try:
        status, err = _ignored_then_interrupted(argv, master, ready)
    finally:
        pinged.shutdown("test over")
    assert (status, "Traceback" in err) == (0, False)


def test_a_background_rospy_script_stops_on_sigint(master: str, tmp_path: Path) -> None:
    script = tmp_path / "spinner.py"
    script.write_text("import rospy\nrospy.init_node('spinner')\nrospy.spin()\n")
    status, err = _ignored_then_interrupted(
        ["run-script", str(script)], master, _registers("/spinner")
    )
    assert (status, err) == (0, "")


@pytest.mark.parametrize("tool", ["roscore", "sim"])
def test_a_background_core_stops_on_sigint(tool: str) -> None:
    port = free_port()
    master = f"http://127.0.0.1:{port}/"
    ready = _registers("/rosout" if tool == "roscore" else "/turtlesim")
    status, err = _ignored_then_interrupted([tool, "-p", str(port)], master, ready)
    assert (status, "Traceback" in err) == (0, False)


def test_a_shell_background_job_stops_on_sigint(master: str) -> None:
    run = " ".join(f"'{a}'" for a in [*_RUN, "rostopic", "echo", "/chatter"])
    script = f'{run} & echo $!; read _; kill -INT $!; wait $!; echo "status $?"'
    shell = subprocess.Popen(
        ["sh", "-c", script],
        env=clean_environ(ROS_MASTER_URI=master),
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
        start_new_session=True,
    )
    try:
        assert shell.stdin is not None and shell.stdout is not None
        shell.stdout.readline()
        wait_for(lambda: any(n.startswith("/rostopic_") for n in _nodes(master)), what="echo")
        shell.stdin.write("\n")
        shell.stdin.flush()
        try:
            out, _ = shell.communicate(timeout=15)
        except subprocess.TimeoutExpired:
            pytest.fail("rostopic echo, a background job of sh, still runs after SIGINT")
    finally:
        stop(shell)
    assert out == "status 0\n"
