"""``rosx roslaunch PKG FILE.launch [arg:=value…]`` and ``rosx roslaunch PATH…``, as ROS 1's.

Options, ``-h`` and usage errors are roslaunch's (optparse, exit status 2). The printing
options (``--nodes``, ``--args NODE``, ``--find-node NODE``, ``--files``, ``--dump-params``,
``--ros-args``) load the files and print (`rosx.launch.printing`); otherwise the files are
loaded, then run (`rosx.launch.run.runner`): the core when no master answers, the parameters, every
node as its own process, until Ctrl-C. ``--core`` runs the core alone, as ``roscore`` does.

A launch file with a mistake starts nothing: the error names its file, line and tag, on one
line (after it, as in ROS 1, that its traceback is in the log), and the status is 1. ROS 1's
options for remote child launchers (``-c``, ``-u``, ``--run_id``) are accepted by the parser,
as in ROS 1, and refused with a clear error.
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.master.defaults import DEFAULT_MASTER_PORT
from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

if TYPE_CHECKING:
    from rosx.launch.model import LaunchPlan
    from rosx.packages.index import PackageIndex

USAGE = (
    "usage: %prog [options] [package] <filename> [arg_name:=value...]\n"
    "       %prog [options] <filename> [<filename>...] [arg_name:=value...]\n\n"
    "If <filename> is a single dash ('-'), launch XML is read from standard input."
)
#: rosmaster's default number of worker threads (``-w``).
NUM_WORKERS = 3


def _parser(env: Environment) -> ToolParser:
    parser = ToolParser(env, "roslaunch", USAGE)
    add = parser.add_option
    add(
        "--files",
        dest="file_list",
        default=False,
        action="store_true",
        help="Print list files loaded by launch file, including launch file itself",
    )
    add(
        "--args",
        dest="node_args",
        default=None,
        help="Print command-line arguments for node",
        metavar="NODE_NAME",
    )
    add(
        "--nodes",
        dest="node_list",
        default=False,
        action="store_true",
        help="Print list of node names in launch file",
    )
    add(
        "--find-node",
        dest="find_node",
        default=None,
        help="Find launch file that node is defined in",
        metavar="NODE_NAME",
    )
    add(
        "-c",
        "--child",
        dest="child_name",
        default=None,
        help="Run as child service 'NAME'. Required with -u",
        metavar="NAME",
    )
    add(
        "--local",
        dest="local_only",
        default=False,
        action="store_true",
        help="Do not launch remote nodes",
    )
    add(
        "--screen",
        dest="force_screen",
        default=False,
        action="store_true",
        help="Force output of all local nodes to screen",
    )
    add(
        "--required",
        dest="force_required",
        default=False,
        action="store_true",
        help="Force all nodes to be required",
    )
    add(
        "--log",
        dest="force_log",
        default=False,
        action="store_true",
        help="Force output of all local nodes to log",
    )
    add(
        "-u",
        "--server_uri",
        dest="server_uri",
        default=None,
        help="URI of server. Required with -c",
        metavar="URI",
    )
    add(
        "--run_id",
        dest="run_id",
        default=None,
        help="run_id of session. Required with -c",
        metavar="RUN_ID",
    )
    add(
        "--wait",
        action="store_true",
        dest="wait_for_master",
        default=False,
        help="wait for master to start before launching",
    )
    add(
        "-p",
        "--port",
        dest="port",
        default=None,
        help="master port. Only valid if master is launched",
        metavar="PORT",
    )
    add(
        "--core",
        action="store_true",
        dest="core",
        default=False,
        help="Launch core services only",
    )
    add("--pid", dest="pid_fn", default="", help="write the roslaunch pid to filename")
    add("-v", action="store_true", dest="verbose", default=False, help="verbose printing")
    add(
        "--no-summary",
        action="store_true",
        dest="no_summary",
        default=False,
        help="hide summary printing",
    )
    add(
        "--dump-params",
        default=False,
        action="store_true",
        dest="dump_params",
        help="Dump parameters of all roslaunch files to stdout",
    )
    add(
        "--skip-log-check",
        default=False,
        action="store_true",
        dest="skip_log_check",
        help="skip check size of log folder",
    )
    add(
        "--ros-args",
        default=False,
        action="store_true",
        dest="ros_args",
        help="Display command-line arguments for this launch file",
    )
    add(
        "--disable-title",
        default=False,
        action="store_true",
        dest="disable_title",
        help="Disable setting of terminal title",
    )
    add(
        "-w",
        "--numworkers",
        dest="num_workers",
        default=NUM_WORKERS,
        type=int,
        help="override number of worker threads. Only valid for core services.",
        metavar="NUM_WORKERS",
    )
    add(
        "-t",
        "--timeout",
        dest="timeout",
        help="override the socket connection timeout (in seconds). Only valid for core services.",
        metavar="TIMEOUT",
    )
    add(
        "--master-logger-level",
        dest="master_logger_level",
        default=False,
        type=str,
        help="set rosmaster.master logger level ('debug', 'info', 'warn', 'error', 'fatal')",
    )
    add(
        "--sigint-timeout",
        dest="sigint_timeout",
        default=15.0,
        type=float,
        help="the SIGINT timeout used when killing nodes (in seconds).",
        metavar="SIGINT_TIMEOUT",
    )
    add(
        "--sigterm-timeout",
        dest="sigterm_timeout",
        default=2.0,
        type=float,
        help="the SIGTERM timeout used when killing nodes if SIGINT does not stop the node "
        "(in seconds).",
        metavar="SIGTERM_TIMEOUT",
    )
    return parser


def _rlexception(message: str) -> CommandError:
    return CommandError(f"RLException: {message}", ExitStatus.ERROR)


def _validate(parser: ToolParser, opts: dict[str, Any], files: list[str]) -> None:
    """roslaunch's checks of the options, in its order."""
    if opts["child_name"]:
        if not opts["server_uri"]:
            parser.error("--child option requires --server_uri to be set as well")
        if not opts["run_id"]:
            parser.error("--child option requires --run_id to be set as well")
        if opts["port"]:
            parser.error("port option cannot be used with roslaunch child mode")
        if files:
            parser.error("Input files are not allowed when run in child mode")
    elif opts["core"]:
        if files:
            parser.error("Input files are not allowed when launching core")
        if opts["run_id"]:
            parser.error("--run_id should only be set for child roslaunches (-c)")
    elif not files:
        parser.error("you must specify at least one input file")
    else:
        missing = [f for f in files if not (f == "-" or Path(f).exists())]
        if missing:
            parser.error(f"The following input files do not exist: {', '.join(missing)}")
    if files.count("-") > 1:
        parser.error("Only a single instance of the dash ('-') may be specified.")
    printing = [opts["node_list"], opts["find_node"], opts["node_args"], opts["ros_args"]]
    if len([x for x in printing if x]) > 1:
        parser.error("only one of [--nodes, --find-node, --args --ros-args] may be specified")


def _port(parser: ToolParser, value: str | None) -> int | None:
    if value is None:
        return None
    try:
        port = int(value)
    except ValueError:
        parser.error(f"invalid port: {value}")
    if not 0 < port < 65536:
        raise _rlexception(f"invalid port assignment: {port}")
    return port


def _stdin_file(env: Environment, files: list[str], keep: list[Path]) -> list[str]:
    """``-``: the launch XML read from stdin, into a file of its own (removed afterwards)."""
    if "-" not in files:
        return files
    env.out("Passed '-' as file argument, attempting to read roslaunch XML from stdin.")
    text = env.stdin.read()
    env.out(f"... {len(text)} bytes read successfully.\n")
    handle, name = tempfile.mkstemp(prefix="roslaunch-stdin-", suffix=".launch")
    with os.fdopen(handle, "w", encoding="utf-8") as file:
        file.write(text)
    keep.append(Path(name))
    return [name if f == "-" else f for f in files]


def _print_option(
    opts: dict[str, Any],
    files: list[str],
    cli_args: dict[str, str],
    argv: list[str],
    env: Environment,
    index: PackageIndex,
) -> int:
    """The printing options: load the files as roslaunch loads them for it, and print."""
    from rosx.launch import errors, loader, printing  # noqa: PLC0415 - launch code loads only for launch files
    from rosx.launch.run.command import run_command  # noqa: PLC0415 - launch code loads only for launch files
    from rosx.launch.run.runner import provided_program  # noqa: PLC0415 - launch code loads only for launch files

    try:
        plan = loader.load_launch(
            files,
            cli_args,
            env.environ,
            index,
            with_core=not opts["dump_params"],
            run=run_command,
            args_only=opts["ros_args"] and not (opts["node_args"] or opts["find_node"]),
            argv=argv,
        )
        if opts["node_args"]:
            text = printing.node_args_text(
                plan,
                opts["node_args"],
                files,
                env.environ,
                index,
                lambda package, kind: provided_program(package, kind, index),
            )
        elif opts["find_node"]:
            text = printing.find_node_text(plan, opts["find_node"], files, env.environ)
        elif opts["dump_params"]:
            text = printing.dump_params_text(plan)
        elif opts["file_list"]:
            text = printing.files_text(plan)
        elif opts["ros_args"]:
            text = printing.ros_args_text(plan)
        else:
            text = printing.nodes_text(plan)
    except errors.LaunchError as error:
        raise CommandError(str(error), error.status) from None
    env.stdout.write(text)
    return ExitStatus.OK


def _write_pid(opts: dict[str, Any], env: Environment, port: int | None) -> Path | None:
    from rosx.workspace.logdir import ros_home  # noqa: PLC0415 - workspace code loads only when used

    if not (opts["pid_fn"] or opts["core"]):
        return None
    home = ros_home(env.environ)
    if opts["pid_fn"]:
        path = Path(os.path.expanduser(opts["pid_fn"]))  # noqa: PTH111 - ROS 1 expands ~ only
    else:
        path = home / f"roscore-{port or DEFAULT_MASTER_PORT}.pid"
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(str(os.getpid()), encoding="utf-8")
    except OSError as error:
        raise _rlexception(f"cannot write the pid file [{path}]: {error.strerror}") from None
    return path if opts["pid_fn"] else None


def _run_core(env: Environment, port: int | None) -> int:
    """``--core``: roscore (which ROS 1's roscore is: ``roslaunch --core``)."""
    from rosx_commands.main import run_tool  # noqa: PLC0415 - tools are loaded by name

    return run_tool(["roscore", "-p", str(port or DEFAULT_MASTER_PORT)], env)


def _launch(
    opts: dict[str, Any],
    files: list[str],
    cli_args: dict[str, str],
    argv: list[str],
    env: Environment,
    port: int | None,
    index: PackageIndex,
) -> int:
    from rosx.launch.loader import load_launch  # noqa: PLC0415 - launch code loads only for launch files
    from rosx.launch.run.command import run_command  # noqa: PLC0415 - launch code loads only for launch files
    from rosx.launch.run.console import LaunchConsole  # noqa: PLC0415 - launch code loads only for launch files
    from rosx.launch.run.runner import LaunchFailedError, LaunchRun, LaunchSettings  # noqa: PLC0415 - launch code loads only for launch files
    from rosx_commands.invocation import script_command  # noqa: PLC0415 - this tool's parts load only when used
    from rosx_commands.scripts import shim_dirs  # noqa: PLC0415 - this tool's parts load only when used

    def load() -> LaunchPlan:
        return load_launch(files, cli_args, env.environ, index, argv=argv, run=run_command)

    settings = LaunchSettings(
        port=port,
        wait_for_master=opts["wait_for_master"],
        local_only=opts["local_only"],
        force_screen=opts["force_screen"],
        force_log=opts["force_log"],
        force_required=opts["force_required"],
        show_summary=not opts["no_summary"],
        verbose=opts["verbose"],
        skip_log_check=opts["skip_log_check"],
        titles=not opts["disable_title"],
        sigint_timeout=opts["sigint_timeout"],
        sigterm_timeout=opts["sigterm_timeout"],
        shim_dirs=shim_dirs(),
    )
    console = LaunchConsole(env.stdout, env.stderr, titles=not opts["disable_title"])
    run = LaunchRun(
        load,
        settings,
        env.environ,
        console,
        package_index=index,
        script_command=script_command(),
        title=",".join(files),
    )
    try:
        return run.run()
    except LaunchFailedError as error:
        raise CommandError(f"{error.prefix}{error}", ExitStatus.ERROR) from None


def _roslaunch(argv: list[str], env: Environment) -> int:
    parser = _parser(env)
    options, args = parser.parse(argv)
    opts = vars(options)
    for name in ("sigint_timeout", "sigterm_timeout"):
        if opts[name] <= 0:
            kind = name.split("_")[0]
            raise _rlexception(f"{kind}_timeout must be a positive number, received {opts[name]:f}")

    from rosx.launch.errors import LaunchError  # noqa: PLC0415 - launch code loads only for launch files
    from rosx.launch.loader import resolve_launch_arguments  # noqa: PLC0415 - launch code loads only for launch files
    from rosx.msg.store import share_package_index  # noqa: PLC0415 - the type store loads on first use
    from rosx.packages.index import PackageIndex  # noqa: PLC0415 - the package index loads only when used

    # One crawl of the package path for the whole launch: the files, the nodes' programs, and
    # the types of the core it may start.
    index = PackageIndex.from_environ(env.environ)
    share_package_index(index)
    try:
        files, cli_args = resolve_launch_arguments(args, index)
    except LaunchError as error:
        hint = _not_found_hint(args, index) if env.stderr_isatty else None
        raise _rlexception(str(error) + (f"\n{hint}" if hint else "")) from None
    _validate(parser, opts, files)
    port = _port(parser, opts["port"])
    if opts["child_name"]:
        raise _rlexception(
            "rosx roslaunch does not run as a child of a remote roslaunch (-c/--child): "
            "it starts nodes on this machine only"
        )
    printing = ("node_args", "node_list", "find_node", "dump_params", "file_list", "ros_args")
    if any(opts[name] for name in printing):
        if opts["node_args"] and not files:
            parser.error("please specify a launch file")
        return _print_option(opts, files, cli_args, args, env, index)
    if opts["wait_for_master"] and opts["core"]:
        parser.error("--wait cannot be used with roscore")
    pid_file = _write_pid(opts, env, port)
    temporary: list[Path] = []
    try:
        if opts["core"]:
            return _run_core(env, port)
        files = _stdin_file(env, files, temporary)
        return _launch(opts, files, cli_args, args, env, port, index)
    finally:
        for path in [*temporary, *([pid_file] if pid_file else [])]:
            path.unlink(missing_ok=True)


def _not_found_hint(args: Sequence[str], index: PackageIndex) -> str | None:
    """For a launch file not found (on a terminal): the package or file meant, or that rosx
    does not provide the package (`rosx_commands.hints`), or the launch files it has."""
    from rosx.names.typos import rejoined  # noqa: PLC0415 - a launch file not found
    from rosx_commands.hints import (  # noqa: PLC0415 - a launch file not found
        close_name,
        known_packages,
        unknown_package_line,
    )

    words = [a for a in args if ":=" not in a]
    if len(words) < 2 or words[0] == "-" or words[0].endswith((".launch", ".test", ".xml")):
        return None
    package = words[0]

    def launch_files(package: str) -> list[str]:
        found = {
            path.name
            for directory in index.directories(package)
            for path in directory.rglob("*")
            if path.suffix in (".launch", ".test", ".xml") and path.name != "package.xml"
        }
        return sorted(found)

    def retyped(fixed: list[str]) -> str:
        package, *rest = fixed
        rest = rejoined(rest, launch_files(package)) or rest
        return " ".join(["roslaunch", package, *rest])

    if package not in known_packages(index):
        return unknown_package_line(words, index, retyped, "roslaunch")
    names = launch_files(package)
    fixed = rejoined(words[1:], names)
    if fixed is None:
        close = close_name(words[1], names)
        fixed = [close, *words[2:]] if close else None
    if fixed is not None:
        return f"[roslaunch] Did you mean {fixed[0]}? ({' '.join(['roslaunch', package, *fixed])})"
    listing = ", ".join(names) if names else "none"
    return f"[roslaunch] the launch files of {package}: {listing}"


def roslaunch(argv: Sequence[str], env: Environment) -> int:
    """Run ``roslaunch ARGV…``."""
    return run_command(_roslaunch, list(argv), env)


__all__ = ["roslaunch"]
