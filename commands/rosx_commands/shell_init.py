"""``rosx shell-init bash|zsh``: Noetic's environment, ROS 1's command names, roscd and rosls.

``eval "$(rosx shell-init bash)"`` exports what sourcing Noetic's ``setup.bash`` exports
(``ROS_DISTRO``, ``ROS_PACKAGE_PATH``…), makes ``roscore``, ``rosrun``, ``rostopic``,
``catkin_make``… run rosx's tools, defines ``roscd`` and ``rosls`` and adds tab completion, so a
lab sheet's commands can be typed exactly as printed (see `rosx.workspace.shell`). The command
names are small programs in the user's cache folder, put in front of ``PATH``
(`rosx.workspace.path_commands`); where they cannot be written, shell functions, with a note
on stderr.

``rosx shell-init --install [bash|zsh]`` makes every new terminal ready: it adds that line
to ``~/.bashrc`` (``~/.zshrc``; the shell of ``$SHELL`` by default) once, marked as rosx's, and
replaces a line it added before (of another rosx install, say) rather than adding a second.
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.context import Environment, ExitStatus

_USAGE = (
    "usage: rosx shell-init {bash,zsh,sh}\n"
    "       rosx shell-init --install [bash|zsh]\n\n"
    'Load with:  eval "$(rosx shell-init bash)"\n'
    "Every new terminal:  rosx shell-init --install"
)
#: Ends the line ``--install`` writes, so that it is found again.
_MARK = "# rosx: ROS 1's command names in every terminal"


def shell_init(argv: Sequence[str], env: Environment) -> int:
    """Print the shell code for the shell named in ``argv`` (bash by default)."""
    from rosx.workspace.shell import ROS_COMMANDS, SHELLS  # noqa: PLC0415 - workspace code loads only when used
    from rosx.workspace.shell import shell_init as code  # noqa: PLC0415 - workspace code loads only when used
    from rosx_commands.invocation import complete_command, self_command  # noqa: PLC0415 - this tool's parts load only when used
    from rosx_commands.tools import TOOLS  # noqa: PLC0415 - this tool's parts load only when used

    args = list(argv)
    if args and args[0] in ("-h", "--help"):
        env.out(_USAGE)
        return ExitStatus.OK
    if args and args[0] == "--install":
        return _install(args[1:], env)
    shell = args[0] if args else "bash"
    if len(args) > 1 or shell not in SHELLS:
        env.err(_USAGE)
        env.err(f"rosx shell-init: error: unknown shell {shell!r} (one of: {', '.join(SHELLS)})")
        return ExitStatus.USAGE
    commands = [name for name in ROS_COMMANDS if name in TOOLS]
    rosx = self_command()
    folder = _written_folder(env, rosx, commands)
    env.stdout.write(code(rosx, shell, commands, folder, complete_command()))
    return ExitStatus.OK


def _written_folder(env: Environment, rosx: str, commands: Sequence[str]) -> str | None:
    """The folder of the command programs, written; None (with a note) where it cannot be."""
    from rosx.workspace.path_commands import command_folder, write_commands  # noqa: PLC0415 - workspace code loads only when used

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


def _install(args: list[str], env: Environment) -> int:
    """Add (or renew) the shell-init line of the user's shell's start-up file."""
    from pathlib import Path  # noqa: PLC0415 - --install only

    from rosx_commands.invocation import self_command  # noqa: PLC0415 - --install only

    default = Path(env.environ.get("SHELL", "bash")).name
    shell = args[0] if args else (default if default in ("bash", "zsh") else "bash")
    if len(args) > 1 or shell not in ("bash", "zsh"):
        env.err(_USAGE)
        env.err(f"rosx shell-init: error: --install knows bash and zsh, not {shell!r}")
        return ExitStatus.USAGE
    home = env.environ.get("HOME")
    if not home:
        env.err("rosx shell-init: no HOME: set it to install the line")
        return ExitStatus.ERROR
    folder = env.environ.get("ZDOTDIR", home) if shell == "zsh" else home
    startup = Path(folder) / f".{shell}rc"
    line = f'eval "$({self_command()} shell-init {shell})"  {_MARK}'
    try:
        old = startup.read_text(encoding="utf-8") if startup.exists() else ""
        lines = old.splitlines()
        if line in lines:
            env.out(f"rosx shell-init: {startup} already has the line; open a new terminal")
            return ExitStatus.OK
        kept = [existing for existing in lines if not existing.endswith(_MARK)]
        text = "\n".join([*kept, line]) + "\n"
        startup.write_text(text, encoding="utf-8")
    except OSError as error:
        env.err(f"rosx shell-init: cannot write {startup}: {error.strerror or error}")
        return ExitStatus.ERROR
    env.out(f"rosx shell-init: added to {startup}:\n  {line}")
    env.out(
        "Every new terminal now has roscore, rosrun, rostopic, roscd… (rosx's). "
        f"In this one: source {startup}"
    )
    return ExitStatus.OK
