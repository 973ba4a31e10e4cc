"""``rosx shell-init bash|zsh``: Noetic's environment, ROS 1's command names, roscd and rosls.

``eval "$(rosx shell-init bash)"`` (in ``~/.bashrc`` to keep it) exports what sourcing Noetic's
``setup.bash`` exports (``ROS_DISTRO``, ``ROS_PACKAGE_PATH``…), makes ``roscore``, ``rosrun``,
``rostopic``, ``catkin_make``… run rosx's tools, defines ``roscd`` and ``rosls`` and adds tab
completion, so a lab sheet's commands can be typed exactly as printed (see
`rosx.workspace.shell`). The command names are small programs in the user's cache folder, put
on ``PATH`` (`rosx.workspace.path_commands`); where they cannot be written, shell functions,
with a note on stderr.
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
    from rosx_commands.tools import TOOLS  # noqa: PLC0415

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
    rosx = self_command()
    folder = _written_folder(env, rosx, commands)
    env.stdout.write(code(rosx, shell, commands, folder))
    return ExitStatus.OK


def _written_folder(env: Environment, rosx: str, commands: Sequence[str]) -> str | None:
    """The folder of the command programs, written; None (with a note) where it cannot be."""
    from rosx.workspace.path_commands import command_folder, write_commands  # noqa: PLC0415

    folder = command_folder(env.environ, rosx)
    if folder is None:
        env.err(
            "rosx shell-init: no cache folder (set HOME or XDG_CACHE_HOME); "
            "ROS commands are shell functions in this shell"
        )
        return None
    try:
        write_commands(folder, rosx, commands)
    except OSError as error:
        env.err(
            f"rosx shell-init: cannot write {folder} ({error.strerror or error}); "
            "ROS commands are shell functions in this shell"
        )
        return None
    return str(folder)
