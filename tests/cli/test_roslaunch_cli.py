"""``rosx roslaunch``'s command line: ROS 1's ``-h``, usage errors and refusals, exit codes."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.support.cli import clean_environ, rosx
from tests.support.procs import free_port
from tests.support.ros1 import needs_ros1, run_ros1

USAGE = """\
Usage: roslaunch [options] [package] <filename> [arg_name:=value...]
       roslaunch [options] <filename> [<filename>...] [arg_name:=value...]

If <filename> is a single dash ('-'), launch XML is read from standard input.
"""

HELP_HEAD = (
    USAGE
    + """
Options:
  -h, --help            show this help message and exit
  --files               Print list files loaded by launch file, including
                        launch file itself
  --args=NODE_NAME      Print command-line arguments for node
  --nodes               Print list of node names in launch file
"""
)


def test_help_is_roslaunchs() -> None:
    result = rosx("roslaunch", "-h")
    assert result.status == 0
    assert result.out.startswith(HELP_HEAD)
    assert "  --sigterm-timeout=SIGTERM_TIMEOUT\n" in result.out
    assert result.err == ""


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        ([], "you must specify at least one input file"),
        (["--bogus"], "no such option: --bogus"),
        (["-c", "x"], "--child option requires --server_uri to be set as well"),
        (["--core", "--wait"], "--wait cannot be used with roscore"),
        (["--core", "--run_id", "x"], "--run_id should only be set for child roslaunches (-c)"),
    ],
)
def test_usage_errors_are_roslaunchs(argv: list[str], message: str) -> None:
    result = rosx("roslaunch", *argv)
    assert result.status == 2
    assert result.out == ""
    assert result.err == f"{USAGE}\nroslaunch: error: {message}\n"


def test_two_printing_options_are_refused(tmp_path: Path) -> None:
    launch = tmp_path / "a.launch"
    launch.write_text("<launch/>\n")
    result = rosx("roslaunch", "--nodes", "--args", "x", str(launch))
    assert result.status == 2
    assert result.err.endswith(
        "roslaunch: error: only one of [--nodes, --find-node, --args --ros-args] may be specified\n"
    )


def test_a_file_that_is_not_there_is_roslaunchs_error(tmp_path: Path) -> None:
    environ = clean_environ(ROS_PACKAGE_PATH=str(tmp_path))
    result = rosx("roslaunch", "nofile.launch", environ=environ)
    assert (result.status, result.out) == (1, "")
    assert result.err == "RLException: [nofile.launch] is not a launch file name\n"


@pytest.mark.parametrize(
    ("text", "error"),
    [
        (
            '<launch>\n  <node pkg="a" type="b" name="c">\n</launch>\n',
            "3: Invalid roslaunch XML syntax: mismatched tag: line 3, column 2",
        ),
        (
            '<launch>\n  <node pkg="a" type="b" name="t"/>\n  <node pkg="a" type="b" name="t"/>\n'
            "</launch>\n",
            "3: <node>: roslaunch file contains multiple nodes named [/t]. Please check all "
            "<node> 'name' attributes to make sure they are unique. Also check that $(anon id) "
            "use different ids.",
        ),
        (
            '<launch>\n  <param name="x" value="$(foo bar)"/>\n</launch>\n',
            "2: <param>: Unknown substitution command [foo bar]. Valid commands are "
            "['find', 'env', 'optenv', 'dirname', 'anon', 'arg']",
        ),
        (
            '<launch>\n  <param name="x" type="int" value="abc"/>\n</launch>\n',
            "2: <param>: Invalid <param> tag: invalid literal for int() with base 10: 'abc'.",
        ),
    ],
    ids=["bad-xml", "duplicate-node", "bad-substitution", "bad-int"],
)
def test_a_launch_file_with_a_mistake_is_reported_after_the_log_opens(
    tmp_path: Path, text: str, error: str
) -> None:
    launch = tmp_path / "bad.launch"
    _reported_after_the_log_opens(tmp_path, launch, text, f"RLException: {launch}:{error}")


def test_a_package_find_does_not_find_is_reported_as_rospkgs_error(tmp_path: Path) -> None:
    """roslaunch lets rospkg's ResourceNotFound through: ``Resource not found: PACKAGE`` and
    the package path searched (rosx names the file, line and tag before the package)."""
    workspace = tmp_path / "ws"
    workspace.mkdir()
    launch = tmp_path / "find.launch"
    _reported_after_the_log_opens(
        tmp_path,
        launch,
        '<launch>\n  <include file="$(find no_such_pkg)/a.launch"/>\n</launch>\n',
        f"Resource not found: {launch}:2: <include>: no_such_pkg\nROS path [0]={workspace}",
        ROS_PACKAGE_PATH=str(workspace),
    )


def _reported_after_the_log_opens(
    tmp_path: Path, launch: Path, text: str, message: str, **extra: str
) -> None:
    """``roslaunch LAUNCH`` (of ``text``) prints roslaunch's log lines, then ``message`` and
    that the traceback is in the log, which holds both; status 1."""
    launch.write_text(text)
    home = tmp_path / "home"
    environ = clean_environ(
        ROS_HOME=str(home), ROS_MASTER_URI=f"http://localhost:{free_port()}", **extra
    )
    result = rosx("roslaunch", str(launch), environ=environ)
    log = next((home / "log" / "latest").glob("roslaunch-*.log"))
    assert result.status == 1
    assert result.out == (
        f"... logging to {log.resolve()}\n"
        "Checking log directory for disk usage. This may take a while.\n"
        "Press Ctrl-C to interrupt\n"
        "Done checking log file disk usage. Usage is <1GB.\n"
    )
    assert result.err == f"{message}\nThe traceback for the exception was written to the log file\n"
    logged = log.read_text()
    assert f": {message}\n" in logged
    assert "Traceback (most recent call last):" in logged


def test_bad_timeouts_are_refused_before_anything_starts() -> None:
    result = rosx("roslaunch", "--sigint-timeout", "0", "x.launch")
    assert result.status == 1
    assert result.err == (
        "RLException: sigint_timeout must be a positive number, received 0.000000\n"
    )


def test_child_mode_is_refused_clearly() -> None:
    result = rosx("roslaunch", "-c", "x", "-u", "http://h:1/", "--run_id", "r")
    assert result.status == 1
    assert result.err.startswith("RLException: rosx roslaunch does not run as a child")


@needs_ros1
def test_help_matches_debian_roslaunch() -> None:
    assert rosx("roslaunch", "-h").out == run_ros1(["/usr/bin/roslaunch", "-h"]).stdout


def test_turtlesims_multisim_launch_comes_with_rosx() -> None:
    result = rosx("roslaunch", "--nodes", "turtlesim", "multisim.launch", environ=clean_environ())
    assert (result.status, result.out, result.err) == (0, "/turtlesim1/sim\n/turtlesim2/sim\n", "")
    environ = clean_environ(ROS_MASTER_URI="http://localhost:11311")
    args = rosx(
        "roslaunch", "--args", "/turtlesim2/sim", "turtlesim", "multisim.launch", environ=environ
    )
    assert args.status == 0
    assert args.out.startswith('ROS_NAMESPACE="/turtlesim2" ')
    assert args.out.endswith("/lib/turtlesim/turtlesim_node __name:=sim\n")  # as Noetic's
