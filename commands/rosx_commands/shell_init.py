"""``rosx shell-init bash|zsh``: shell functions for ROS 1's command names, roscd and rosls.

``eval "$(rosx shell-init bash)"`` (in ``~/.bashrc`` to keep it) makes ``roscore``, ``rosrun``,
``rostopic``, ``catkin_make``… run rosx's tools, and defines ``roscd`` and ``rosls``, so a lab
sheet's commands can be typed exactly as printed (see `rosx.workspace.shell`).
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.context import Environment, ExitStatus

_USAGE = 'usage: rosx shell-init {bash,zsh,sh}\n\nLoad with:  eval "$(rosx shell-init bash)"'


def shell_init(argv: Sequence[str], env: Environment) -> int:
    """Print the shell code for the shell named in ``argv`` (bash by default)."""
    from rosx.workspace.shell import SHELLS  # noqa: PLC0415
    from rosx.workspace.shell import shell_init as code  # noqa: PLC0415
    from rosx_commands.invocation import self_command  # noqa: PLC0415

    args = list(argv)
    if args and args[0] in ("-h", "--help"):
        env.out(_USAGE)
        return ExitStatus.OK
    shell = args[0] if args else "bash"
    if len(args) > 1 or shell not in SHELLS:
        env.err(_USAGE)
        env.err(f"rosx shell-init: error: unknown shell {shell!r} (one of: {', '.join(SHELLS)})")
        return ExitStatus.USAGE
    env.stdout.write(code(self_command(), shell))
    return ExitStatus.OK
