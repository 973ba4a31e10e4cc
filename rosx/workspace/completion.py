"""Tab completion of the ROS commands in bash and zsh, as rosbash completes them.

ROS 1's rosbash completes packages (``roscd``, ``rospack``…), a package's executables
(``rosrun``), its files (``rosed``, ``roscp``), launch files (``roslaunch``), and the live
graph's topics, nodes, services and parameters and the message types (``rostopic``,
``rosnode``, ``rosservice``, ``rosparam``, ``rosmsg``…), with a shell function per command.
Here one shell function serves every command: it hands the command line to ``rosx complete``,
which answers with the candidates (NUL-separated, so that a message prototype spanning lines is
one candidate), and adds them. The caller says how the shell runs it: ``rosx_commands`` gives a
Python started for it alone, which answers package names in a few milliseconds more than the
``stat`` calls that keep them fresh. Where rosx has nothing to offer, bash's and zsh's own file-name
completion take over (a destination of ``roscp``, a YAML file of ``rosparam load``), as
rosbash's do; ``roscd`` and ``rosls`` complete ``package/sub/dir/`` without a trailing space.
"""

from __future__ import annotations

#: The commands completed (with ``rosx`` itself); `completion` registers those of them given.
COMPLETED = (
    "roscd",
    "rosls",
    "rosed",
    "roscp",
    "rosrun",
    "roslaunch",
    "rospack",
    "rosnode",
    "rostopic",
    "rosservice",
    "rosparam",
    "rosmsg",
    "rossrv",
    "rosbag",
    "roswtf",
    "rosversion",
    "rosclean",
    "rosmsg-proto",
    "rossrv-proto",
    "catkin_create_pkg",
    "rosx",
)

_BASH = """\
_rosx_complete() {
  local _rosx_c
  COMPREPLY=()
  while IFS= read -r -d '' _rosx_c; do COMPREPLY+=("$_rosx_c"); done \\
    < <({complete} "$COMP_CWORD" "${COMP_WORDS[@]}" 2>/dev/null)
}
complete -o nospace -F _rosx_complete roscd rosls
complete -o default -F _rosx_complete {commands}
"""

_ZSH = """\
_rosx_complete() {
  local -a _rosx_c _rosx_dirs _rosx_words
  _rosx_c=(${(0)"$({complete} $((CURRENT - 1)) "${words[@]}" 2>/dev/null)"})
  _rosx_dirs=(${(M)_rosx_c:#*/})
  _rosx_words=(${_rosx_c:#*/})
  (( ${#_rosx_dirs} )) && compadd -Q -S '' -- "${_rosx_dirs[@]}"
  (( ${#_rosx_words} )) && compadd -Q -- "${_rosx_words[@]}"
  if (( ! ${#_rosx_c} )) && [[ $words[1] != roscd && $words[1] != rosls ]]; then
    _files
  fi
}
if (( $+functions[compdef] )); then
  compdef _rosx_complete {commands}
fi
"""


#: How the shell functions run ``rosx complete`` when not told: through ``rosx``'s own
#: function (`rosx.workspace.shell.navigation_functions`).
DEFAULT_COMPLETE = "_rosx complete"


def completion(
    shell: str, commands: tuple[str, ...] = COMPLETED, complete: str | None = None
) -> str:
    """The shell code completing ``commands`` in ``shell`` (none for plain ``sh``), running
    ``rosx complete`` as the shell words ``complete`` (`DEFAULT_COMPLETE` if None)."""
    if shell == "bash":
        others = [c for c in commands if c not in ("roscd", "rosls")]
        code = _BASH.replace("{commands}", " ".join(others))
    elif shell == "zsh":
        code = _ZSH.replace("{commands}", " ".join(commands))
    else:
        return ""
    return code.replace("{complete}", complete or DEFAULT_COMPLETE)


__all__ = ["COMPLETED", "DEFAULT_COMPLETE", "completion"]
