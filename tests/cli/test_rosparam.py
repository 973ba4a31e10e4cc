"""``rosx rosparam``: golden texts, exit codes and stored XML-RPC types, against a rosx master."""

from __future__ import annotations

import math
from collections.abc import Iterator
from pathlib import Path
from typing import Any
from xmlrpc.client import DateTime

import pytest

from rosx.master.server import MasterThread
from rosx.transport.client import XmlRpcClient
from tests.support.cli import Result, clean_environ, rosx
from tests.support.procs import free_port

OVERVIEW = """rosparam is a command-line tool for getting, setting, and deleting parameters from the ROS Parameter Server.

Commands:
\trosparam set\tset parameter
\trosparam get\tget parameter
\trosparam load\tload parameters from file
\trosparam dump\tdump parameters to file
\trosparam delete\tdelete parameter
\trosparam list\tlist parameter names

"""


class Server:
    """A rosx master for one test, with direct access to what it stores."""

    def __init__(self, uri: str) -> None:
        self.uri = uri
        self.client = XmlRpcClient(timeout=5.0)

    def run(self, *argv: str, stdin: str = "", **environ: str) -> Result:
        return rosx(*argv, stdin=stdin, environ=clean_environ(ROS_MASTER_URI=self.uri, **environ))

    def stored(self, name: str) -> Any:
        code, status, value = self.client.call(self.uri, "getParam", "/test", name)
        assert code == 1, status
        return value


@pytest.fixture
def server() -> Iterator[Server]:
    with MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as master:
        server = Server(master.uri)
        try:
            yield server
        finally:
            server.client.close()


@pytest.mark.parametrize(
    ("text", "stored", "printed"),
    [
        ("5", 5, "5\n"),
        ("-3", -3, "-3\n"),
        ("-3.5", -3.5, "-3.5\n"),
        ("1e5", "1e5", "1e5\n"),
        ("1.0e+5", 100000.0, "100000.0\n"),
        ("0.00001", 1e-05, "1.0e-05\n"),
        ("true", True, "true\n"),
        ("hello", "hello", "hello\n"),
        ("'5'", "5", "'5'\n\n"),
        ("", "", "''\n\n"),
        ("deg(180)", math.pi, "3.141592653589793\n"),
        ("h\xe9llo", "h\xe9llo", '"h\\xE9llo"\n\n'),
        ("[1, 2.5, x, true]", [1, 2.5, "x", True], "- 1\n- 2.5\n- x\n- true\n\n"),
        (".inf", math.inf, ".inf\n"),
        ("!!binary aGVsbG8=", b"hello", "!!binary |-\n  aGVsbG8=\n\n"),
        (
            "2001-12-14t21:59:43.10-05:00",
            DateTime("20011214T21:59:43"),
            "!!python/object:xmlrpc.client.DateTime\nvalue: 20011214T21:59:43\n\n",
        ),
    ],
)
def test_set_keeps_yaml_types_and_get_prints_yaml(
    server: Server, text: str, stored: object, printed: str
) -> None:
    assert server.run("rosparam", "set", "/p", text).status == 0
    value = server.stored("/p")
    assert value == stored and type(value) is type(stored)
    done = server.run("rosparam", "get", "/p")
    assert (done.out, done.err, done.status) == (printed, "", 0)


def test_date_times_print_as_ros1_prints_them(server: Server) -> None:
    # What ROS 1's rosparam prints for the xmlrpc.client.DateTime values rospy hands it.
    for name, text in (("/q/dt", "20240102T03:04:05"), ("/q/odd", "2024-01-02T03:04:05")):
        server.client.call(server.uri, "setParam", "/t", name, DateTime(text))
    server.client.call(server.uri, "setParam", "/t", "/l", [1, DateTime("whenever")])
    tag = "!!python/object:xmlrpc.client.DateTime"
    assert server.run("rosparam", "get", "/q/dt").out == f"{tag}\nvalue: 20240102T03:04:05\n\n"
    namespace = (
        f"dt: {tag}\n  value: 20240102T03:04:05\nodd: {tag}\n  value: '2024-01-02T03:04:05'\n"
    )
    assert server.run("rosparam", "get", "/q").out == namespace + "\n"
    assert server.run("rosparam", "dump", "", "/q").out == namespace
    assert server.run("rosparam", "get", "-p", "/q").out == (
        f"dt: {tag}\nvalue: 20240102T03:04:05\nodd: {tag}\nvalue: '2024-01-02T03:04:05'\n"
    )
    assert server.run("rosparam", "get", "/l").out == f"- 1\n- {tag}\n  value: whenever\n\n"


def test_dicts_update_a_namespace(server: Server) -> None:
    server.run("rosparam", "set", "/d", "{a: 1, b: {c: [1, 2], d: str}, e: 2.0}")
    server.run("rosparam", "set", "/d", "{b: {d: new}, f: {}}")
    assert server.stored("/d") == {"a": 1, "b": {"c": [1, 2], "d": "new"}, "e": 2.0}
    assert server.run("rosparam", "get", "/d").out == (
        "a: 1\nb:\n  c:\n  - 1\n  - 2\n  d: new\ne: 2.0\n\n"
    )
    assert server.run("rosparam", "get", "-p", "/d").out == (
        "a: 1\nb:\n  c: - 1\n- 2\n  d: new\ne: 2.0\n"
    )
    assert server.run("rosparam", "list", "/d").out == "/d/a\n/d/b/c\n/d/b/d\n/d/e\n"


def test_verbose_set_get_delete(server: Server) -> None:
    done = server.run("rosparam", "set", "-v", "/v", "{a: 1, b: [1, 2], c: {d: x}}")
    assert done.out == (
        "set parameter [/v/a] to [1]\nset parameter [/v/b] to [[1, 2]]\nset parameter [/v/c/d] to [x]\n"
    )
    assert server.run("rosparam", "get", "-v", "/v/a").out == "getting parameter [/v/a]\n1\n"
    assert server.run("rosparam", "delete", "-v", "/v").out == "deleted parameter [/v]\n"
    gone = server.run("rosparam", "get", "/v")
    assert (gone.out, gone.err, gone.status) == ("", "ERROR: Parameter [/v] is not set\n", 1)


def test_files_negative_numbers_and_private_names(server: Server, tmp_path: Path) -> None:
    text = tmp_path / "t.txt"
    text.write_text("text file\ncontents\n")
    binary = tmp_path / "b.dat"
    binary.write_bytes(b"\x00\x01\xff")
    assert server.run("rosparam", "set", "-t", str(text), "/txt").status == 0
    assert server.stored("/txt") == "text file\ncontents\n"
    assert server.run("rosparam", "get", "/txt").out == "'text file\n\n  contents\n\n  '\n\n"
    assert server.run("rosparam", "set", "/bin", "--binfile", str(binary)).status == 0
    assert server.stored("/bin") == b"\x00\x01\xff"
    assert server.run("rosparam", "set", "/neg", "-5").status == 0
    assert server.stored("/neg") == -5
    assert server.run("rosparam", "set", "~x", "1").status == 0
    assert server.stored("/rosparam/x") == 1
    assert server.run("rosparam", "set", "rel", "7", ROS_NAMESPACE="/ns").status == 0
    assert server.run("rosparam", "get", "rel", ROS_NAMESPACE="/ns").out == "7\n"


def test_dump_and_load_round_trip(server: Server, tmp_path: Path) -> None:
    server.run("rosparam", "set", "/x", "{i: 1, f: 1.5, b: false, s: 'yes', l: [a, 1], n: {m: -2}}")
    server.run("rosparam", "set", "-b", str(_write(tmp_path / "b", b"\xffbin")), "/x/bin")
    dumped = "b: false\nbin: !!binary |-\n  /2Jpbg==\nf: 1.5\ni: 1\nl:\n- a\n- 1\nn:\n  m: -2\ns: 'yes'\n"
    assert server.run("rosparam", "dump", "", "/x").out == dumped
    target = tmp_path / "x.yaml"
    assert server.run("rosparam", "dump", str(target), "/x").out == ""
    assert target.read_text() == dumped
    assert server.run("rosparam", "load", str(target), "/copy").status == 0
    assert server.stored("/copy") == server.stored("/x")
    assert server.run("rosparam", "load", "-", "/stdin", stdin=dumped).status == 0
    assert server.stored("/stdin") == server.stored("/x")
    verbose = server.run("rosparam", "dump", "-v", str(tmp_path / "v.yaml"), "/x/n")
    assert verbose.out == f"dumping namespace [/x/n] to file [{tmp_path / 'v.yaml'}]\n/x/n/m=-2\n"


def _write(path: Path, data: bytes) -> Path:
    path.write_bytes(data)
    return path


def test_load_angles_namespaces_and_documents(server: Server, tmp_path: Path) -> None:
    source = tmp_path / "l.yaml"
    source.write_text(
        "a: !degrees 180\nb: deg(90)\nc: !radians pi/2\nd: rad(2*pi)\ne: '!degrees 1'\n"
        "---\n_ns: sub\nx: 1\n---\ny: [1, {k: v}]\n"
    )
    done = server.run("rosparam", "load", "-v", str(source), "/ld")
    assert done.out == (
        f"reading parameters from [{source}]\nreading parameters into namespace [/ld/sub]\n"
        f"/ld/a={math.pi}\n/ld/b={math.pi / 2}\n/ld/c={math.pi / 2}\n/ld/d={2 * math.pi}\n"
        "/ld/e=!degrees 1\n/ld/sub/x=1\n/ld/y=[1, {'k': 'v'}]\n"
    )
    assert server.stored("/ld/sub/x") == 1
    assert server.stored("/ld/d") == 2 * math.pi
    assert server.run("rosparam", "get", "/ld/e").out == "'!degrees 1'\n\n"


def test_list_and_delete(server: Server) -> None:
    server.run("rosparam", "set", "/a/b", "1")
    server.run("rosparam", "set", "/a/c", "2")
    server.run("rosparam", "set", "/z", "3")
    assert server.run("rosparam", "list").out == "/a/b\n/a/c\n/z\n"
    assert server.run("rosparam", "list", "/a").out == "/a/b\n/a/c\n"
    assert server.run("rosparam", "list", "/nothing").out == "\n"
    # ROS 1 refuses two namespaces but ignores three.
    assert server.run("rosparam", "list", "/a", "b", "c").out == "/a/b\n/a/c\n/z\n"
    assert server.run("rosparam", "delete", "/a/b").status == 0
    assert server.run("rosparam", "list").out == "/a/c\n/z\n"
    assert server.run("rosparam", "delete", "-v", "/").out == "deleted ENTIRE parameter server\n"
    assert server.run("rosparam", "get", "/").out == "{}\n\n"
    missing = server.run("rosparam", "delete", "/nope")
    assert (missing.err, missing.status) == ("ERROR: parameter [/nope] is not set\n", 1)


@pytest.mark.parametrize(
    ("argv", "err"),
    [
        (
            ["set", "/p", "{x:5}"],
            "ERROR: cannot set parameter [/p/x:5]: YAML needs a space after the colon, write {x: 5}",
        ),
        (
            ["set", "/p", "null"],
            "ERROR: cannot set parameter [/p]: the Parameter Server cannot store null (an empty value)",
        ),
        (
            ["set", "/p", "{a: {b: 2002-12-14}}"],
            "ERROR: cannot set parameter [/p/a/b]: the Parameter Server cannot store a date (2002-12-14); quote it for a string",
        ),
        (
            ["set", "/p", "3000000000"],
            "ERROR: cannot set parameter [/p]: 3000000000 is beyond the Parameter Server's 32-bit integers (-2147483648 to 2147483647)",
        ),
        (
            ["set", "/p", "a\tb"],
            "ERROR: Invalid YAML value: while scanning for the next token; found character '\\t' that cannot start any token (line 1, column 2)",
        ),
        (
            ["set", "/p", "{a: [1"],
            "ERROR: Invalid YAML value: while parsing a flow sequence; expected ',' or ']', but got '<stream end>' (line 1, column 7)",
        ),
        (["set", "/p", "deg(abc)"], "ERROR: invalid degree value: deg(abc)"),
        (
            ["set", "/", "5"],
            "ERROR: Error: invalid arguments: cannot set root of parameter tree to non-dictionary",
        ),
        (["get", "/nope"], "ERROR: Parameter [/nope] is not set"),
        (["dump", "", "/nope"], "ERROR: Parameter [/nope] is not set"),
        (["load", "/nonexistent/file.yaml"], "ERROR: file [/nonexistent/file.yaml] does not exist"),
        (["load", "-"], "ERROR: global / can only be set to a dictionary"),
    ],
)
def test_bad_values_get_one_line_errors(server: Server, argv: list[str], err: str) -> None:
    done = server.run("rosparam", *argv, stdin="- 1\n")
    assert (done.out, done.err, done.status) == ("", err + "\n", 1)
    assert server.run("rosparam", "set", "/after", "1").status == 0
    assert server.stored("/after") == 1


def test_a_failing_load_sets_nothing(server: Server, tmp_path: Path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("a: 1\n---\nb: [\n")
    done = server.run("rosparam", "load", str(bad), "/l")
    assert done.err == (
        f"ERROR: Invalid YAML in [{bad}]: while parsing a flow node; expected the node content, "
        "but found '<stream end>' (line 4, column 1)\n"
    )
    assert server.run("rosparam", "list", "/l").out == "\n"


@pytest.mark.parametrize("argv", [[], ["-h"], ["nope"]])
def test_overview_exits_0(argv: list[str]) -> None:
    done = rosx("rosparam", *argv)
    assert (done.out, done.err, done.status) == (OVERVIEW, "", 0)


@pytest.mark.parametrize(
    ("argv", "usage", "error"),
    [
        (["get"], "get [options] parameter", "invalid arguments. Please specify a parameter name"),
        (["get", "a", "b"], "get [options] parameter", "too many arguments"),
        (
            ["set"],
            "set [options] parameter value",
            "invalid arguments. Please specify a parameter name",
        ),
        (
            ["set", "a"],
            "set [options] parameter value",
            "invalid arguments. Please specify a parameter value",
        ),
        (["set", "a", "b", "c"], "set [options] parameter value", "too many arguments"),
        (
            ["set", "-t", "nofile", "/x"],
            "set [options] parameter value",
            "file 'nofile' does not exist",
        ),
        (
            ["set", "-t", "a", "-b", "b", "/x"],
            "set [options] parameter value",
            "you may only specify one of --textfile or --binfile",
        ),
        (
            ["set", "-t", "-v", "x"],
            "set [options] parameter value",
            "-t and --textfile options require an argument",
        ),
        (["set", "/q", "-t"], "set [options] parameter value", "-t option requires 1 argument"),
        (["set", "/q", "-.5"], "set [options] parameter value", "no such option: -."),
        (
            ["load"],
            "load [options] file [namespace]",
            "invalid arguments. Please specify a file name or - for stdin",
        ),
        (["load", "a", "b", "c"], "load [options] file [namespace]", "too many arguments"),
        (["dump", "a", "b", "c"], "dump [options] file [namespace]", "too many arguments"),
        (
            ["delete"],
            "delete [options] parameter",
            "invalid arguments. Please specify a parameter name",
        ),
        (["delete", "a", "b"], "delete [options] parameter", "too many arguments"),
        (["list", "a", "b"], "list [namespace]", "too many arguments"),
    ],
)
def test_usage_errors_exit_2(argv: list[str], usage: str, error: str) -> None:
    done = rosx("rosparam", *argv)
    assert (done.out, done.err, done.status) == (
        "",
        f"Usage: rosparam {usage}\n\nrosparam: error: {error}\n",
        2,
    )


def test_help_texts() -> None:
    assert rosx("rosparam", "set", "-h").out == (
        "Usage: rosparam set [options] parameter value\n\nOptions:\n"
        "  -h, --help            show this help message and exit\n"
        "  -t TEXT_FILE, --textfile=TEXT_FILE\n"
        "                        set parameters to contents of text file\n"
        "  -b BINARY_FILE, --binfile=BINARY_FILE\n"
        "                        set parameters to contents of binary file\n"
        "  -v                    turn on verbose output\n"
    )
    assert rosx("rosparam", "get", "-h").out == (
        "Usage: rosparam get [options] parameter\n\nOptions:\n"
        "  -h, --help  show this help message and exit\n"
        "  -p          pretty print. WARNING: not YAML-safe\n"
        "  -v          turn on verbose output\n"
    )


@pytest.mark.parametrize(
    "argv", [["list"], ["get", "/x"], ["set", "/x", "1"], ["delete", "/x"], ["dump"]]
)
def test_master_down_exits_1(argv: list[str]) -> None:
    done = rosx(
        "rosparam", *argv, environ=clean_environ(ROS_MASTER_URI=f"http://127.0.0.1:{free_port()}")
    )
    assert done.status == 1
    assert done.err.startswith("ERROR: Unable to communicate with master!\n")
