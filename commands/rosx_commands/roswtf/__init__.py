"""``rosx roswtf [launch file…]``: check the ROS environment and the running graph, as roswtf.

First the static checks (`offline`: the environment variables; with launch files, the packages
and nodes they name), then, when a master answers and ``--offline`` is not given, the graph
checks (`online`). The texts are roswtf's: ``Package: NAME`` when run in a package,
``Static checks summary:``, ``No errors or warnings`` or the warnings and errors,
``ROS Master does not appear to be running.``… A ``ROS_ROOT`` that is not set counts as rosx's
own (`rosx.workspace.environment.ROS_ROOT`), which ``rosx shell-init`` exports.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import Environment, ExitStatus
from rosx_commands.roswtf.report import Findings

_RULE = "=" * 80


def _options(env: Environment) -> ToolParser:
    parser = ToolParser(env, "roswtf", "usage: roswtf [launch file]")
    parser.description = (
        "roswtf is a tool for verifying a ROS installation and running system. Checks provided "
        "launchfile if provided, else current stack or package."
    )
    parser.add_option(
        "--all",
        dest="all_packages",
        default=False,
        action="store_true",
        help="run roswtf against all packages",
    )
    parser.add_option(
        "--no-plugins",
        dest="disable_plugins",
        default=False,
        action="store_true",
        help="disable roswtf plugins",
    )
    parser.add_option(
        "--offline",
        dest="offline",
        default=False,
        action="store_true",
        help="only run offline tests",
    )
    return parser


def _package_here(env: Environment) -> str | None:
    from rosx.packages.manifest import package_in  # noqa: PLC0415 - the package index loads only when used
    from rosx_commands.invocation import working_directory  # noqa: PLC0415 - this tool's parts load only when used

    return package_in(working_directory(env))


def _launch_rules(files: list[str], env: Environment, findings: Findings) -> str | None:
    """roswtf's static checks of launch files; the text of a file that cannot be loaded."""
    from rosx.launch.errors import LaunchError  # noqa: PLC0415 - launch code loads only for launch files
    from rosx.launch.loader import load_launch  # noqa: PLC0415 - launch code loads only for launch files
    from rosx.launch.run.command import run_command  # noqa: PLC0415 - launch code loads only for launch files
    from rosx.packages.index import PackageIndex, PackageNotFoundError  # noqa: PLC0415 - the package index loads only when used
    from rosx.workspace.executables import find_executables  # noqa: PLC0415 - workspace code loads only when used

    index = PackageIndex.from_environ(env.environ)
    for file in files:
        try:
            load_launch(
                [file], environ=env.environ, package_index=index, core_params={}, run=run_command
            )
        except LaunchError as error:
            return f"Unable to load roslaunch file [{file}]: {error}"
    plan = load_launch(
        files, environ=env.environ, package_index=index, core_params={}, run=run_command
    )
    missing_packages: list[str] = []
    missing_nodes: list[str] = []
    for node in plan.nodes:
        try:
            directory = index.find(node.package)
        except PackageNotFoundError:
            missing_packages.append(node.package)
            continue
        if not find_executables(directory, node.type).executables:
            missing_nodes.append(f"node [{node.type}] in package [{node.package}]")
    findings.check(
        "warning",
        "Loading your launch files reported the following configuration errors:",
        plan.warnings,
    )
    findings.check("error", "Cannot find the following required packages:", missing_packages)
    findings.check(
        "error",
        "Several nodes in your launch file could not be located. These are either typed "
        "incorrectly or need to be built:",
        missing_nodes,
    )
    return None


def _roswtf(argv: list[str], env: Environment) -> int:
    from rosx.master.defaults import master_uri as uri_of  # noqa: PLC0415 - the master's code loads only to talk to one
    from rosx.workspace.environment import ROS_ROOT  # noqa: PLC0415 - workspace code loads only when used
    from rosx_commands.roswtf import offline  # noqa: PLC0415 - this tool's parts load only when used

    options, files = _options(env).parse(argv)
    environ = env.environ
    ros_root = environ.get("ROS_ROOT") or str(ROS_ROOT)
    if Path(ros_root.rstrip("/")).name not in ("ros", "rosbuild"):
        env.out(f"ROS_ROOT is invalid: ROS_ROOT [{ros_root}] must end in directory named 'ros'")
        return ExitStatus.ERROR
    findings = Findings()
    if files:
        problem = _launch_rules(files, env, findings)
        if problem is not None:
            env.err(problem)
            return ExitStatus.OK
    else:
        package = _package_here(env)
        env.out(
            f"Package: {package}" if package else "No package or stack in the current directory"
        )
        if options.all_packages:
            env.out("roswtf will run against all packages")
    master = uri_of(environ)
    errors_before = list(findings.errors)
    warnings_before = list(findings.warnings)
    findings.clear()
    findings.run(offline.rules(environ, ros_root, master))
    findings.warnings += warnings_before
    findings.errors += errors_before
    env.out(_RULE)
    env.out("Static checks summary:\n")
    findings.print(env)
    findings.clear()
    env.out(_RULE)
    from rosx.master.client import master_is_online  # noqa: PLC0415 - the network only here

    online = not (options.offline or not master or offline.invalid_url(master))
    if not online or not master_is_online(master, "/roswtf", timeout=3.0):
        env.out(
            "\nROS Master does not appear to be running.\nOnline graph checks will not be run.\n"
            f"ROS_MASTER_URI is [{master}]"
        )
        return ExitStatus.OK
    env.out("Beginning tests of your ROS graph. These may take a while...")
    env.stdout.flush()
    from rosx.master.client import MasterUnreachable  # noqa: PLC0415 - the master's code loads only to talk to one
    from rosx_commands.roswtf.online import check_graph  # noqa: PLC0415 - this tool's parts load only when used

    def say(text: str) -> None:
        env.out(text)
        env.stdout.flush()

    try:
        check_graph(master, findings, say, env.err)
    except MasterUnreachable:
        findings.check("error", f"cannot contact ROS Master at {master}", True)
        env.err(f"roswtf lost connection to the ROS Master at {master}")
        env.out("\nAborting checks, partial results summary:\n")
        findings.print(env)
        return ExitStatus.OK
    env.out("\nOnline checks summary:\n")
    findings.print(env)
    return ExitStatus.OK


def roswtf(argv: Sequence[str], env: Environment) -> int:
    """Run ``roswtf ARGV…``."""
    return run_command(_roswtf, list(argv), env)


__all__ = ["roswtf"]
