"""Shell code: what ``rosx shell-init`` prints and a workspace's ``devel/setup.*`` files.

A process cannot change its shell's directory, so ``roscd`` (and ``rosls``) are shell functions,
as in ROS 1 (rosbash defines them when a ROS setup file is sourced). They ask rosx where to go
(``rosx roscd --where TARGET``) and go there. A ``rosx`` function sends ``rosx roscd`` and
``rosx rosls`` to them, so the commands of a lab sheet work with ``rosx`` in front too.

`shell_init` makes ROS 1's command names (``roscore``, ``rosrun``, ``rostopic``…) run rosx's
tools, so commands can be typed as ROS 1 prints them. As in ROS 1 they are programs on ``PATH``
(written by `rosx.workspace.path_commands`), so ``timeout``, ``watch``, ``xargs``, ``nohup`` and
scripts run them too; where that folder cannot be written, they are shell functions instead.
A workspace's setup files (`setup_sh`) give what Noetic's give, since a workspace's
``devel/setup.bash`` chains to ``/opt/ros/noetic/setup.bash``: the environment, ``roscd`` and
``rosls``, and ROS 1's command names (the programs ``catkin_make`` writes in the space's
``bin/``) in front of ``PATH``, so ``roscore`` is rosx's in a terminal that sourced it, even on a
machine where a system's ROS 1 is installed too.

Everything is POSIX sh that bash and zsh also run. For bash and zsh, tab completion of every
ROS command (`rosx.workspace.completion`) comes with it, and ``rosx shell-init`` and the setup
files export Noetic's environment (`rosx.workspace.environment`).
"""

from __future__ import annotations

import shlex
from typing import TYPE_CHECKING

from rosx.workspace.completion import completion
from rosx.workspace.environment import base_exports, prepend_path

if TYPE_CHECKING:
    from collections.abc import Sequence

#: ROS 1 command names that `shell_init` makes run rosx's tools (those of them that rosx has:
#: the caller passes which).
ROS_COMMANDS = (
    "roscore",
    "rosrun",
    "roslaunch",
    "rostopic",
    "rosnode",
    "rosmsg",
    "rossrv",
    "rosservice",
    "rosparam",
    "rospack",
    "rosbag",
    "rosed",
    "roscp",
    "roswtf",
    "rosversion",
    "rosclean",
    "rosmsg-proto",
    "rossrv-proto",
    "catkin_make",
    "catkin_create_pkg",
    "rqt_graph",
    "rqt_console",
    "rqt_logger_level",
    "rqt_plot",
    "rqt_topic",
    "rqt",
)

SHELLS = ("bash", "zsh", "sh")

_NAVIGATION = """\
_rosx() { {rosx} "$@"; }
rosx() {
  case "$1" in
    roscd|rosls) _rosx_verb="$1"; shift; "$_rosx_verb" "$@" ;;
    *) _rosx "$@" ;;
  esac
}
roscd() {
  _rosx_dir="$(_rosx roscd --where "$@")" || return $?
  if [ -n "$_rosx_dir" ]; then cd "$_rosx_dir" || return $?; fi
}
rosls() {
  _rosx_dir="$(_rosx roscd --where "$@")" || return $?
  if [ -n "$_rosx_dir" ]; then ls "$_rosx_dir"; fi
}
"""


def rosx_command(argv: Sequence[str]) -> str:
    """How the shell runs rosx: ``argv`` quoted for the shell."""
    return " ".join(shlex.quote(arg) for arg in argv)


def navigation_functions(rosx: str, shell: str = "sh", complete: str | None = None) -> str:
    """``roscd``, ``rosls`` and the ``rosx`` function, running rosx as ``rosx``; with the
    completion of every ROS command for bash and zsh (running ``rosx complete`` as
    ``complete``, `rosx.workspace.completion.completion`)."""
    return _NAVIGATION.replace("{rosx}", rosx) + completion(shell, complete=complete)


def _command_function(name: str) -> str:
    return f'{name}() {{ _rosx {name} "$@"; }}\n'


def shell_init(
    rosx: str,
    shell: str,
    commands: Sequence[str] = ROS_COMMANDS,
    folder: str | None = None,
    complete: str | None = None,
) -> str:
    """What ``eval "$(rosx shell-init SHELL)"`` runs: Noetic's environment (`base_exports`),
    ``roscd``/``rosls``, ROS 1's command names of ``commands``, completion.

    Args:
        rosx: how the shell runs rosx.
        shell: ``bash``, ``zsh`` or ``sh``.
        commands: the ROS 1 command names to provide.
        folder: the folder holding a program per name of ``commands``
            (`rosx.workspace.path_commands`), put in front of ``PATH`` once; None: no such
            folder, the names become shell functions.
        complete: how a <TAB> runs ``rosx complete`` (`rosx.workspace.completion.completion`).
    """
    head = (
        f"# rosx shell integration for {shell}: Noetic's environment, ROS 1's command names,\n"
        "# roscd, rosls and tab completion.\n"
        f'# Load it with:  eval "$(rosx shell-init {shell})"\n'
    )
    names = _command_names(shell, commands, folder)
    handler = not_found_handler(shell, commands)
    navigation = navigation_functions(rosx, shell, complete)
    return head + base_exports() + navigation + names + handler


def _command_names(shell: str, commands: Sequence[str], folder: str | None) -> str:
    if folder is not None:
        return _command_programs(commands, folder)
    # POSIX sh allows no "-" in a function's name; bash and zsh do.
    names = [n for n in commands if shell != "sh" or "-" not in n]
    return "".join(_command_function(name) for name in names)


def _command_programs(commands: Sequence[str], folder: str) -> str:
    """``folder`` (a program per name of ``commands``) in front of ``PATH``, once."""
    # Functions of an earlier shell-init in this shell would hide the programs, and a shell
    # remembers where it found a name before (bash's hash table).
    return (
        f"unset -f {' '.join(commands)} 2>/dev/null || :\n"
        + _front_of_path(folder)
        + "hash -r 2>/dev/null || :\n"
    )


_FRONT_OF_PATH = """\
_rosx_p=":${PATH:-}:"
while :; do
  case "$_rosx_p" in
    *:"$_rosx_bin":*) _rosx_p="${_rosx_p%%:"$_rosx_bin":*}:${_rosx_p#*:"$_rosx_bin":}" ;;
    *) break ;;
  esac
done
_rosx_p="${_rosx_p#:}"; _rosx_p="${_rosx_p%:}"
PATH="$_rosx_bin${_rosx_p:+:$_rosx_p}"; export PATH
unset _rosx_p _rosx_bin
"""


def _front_of_path(folder: str) -> str:
    """``folder`` first on ``PATH``, taken out of where it was (a ROS 1 setup file sourced
    since may have put its own ``bin`` in front of it)."""
    return f"_rosx_bin={shlex.quote(folder)}\n" + _FRONT_OF_PATH


def setup_sh(
    *, source: str, devel: str, shims: Sequence[str], rosx: str, commands: Sequence[str] = ()
) -> str:
    """A workspace's ``setup.sh`` (devel or install space): Noetic's environment with the
    workspace's packages (``source``) in front, their Python imports, roscd and rosls, and
    ROS 1's command names.

    Args:
        source: where the workspace's packages are (``src`` for devel, ``install/share``).
        devel: the space itself (``devel`` or ``install``).
        shims: the folders of rosx's ``rospy`` and message modules, first one first on
            ``PYTHONPATH``; the space's ``lib/python3/dist-packages`` (the packages' own
            modules, ``catkin_python_setup()``) goes in front of them when it exists.
        rosx: how the shell runs rosx.
        commands: the command names whose programs are in the space's ``bin/``, put in front
            of ``PATH``.
    """
    return (
        "# generated by rosx catkin_make: use this workspace's packages in this shell\n"
        + base_exports()
        + prepend_path("ROS_PACKAGE_PATH", source)
        + prepend_path("CMAKE_PREFIX_PATH", devel)
        + "".join(prepend_path("PYTHONPATH", shim) for shim in reversed(shims))
        + _python_folder(f"{devel}/lib/python3/dist-packages")
        + f"export ROSLISP_PACKAGE_DIRECTORIES={shlex.quote(devel + '/share/common-lisp')}\n"
        + navigation_functions(rosx)
        + (_command_programs(commands, f"{devel}/bin") if commands else "")
    )


def _python_folder(folder: str) -> str:
    """``folder`` in front of ``PYTHONPATH`` when it exists as the file is sourced (as catkin's
    setup does: roswtf names a ``PYTHONPATH`` entry that is no folder)."""
    return f"if [ -d {shlex.quote(folder)} ]; then\n{prepend_path('PYTHONPATH', folder)}fi\n"


def setup_for_shell(
    shell: str, devel: str, rosx: str, commands: Sequence[str] = (), complete: str | None = None
) -> str:
    """``setup.bash`` or ``setup.zsh`` of a space: ``setup.sh`` plus completion (running
    ``rosx complete`` as ``complete``) and the hint for command names typed with spaces
    (`not_found_handler`)."""
    head = f"# generated by rosx catkin_make: use this workspace's packages in {shell}\n"
    return (
        head
        + f". {shlex.quote(devel + '/setup.sh')}\n"
        + completion(shell, complete=complete)
        + not_found_handler(shell, commands)
    )


#: ``_rosx_joined WORD…``: the command that the first words make joined with ``_`` or with
#: nothing (the longest of ``$_rosx_names``; `rosx.names.typos.joined`), with the other words;
#: nothing when they make none.
_JOINED = """\
_rosx_joined() {
  _rosx_try="$1"; _rosx_glued="$1"; _rosx_best=""; _rosx_n=0; _rosx_at=0
  shift
  for _rosx_w in "$@"; do
    _rosx_try="${_rosx_try}_$_rosx_w"; _rosx_glued="$_rosx_glued$_rosx_w"
    _rosx_at=$((_rosx_at + 1))
    case " $_rosx_names " in
      *" $_rosx_try "*) _rosx_best="$_rosx_try"; _rosx_n=$_rosx_at ;;
      *" $_rosx_glued "*) _rosx_best="$_rosx_glued"; _rosx_n=$_rosx_at ;;
    esac
  done
  if [ -n "$_rosx_best" ]; then
    shift "$_rosx_n"
    printf '[rosx] Did you mean %s? (%s)\\n' "$_rosx_best" "$_rosx_best${*:+ $*}"
  fi
}
"""

_NOT_FOUND_BASH = """\
if declare -F command_not_found_handle >/dev/null \\
    && ! declare -f command_not_found_handle | grep -q _rosx_joined; then
  eval "_rosx_next_not_found() $(declare -f command_not_found_handle | tail -n +2)"
fi
command_not_found_handle() {
  _rosx_meant="$(_rosx_joined "$@")"
  if declare -F _rosx_next_not_found >/dev/null; then
    _rosx_next_not_found "$@"
  else
    printf 'bash: %s: command not found\\n' "$1" >&2
  fi
  if [ -n "$_rosx_meant" ]; then printf '%s\\n' "$_rosx_meant" >&2; fi
  return 127
}
"""

_NOT_FOUND_ZSH = """\
if (( $+functions[command_not_found_handler] )) \\
    && [[ $functions[command_not_found_handler] != *_rosx_joined* ]]; then
  functions[_rosx_next_not_found]=$functions[command_not_found_handler]
fi
command_not_found_handler() {
  local _rosx_meant="$(_rosx_joined "$@")"
  if (( $+functions[_rosx_next_not_found] )); then
    _rosx_next_not_found "$@"
  else
    print -u2 -r -- "zsh: command not found: $1"
  fi
  if [[ -n $_rosx_meant ]]; then print -u2 -r -- "$_rosx_meant"; fi
  return 127
}
"""


def not_found_handler(shell: str, commands: Sequence[str]) -> str:
    """bash's and zsh's handler of a command not found: the shell's own words (or those of
    the handler it had, such as a distribution's ``command-not-found``), then, when the words
    typed make one of ``commands`` joined with ``_`` (``catkin make``), the command meant."""
    if shell not in ("bash", "zsh") or not commands:
        return ""
    names = f"_rosx_names={shlex.quote(' '.join(['rosx', *commands]))}\n"
    return names + _JOINED + (_NOT_FOUND_BASH if shell == "bash" else _NOT_FOUND_ZSH)


__all__ = [
    "ROS_COMMANDS",
    "SHELLS",
    "navigation_functions",
    "not_found_handler",
    "rosx_command",
    "setup_for_shell",
    "setup_sh",
    "shell_init",
]
