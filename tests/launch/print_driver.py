"""``roslaunch``'s printing options over `rosx.launch`, for tests until ``rosx roslaunch`` has them.

Usage: ``python print_driver.py --nodes|--files|--dump-params|--ros-args|--args NODE|
--find-node NODE [PKG] FILE... [name:=value...]``. Prints what roslaunch prints; errors go to
stderr with roslaunch's exit status.
"""

from __future__ import annotations

import os
import sys

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
from rosx.packages.index import PackageIndex


def main(argv: list[str]) -> int:
    option, rest = argv[0], argv[1:]
    node = ""
    if option in ("--args", "--find-node"):
        node, rest = rest[0], rest[1:]
    index = PackageIndex.from_environ(os.environ)
    try:
        files, cli_args = resolve_launch_arguments(rest, index)
        plan = load_launch(
            files,
            cli_args,
            os.environ,
            index,
            with_core=option != "--dump-params",
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
            text = node_args_text(plan, node, files, os.environ, index)
        else:
            text = find_node_text(plan, node, files, os.environ)
    except LaunchError as error:
        sys.stderr.write(f"{error}\n")
        return error.status
    sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
