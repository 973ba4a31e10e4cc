"""Short commands stay fast: the headless core never pays for the TUI, numpy or unused layers."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

HEAVY = ("textual", "numpy", "rosbags")


def _modules_after(code: str) -> set[str]:
    script = f"{code}\nimport sys, json\nprint(json.dumps(sorted(sys.modules)))"
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, check=True
    )
    return set(json.loads(done.stdout.splitlines()[-1]))


def _tool_modules(argv: list[str]) -> set[str]:
    """The modules a ROS tool loads for ``argv``, with no master to answer it."""
    return _modules_after(
        "import io\nfrom rosx_commands.context import Environment\nfrom rosx_commands.main import run_tool\n"
        f"run_tool({argv!r}, Environment(stdout=io.StringIO(), stderr=io.StringIO(),"
        " environ={'ROS_MASTER_URI': 'http://localhost:9'}))"
    )


@pytest.mark.parametrize(
    "code",
    [
        "import rosx.names, rosx.wire.xmlrpc, rosx.wire.tcpros, rosx.msg.store",
        "from rosx.msg.codec.classes import get_message_class; from rosx.msg.store import TypeStore\n"
        "TypeStore([]).msg('turtlesim/Pose'); get_message_class('turtlesim/Pose')().serialize",
    ],
)
def test_core_imports_nothing_heavy(code: str) -> None:
    loaded = _modules_after(code)
    assert not {m for m in loaded if m.split(".")[0] in HEAVY}
    assert not {m for m in loaded if m.startswith(("rosx_commands", "rosx_turtle"))}


def test_rosmsg_of_a_user_type_loads_no_tui_and_no_numpy() -> None:
    loaded = _modules_after(
        "import io\nfrom rosx_commands.context import Environment\nfrom rosx_commands.main import run_tool\n"
        "run_tool(['rosmsg', 'show', 'turtlesim/Pose'], Environment(stdout=io.StringIO(), environ={}))"
    )
    assert not {m for m in loaded if m.split(".")[0] in HEAVY}


def test_ros_tools_do_not_pay_for_typer() -> None:
    loaded = _modules_after(
        "import io\nfrom rosx_commands.context import Environment\nfrom rosx_commands.main import run_tool\n"
        "run_tool(['rostopic', 'list'], Environment(stdout=io.StringIO(), stderr=io.StringIO(),"
        " environ={'ROS_MASTER_URI': 'http://localhost:9'}))"
    )
    assert not {m for m in loaded if m.split(".")[0] in ("typer", "pydantic", "rich", *HEAVY)}


@pytest.mark.parametrize(
    "argv",
    [["rosservice", "list"], ["rosservice", "call", "/x", "{a: 1}"], ["rosparam", "get", "/x"]],
)
def test_service_and_param_tools_do_not_pay_for_typer(argv: list[str]) -> None:
    loaded = _tool_modules(argv)
    assert not {m for m in loaded if m.split(".")[0] in ("typer", "pydantic", "rich", *HEAVY)}
    assert "dataclasses" not in loaded and "textual" not in loaded


def test_client_and_workspace_layers_import_nothing_heavy_or_higher() -> None:
    loaded = _modules_after(
        "import rosx.client, rosx.client.script, rosx.client.modules\n"
        "import rosx.workspace.build, rosx.packages.index, rosx.workspace.create"
    )
    assert not {m for m in loaded if m.split(".")[0] in HEAVY}
    assert not {m for m in loaded if m.startswith(("rosx_commands", "rosx_turtle"))}
    assert not {m for m in loaded if m.startswith(("rosx.bag", "rosx.launch"))}


def test_the_bag_layers_shim_directory_costs_no_bag_module() -> None:
    loaded = _modules_after("import rosx.bag\nrosx.bag.SHIM_DIR")
    assert {m for m in loaded if m.startswith("rosx.bag")} == {"rosx.bag"}


@pytest.mark.parametrize(
    "argv",
    [
        ["rosrun", "nopkg", "x"],
        ["rospack", "find", "x"],
        ["catkin_create_pkg", "--help"],
        ["catkin_make", "-C", "/nonexistent"],
        ["roscd", "--where", "x"],
        ["shell-init", "bash"],
    ],
)
def test_workspace_tools_do_not_pay_for_typer(argv: list[str], tmp_path: Path) -> None:
    environ = {"XDG_CACHE_HOME": str(tmp_path)}  # where shell-init writes its programs
    loaded = _modules_after(
        "import io\nfrom rosx_commands.context import Environment\nfrom rosx_commands.main import run_tool\n"
        f"run_tool({argv!r}, Environment(stdout=io.StringIO(), stderr=io.StringIO(), environ={environ!r}))"
    )
    assert not {m for m in loaded if m.split(".")[0] in ("typer", "pydantic", "rich", *HEAVY)}
    assert "dataclasses" not in loaded and "textual" not in loaded
    if argv[0] == "shell-init":  # the programs on PATH were written, at that cost
        assert list(tmp_path.glob("rosx/bin-*/rostopic"))


def test_rosbag_info_loads_no_tui_numpy_or_typer() -> None:
    loaded = _modules_after(
        "import io\nfrom rosx_commands.context import Environment\nfrom rosx_commands.main import run_tool\n"
        "run_tool(['rosbag', 'info', '/nonexistent.bag'], Environment(stdout=io.StringIO(),"
        " stderr=io.StringIO(), environ={}))"
    )
    assert not {m for m in loaded if m.split(".")[0] in ("typer", "pydantic", "rich", *HEAVY)}


def test_rqt_graph_text_output_loads_no_tui() -> None:
    loaded = _modules_after(
        "import io\nfrom rosx_commands.context import Environment\nfrom rosx_commands.main import run_tool\n"
        "run_tool(['rqt_graph', '--text'], Environment(stdout=io.StringIO(), stderr=io.StringIO(),"
        " environ={'ROS_MASTER_URI': 'http://localhost:9'}))"
    )
    assert not {m for m in loaded if m.split(".")[0] in ("textual", "typer", "numpy")}


@pytest.mark.parametrize(
    "argv",
    [["rostopic", "list"], ["rosnode", "info", "/x"], ["rosservice", "call", "/x"]],
)
def test_master_and_service_clients_do_not_load_the_node_runtime(argv: list[str]) -> None:
    loaded = _tool_modules(argv)
    service_client = {"rosx.node.errors", "rosx.node.service_client"}
    assert not {m for m in loaded if m.startswith("rosx.node.")} - service_client
    assert not {"asyncio", "threading", "rosx.node.node", "rosx.transport.loop_thread"} & loaded


def test_rosx_node_loads_its_modules_on_first_use() -> None:
    loaded = _modules_after("import rosx.node")
    assert "rosx.node.node" not in loaded and "asyncio" not in loaded
    loaded = _modules_after("from rosx.node import Node, ServiceClient")
    assert {"rosx.node.node", "rosx.node.service_client"} <= loaded


#: What a one-shot ROS tool's start-up does without: each costs milliseconds that ROS 1's own
#: tools (a 50 ms ``rosparam get``) leave no room for.
STARTUP_FREE = ("dataclasses", "typing", "optparse", "pathlib", "rosbags", "asyncio", "threading")


@pytest.mark.parametrize(
    "argv",
    [
        ["rostopic", "list"],
        ["rosnode", "list"],
        ["rosparam", "get", "/"],
        ["rosparam", "list"],
        ["rosservice", "list"],
    ],
)
def test_master_tools_start_with_little(argv: list[str]) -> None:
    loaded = _tool_modules(argv)
    assert not {m for m in loaded if m.split(".")[0] in STARTUP_FREE}


def test_rosmsg_of_a_standard_type_reads_rosbags_once(tmp_path: Path) -> None:
    """The texts of the types only rosbags defines (``bond/Status``) are kept in the user's
    cache: rosbags is imported once; the types rosx ships as files never need it."""
    code = (
        f"import io, os\nos.environ['XDG_CACHE_HOME'] = {str(tmp_path)!r}\n"
        "from rosx_commands.context import Environment\nfrom rosx_commands.main import run_tool\n"
        "out = io.StringIO()\n"
        "run_tool(['rosmsg', 'show', 'bond/Status'], Environment(stdout=out, environ={}))\n"
        "assert out.getvalue().startswith('std_msgs/Header header'), out.getvalue()"
    )
    first, second = _modules_after(code), _modules_after(code)
    assert "rosbags" in first
    assert not {m for m in second if m.split(".")[0] in ("rosbags", "dataclasses", "typing")}
    shipped = _modules_after(code.replace("bond/Status", "geometry_msgs/Twist").replace(
        "std_msgs/Header header", "geometry_msgs/Vector3 linear"))  # fmt: skip
    assert not {m for m in shipped if m.split(".")[0] in ("rosbags", "dataclasses")}


@pytest.mark.parametrize(
    "argv", [["rqt_plot", "--help"], ["rqt_plot", "/a/x"], ["rqt_topic"], ["rqt", "--help"]]
)
def test_rqt_tools_load_no_tui_before_they_draw(argv: list[str]) -> None:
    loaded = _modules_after(
        "import io\nfrom rosx_commands.context import Environment\nfrom rosx_commands.main import run_tool\n"
        f"run_tool({argv!r}, Environment(stdout=io.StringIO(), stderr=io.StringIO(), environ={{}}))"
    )
    assert not {m for m in loaded if m.split(".")[0] in ("textual", "textual_plot", "numpy")}


def test_a_tab_for_package_names_loads_neither_pathlib_nor_the_index(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The Python a shell's <TAB> starts (no ``site``) reads the kept crawl with ``os`` alone;
    ``rospack list`` and ``find`` do too."""
    import shlex

    from rosx.packages import cache
    from rosx_commands.invocation import complete_command
    from tests.support.packages import package

    monkeypatch.setattr(cache, "RACY_SECONDS", 0.0)  # the tree was made a moment ago
    package(tmp_path / "src", "lab2")
    environ = {"ROS_PACKAGE_PATH": str(tmp_path / "src"), "ROS_HOME": str(tmp_path / "home")}
    cache.cached_packages([tmp_path / "src"], tmp_path / "home")  # kept by an earlier command
    python, *flags, code = shlex.split(complete_command())
    # What it loaded, said as it exits (atexit is built in, as the modules it needs are).
    said = "import atexit; atexit.register(lambda: print('', *sorted(sys.modules))); "
    code = code.replace("from rosx_commands", said + "from rosx_commands")
    done = subprocess.run(
        [python, *flags, code, "1", "roscd", "la"],
        env=environ,
        capture_output=True,
        text=True,
        check=False,
    )
    offered, loaded = done.stdout.split("\0")
    assert offered == "lab2/"
    light = set(loaded.split())
    assert "rosx.packages.kept" in light
    assert not light & {"pathlib", "re", "enum", "rosx.packages.index", "rosx.packages.crawl"}
    for argv in (["rospack", "list"], ["rospack", "find", "lab2"]):
        by_rospack = _modules_after(
            "import io\nfrom rosx_commands.context import Environment\n"
            "from rosx_commands.main import run_tool\n"
            f"run_tool({argv!r}, Environment(stdout=io.StringIO(), environ={environ!r}))"
        )
        assert "rosx.packages.kept" in by_rospack
        assert not by_rospack & {"pathlib", "rosx.packages.index", "rosx.packages.crawl"}
