"""roslaunch's printing options over `rosx.launch`, for tests until ``rosx roslaunch`` has them.

``main(argv, environ)`` takes what follows ``roslaunch`` (``--nodes|--files|--dump-params|
--ros-args|--args NODE|--find-node NODE [PKG] FILE… [name:=value…]``) and returns roslaunch's
exit status, stdout and stderr. Run as a script, it prints them.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Mapping

from rosx.launch import (
    LaunchError,
    dump_params_text,
    files_text,
    find_node_text,
    load_launch,
    node_args_text,
    nodes_text,
    resolve_launch_arguments,
    ros_args_text,
)
from rosx.launch.run.command import run_command
from rosx.packages.index import PackageIndex


def main(argv: list[str], environ: Mapping[str, str]) -> tuple[int, str, str]:
    """``roslaunch ARGV…`` for one printing option: (status, stdout, stderr)."""
    option, rest = argv[0], argv[1:]
    node = ""
    if option in ("--args", "--find-node"):
        node, rest = rest[0], rest[1:]
    index = PackageIndex.from_environ(environ)
    try:
        files, cli_args = resolve_launch_arguments(rest, index)
        plan = load_launch(
            files,
            cli_args,
            environ,
            index,
            with_core=option != "--dump-params",
            run=run_command,
            core_params={},
            args_only=option == "--ros-args",
            argv=rest,
        )
        if option == "--nodes":
            text = nodes_text(plan)
        elif option == "--files":
            text = files_text(plan)
        elif option == "--dump-params":
            text = dump_params_text(plan)
        elif option == "--ros-args":
            text = ros_args_text(plan)
        elif option == "--args":
            text = node_args_text(plan, node, files, environ, index)
        else:
            text = find_node_text(plan, node, files, environ)
    except LaunchError as error:
        return error.status, "", f"{error}\n"
    return 0, text, ""


if __name__ == "__main__":
    status, out, err = main(sys.argv[1:], os.environ)
    sys.stdout.write(out)
    sys.stderr.write(err)
    sys.exit(status)
