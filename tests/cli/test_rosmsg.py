"""rosx rosmsg / rossrv: golden text, exit codes, and ROS 1's output for every shared type."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rosx.packages.crawl import bundled_packages
from tests.support.cli import clean_environ, rosx, rosx_process
from tests.support.ros1 import needs_ros1, ros1_python, run_ros1

TWIST = """\
geometry_msgs/Vector3 linear
  float64 x
  float64 y
  float64 z
geometry_msgs/Vector3 angular
  float64 x
  float64 y
  float64 z

"""


def test_show_expands_nested_types() -> None:
    result = rosx("rosmsg", "show", "geometry_msgs/Twist")
    assert (result.status, result.out, result.err) == (0, TWIST, "")


def test_show_bare_name_searches_every_package() -> None:
    result = rosx("rosmsg", "show", "Twist")
    assert result.out == "[geometry_msgs/Twist]:\n" + TWIST


def test_info_is_show() -> None:
    assert rosx("rosmsg", "info", "geometry_msgs/Twist").out == TWIST


def test_show_reads_the_type_from_stdin() -> None:
    assert rosx("rosmsg", "show", stdin="geometry_msgs/Twist\n").out == TWIST


def test_constants_come_first_as_written() -> None:
    out = rosx("rosmsg", "show", "sensor_msgs/NavSatStatus").out
    assert out.splitlines()[:3] == [
        "int8 STATUS_NO_FIX=-1",
        "int8 STATUS_FIX=0",
        "int8 STATUS_SBAS_FIX=1",
    ]
    assert out.endswith("int8 status\nuint16 service\n\n")


def test_turtlesim_pose() -> None:
    out = rosx("rosmsg", "show", "turtlesim/Pose").out
    assert (
        out
        == "float32 x\nfloat32 y\nfloat32 theta\nfloat32 linear_velocity\nfloat32 angular_velocity\n\n"
    )


def test_header_and_arrays() -> None:
    out = rosx("rosmsg", "show", "sensor_msgs/Image").out
    assert out.startswith(
        "std_msgs/Header header\n  uint32 seq\n  time stamp\n  string frame_id\nuint32 height\n"
    )
    assert "uint8[] data\n" in out
    polygon = rosx("rosmsg", "show", "geometry_msgs/Polygon").out
    assert polygon == "geometry_msgs/Point32[] points\n  float32 x\n  float32 y\n  float32 z\n\n"


def test_raw_shows_the_definition_text() -> None:
    out = rosx("rosmsg", "show", "-r", "turtlesim/Color").out
    assert out == "uint8 r\nuint8 g\nuint8 b\n\n"


def test_md5() -> None:
    assert rosx("rosmsg", "md5", "geometry_msgs/Twist").out == "9f195f881246fdfa2798d1d3eebca84a\n"
    assert (
        rosx("rosmsg", "md5", "Twist").out
        == "[geometry_msgs/Twist]: 9f195f881246fdfa2798d1d3eebca84a\n"
    )
    assert rosx("rossrv", "md5", "turtlesim/Spawn").out == "0b2d2e872a8e2887d5ed626f2bf2c561\n"


def test_md5_of_unknown_types_reports_on_stderr_and_exits_zero() -> None:
    result = rosx("rosmsg", "md5", "foo/Bar")
    assert (result.status, result.out, result.err) == (0, "", "Cannot locate [foo/Bar]\n")
    result = rosx("rosmsg", "md5", "Bar")
    assert (result.status, result.err) == (0, "No messages matching the name [Bar]\n")


def test_rossrv_show() -> None:
    spawn = "float32 x\nfloat32 y\nfloat32 theta\nstring name\n---\nstring name\n\n"
    assert rosx("rossrv", "show", "turtlesim/Spawn").out == spawn
    assert rosx("rossrv", "show", "Spawn").out == "[turtlesim/Spawn]:\n" + spawn
    assert rosx("rossrv", "show", "std_srvs/Empty").out == "---\n\n"


def test_rossrv_show_nested_with_constants() -> None:
    out = rosx("rossrv", "show", "nav_msgs/LoadMap").out
    lines = out.splitlines()
    assert lines[:3] == ["string map_url", "---", "uint8 RESULT_SUCCESS=0"]
    assert "      geometry_msgs/Point position" in lines
    assert lines[-2:] == ["uint8 result", ""]


def test_list_and_packages() -> None:
    listing = rosx("rosmsg", "list").out.splitlines()
    assert listing == sorted(listing)
    assert {"geometry_msgs/Twist", "turtlesim/Pose", "std_msgs/String", "rosgraph_msgs/Log"} <= set(
        listing
    )
    services = rosx("rossrv", "list").out.splitlines()
    assert {"std_srvs/Empty", "turtlesim/Spawn", "roscpp/GetLoggers", "nav_msgs/GetMap"} <= set(
        services
    )
    assert rosx("rosmsg", "package", "-s", "turtlesim").out == "turtlesim/Color turtlesim/Pose\n"
    assert rosx("rossrv", "package", "turtlesim").out.splitlines() == [
        "turtlesim/Kill",
        "turtlesim/SetPen",
        "turtlesim/Spawn",
        "turtlesim/TeleportAbsolute",
        "turtlesim/TeleportRelative",
    ]
    assert "turtlesim" in rosx("rosmsg", "packages").out.splitlines()
    assert "std_srvs" in rosx("rossrv", "packages", "-s").out.split()


def test_unknown_message_errors() -> None:
    result = rosx("rosmsg", "show", "std_msgs/Nope")
    assert result.status == 1
    assert result.err.startswith(
        "Unable to load msg [std_msgs/Nope]: Cannot locate message [Nope] in package [std_msgs]"
    )
    result = rosx("rosmsg", "show", "nopkg/Nope")
    assert result.status == 1
    assert result.err.startswith(
        "Unable to load msg [nopkg/Nope]: Cannot locate message [Nope]: unknown package [nopkg]"
    )
    result = rosx("rosmsg", "show", "Nope")
    assert (result.status, result.err) == (1, "Could not find msg 'Nope'\n")
    result = rosx("rossrv", "show", "turtlesim/Nope")
    assert result.status == 1
    assert result.err.startswith(
        "Unknown srv type [turtlesim/Nope]: Cannot locate message [Nope] in package [turtlesim]"
    )


def test_a_name_with_two_slashes_is_genmsgs_invalid_name() -> None:
    """ROS 1 refuses ``a/b/c`` before it looks for a package ``a``."""
    for tool, prefix in (("rosmsg", "Unable to load msg"), ("rossrv", "Unknown srv type")):
        for name in ("a/b/c", "/std_msgs/String"):
            for command in ("show", "info"):
                result = rosx(tool, command, name)
                expected = f"{prefix} [{name}]: invalid name [{name}]\n"
                assert (result.status, result.out, result.err) == (1, "", expected)
        result = rosx(tool, "md5", "a/b/c")
        expected = "Invalid type: 'invalid name [a/b/c]'\n"
        assert (result.status, result.out, result.err) == (64, "", expected)
    result = rosx("rosmsg", "md5", "/Twist")
    expected = "Invalid type: 'message type is missing package name: /Twist'\n"
    assert (result.status, result.out, result.err) == (64, "", expected)


def test_an_unknown_package_names_every_package_of_the_search_path(tmp_path: Path) -> None:
    """As ROS 1: each package rospack finds, with its ``msg`` folders, the package path's
    first (a workspace's ``std_msgs`` over rosx's own)."""
    overlay = tmp_path / "std_msgs"
    overlay.mkdir()
    (overlay / "package.xml").write_text(
        '<package format="2"><name>std_msgs</name><version>0.5.13</version>'
        "<description>d</description><maintainer email='m@example.com'>m</maintainer>"
        "<license>BSD</license></package>"
    )
    environ = clean_environ(ROS_PACKAGE_PATH=str(tmp_path))
    for tool, kind, prefix in (
        ("rosmsg", "msg", "Unable to load msg"),
        ("rossrv", "srv", "Unknown srv type"),
    ):
        search_path = {name: [f"{folder}/{kind}"] for name, folder in bundled_packages().items()}
        search_path["std_msgs"].insert(0, f"{overlay}/{kind}")
        result = rosx(tool, "show", "/Twist", environ=environ)
        expected = (
            f"{prefix} [/Twist]: Cannot locate message [Twist]: unknown package [] "
            f"on search path [{search_path!r}]\n"
        )
        assert (result.status, result.out, result.err) == (1, "", expected)
        result = rosx(tool, "show", "std_msgs/Nope", environ=environ)
        assert result.err == (
            f"{prefix} [std_msgs/Nope]: Cannot locate message [Nope] in package [std_msgs] "
            f"with paths [{search_path['std_msgs']!r}]\n"
        )


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (
            ["show", "std_msgs::String"],
            "rosmsg does not understand C++-style namespaces (i.e. '::').\n"
            "Please refer to msg/srv types as 'package_name/Type'.",
        ),
        (
            ["show", "std_msgs.String"],
            "invalid message type 'std_msgs.String'.\n"
            "Please refer to msg/srv types as 'package_name/Type'.",
        ),
        (["show", "a/B", "c/D"], "you may only specify one message type"),
        (["show", "-x"], "no such option: -x"),
    ],
)
def test_malformed_arguments_are_usage_errors(argv: list[str], message: str) -> None:
    result = rosx("rosmsg", *argv)
    assert result.status == 2
    assert (
        result.err == f"Usage: rosmsg show [options] <message type>\n\nrosmsg: error: {message}\n"
    )


def test_unknown_package_exits_64() -> None:
    result = rosx("rosmsg", "package", "nopkg")
    assert (result.status, result.err) == (64, "Invalid package: nopkg\n")


def test_overview_without_and_with_a_wrong_command() -> None:
    result = rosx("rosmsg")
    assert result.status == 0
    assert result.out.startswith(
        "rosmsg is a command-line tool for displaying information about ROS Message types.\n\nCommands:\n\trosmsg show\tShow message description\n"
    )
    assert result.out.endswith("\nType rosmsg <command> -h for more detailed usage\n\n")
    assert rosx("rosmsg", "nope").status == 64
    assert rosx("rossrv").out.startswith(
        "rossrv is a command-line tool for displaying information about ROS Service types."
    )


def test_user_packages_on_the_package_path(tmp_path: object) -> None:
    from pathlib import Path

    root = Path(str(tmp_path)) / "src" / "lab2"
    (root / "msg").mkdir(parents=True)
    (root / "package.xml").write_text("<package><name>lab2</name></package>")
    (root / "msg" / "Goal.msg").write_text("# where to go\nHeader header\nPoint target  # nope\n")
    environ = {"ROS_PACKAGE_PATH": str(root.parent)}
    result = rosx("rosmsg", "show", "-r", "lab2/Goal", environ=environ)
    assert result.out == "# where to go\nHeader header\nPoint target  # nope\n\n"
    result = rosx("rosmsg", "show", "lab2/Goal", environ=environ)
    assert result.status == 1
    assert result.err.startswith(
        "Unable to load msg [lab2/Goal]: Cannot locate message [Point] in package [lab2]"
    )


def test_console_script_prints_no_traceback() -> None:
    result = rosx_process("rosmsg", "show", "nopkg/Nope")
    assert result.status == 1
    assert "Traceback" not in result.err
    assert result.err.count("\n") == 1


def test_version_and_help() -> None:
    import rosx as core

    assert rosx_process("--version").out == f"rosx {core.__version__}\n"
    help_text = rosx_process("--help").out
    assert "rosmsg" in help_text and "rossrv" in help_text


# -- against ROS 1 -------------------------------------------------------------------------

_ROS1_TEXTS = """
import json, rosmsg, rospkg
rp = rospkg.RosPack()
out = {"msg": {}, "srv": {}, "md5": {}, "raw_msg": {}, "raw_srv": {}}
for kind, lister, getter in (("msg", rosmsg.list_msgs, rosmsg.get_msg_text), ("srv", rosmsg.list_srvs, rosmsg.get_srv_text)):
    for pkg in sorted(set(rosmsg.iterate_packages(rp, rosmsg.MODE_MSG if kind == "msg" else rosmsg.MODE_SRV))):
        for t in lister(pkg[0], rp):
            out[kind][t] = getter(t, rospack=rp)
            out["raw_" + kind][t] = getter(t, raw=True, rospack=rp)
            out["md5"][kind + ":" + t] = rosmsg.rosmsg_md5(rosmsg.MODE_MSG if kind == "msg" else rosmsg.MODE_SRV, t)
print(json.dumps(out))
"""


#: ROS 1's rosmsg/rossrv output for every type it knows (``show`` and ``show -r`` texts, md5
#: sums), recorded from the reference with `_ROS1_TEXTS`; the live test below keeps it honest.
GOLDEN = Path(__file__).resolve().parent.parent / "golden" / "ros1_rosmsg.json"


def _compare_with(ros1: dict[str, dict[str, str]]) -> None:
    assert len(ros1["msg"]) > 100 and len(ros1["srv"]) > 10
    for kind in ("msg", "srv"):
        for type_name, text in ros1[kind].items():
            ours = rosx("ros" + kind, "show", type_name)
            assert ours.status == 0, (type_name, ours.err)
            assert ours.out == text + "\n", type_name
            md5 = rosx("ros" + kind, "md5", type_name).out
            assert md5 == ros1["md5"][f"{kind}:{type_name}"] + "\n", type_name
        for type_name, text in ros1["raw_" + kind].items():
            if type_name.startswith("turtlesim/"):
                continue  # the reference's turtlesim files are field lists: rosx ships Noetic's
            raw = rosx("ros" + kind, "show", "-r", type_name)
            assert (raw.status, raw.out) == (0, text + "\n"), type_name


def test_every_type_ros1_knows_shows_and_hashes_as_recorded() -> None:
    _compare_with(json.loads(GOLDEN.read_text(encoding="utf-8")))


def _known_to_both(
    live: dict[str, dict[str, str]], golden: dict[str, dict[str, str]]
) -> dict[str, dict[str, str]]:
    """``live`` cut down to the types the recording holds too.

    A Debian with more ROS packages installed lists more types (roscpp's own, for one), and one
    with fewer lists fewer: neither is a difference in the texts or sums of a type both know.
    """
    return {part: {k: v for k, v in live[part].items() if k in golden[part]} for part in live}


@needs_ros1
def test_every_type_ros1_knows_shows_and_hashes_the_same() -> None:
    golden = json.loads(GOLDEN.read_text(encoding="utf-8"))
    live = _known_to_both(ros1_python(_ROS1_TEXTS), golden)
    _compare_with(live)
    for part, recorded in golden.items():
        both = {k: v for k, v in recorded.items() if k in live[part]}
        assert live[part] == both, f"re-record tests/golden ({part})"


@needs_ros1
@pytest.mark.parametrize(
    "argv",
    [
        ["rosmsg", "show", "geometry_msgs/Twist"],
        ["rosmsg", "show", "turtlesim/Pose"],
        ["rossrv", "show", "turtlesim/Spawn"],
        ["rossrv", "show", "Spawn"],
        ["rosmsg", "md5", "sensor_msgs/Image"],
        ["rosmsg", "package", "-s", "turtlesim"],
        ["rosmsg", "show", "std_msgs.String"],
        ["rosmsg", "show", "std_msgs::String"],
        ["rosmsg", "show", "-x"],
        ["rosmsg", "show", "NoSuchType"],
        ["rosmsg", "md5", "foo/Bar"],
        ["rosmsg"],
        ["rossrv"],
        ["rosmsg", "nope"],
    ],
)
def test_command_line_matches_ros1(argv: list[str]) -> None:
    ros1 = run_ros1(argv)
    ours = rosx(*argv)
    assert (ours.status, ours.out, ours.err) == (ros1.returncode, ros1.stdout, ros1.stderr)
