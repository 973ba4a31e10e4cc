"""``rosx shell-init bash|zsh``: Noetic's environment, ROS 1's command names, roscd and rosls.

``eval "$(rosx shell-init bash)"`` (in ``~/.bashrc`` to keep it) exports what sourcing Noetic's
``setup.bash`` exports (``ROS_DISTRO``, ``ROS_PACKAGE_PATH``…), makes ``roscore``, ``rosrun``,
``rostopic``, ``catkin_make``… run rosx's tools, defines ``roscd`` and ``rosls`` and adds tab
completion, so a lab sheet's commands can be typed exactly as printed (see
`rosx.workspace.shell`).
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.context import Environment, ExitStatus

_USAGE = 'usage: rosx shell-init {bash,zsh,sh}\n\nLoad with:  eval "$(rosx shell-init bash)"'


def shell_init(argv: Sequence[str], env: Environment) -> int:
    """Print the shell code for the shell named in ``argv`` (bash by default)."""
    from rosx.workspace.shell import ROS_COMMANDS, SHELLS  # noqa: PLC0415
    from rosx.workspace.shell import shell_init as code  # noqa: PLC0415
    from rosx_commands.invocation import self_command  # noqa: PLC0415
    from rosx_commands.main import TOOLS  # noqa: PLC0415

    args = list(argv)
    if args and args[0] in ("-h", "--help"):
        env.out(_USAGE)
        return ExitStatus.OK
    shell = args[0] if args else "bash"
    if len(args) > 1 or shell not in SHELLS:
        env.err(_USAGE)
        env.err(f"rosx shell-init: error: unknown shell {shell!r} (one of: {', '.join(SHELLS)})")
        return ExitStatus.USAGE
    commands = [name for name in ROS_COMMANDS if name in TOOLS]
    env.stdout.write(code(self_command(), shell, commands))
    return ExitStatus.OK
