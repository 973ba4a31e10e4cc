"""``rosx run-script FILE [ARGS…]``: run a ROS Python script with rosx's rospy and messages.

What ``rosx rosrun`` runs Python scripts with; usable alone for a script outside any package
(see `rosx.client.script`).
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.context import Environment, ExitStatus

_USAGE = "usage: rosx run-script FILE [ARGS...]"


def run_script(argv: Sequence[str], env: Environment) -> int:
    """Run the script named by ``argv[0]`` with the rest of ``argv``."""
    args = list(argv)
    if not args or args[0] in ("-h", "--help"):
        (env.stdout if args else env.stderr).write(_USAGE + "\n")
        return ExitStatus.OK if args else ExitStatus.USAGE
    from rosx.client.script import run_script as run  # noqa: PLC0415 - the rospy API loads only when used
    from rosx_commands.scripts import shim_dirs  # noqa: PLC0415 - this tool's parts load only when used

    return run(args[0], args[1:], stderr=env.stderr, shim_dirs=shim_dirs())
