"""Tab completion of the ROS commands in bash and zsh, as rosbash completes them.

ROS 1's rosbash completes packages (``roscd``, ``rospack``…), a package's executables
(``rosrun``), its files (``rosed``, ``roscp``), launch files (``roslaunch``), and the live
graph's topics, nodes, services and parameters and the message types (``rostopic``,
``rosnode``, ``rosservice``, ``rosparam``, ``rosmsg``…), with a shell function per command.
Here one shell function serves every command: it hands the command line to ``rosx complete``,
which answers with the candidates (NUL-separated, so that a message prototype spanning lines is
one candidate), and adds them. Where rosx has nothing to offer, bash's and zsh's own file-name
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
    < <(_rosx complete "$COMP_CWORD" "${COMP_WORDS[@]}" 2>/dev/null)
}
complete -o nospace -F _rosx_complete roscd rosls
complete -o default -F _rosx_complete {commands}
"""

_ZSH = """\
_rosx_complete() {
  local -a _rosx_c _rosx_dirs _rosx_words
  _rosx_c=(${(0)"$(_rosx complete $((CURRENT - 1)) "${words[@]}" 2>/dev/null)"})
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


def completion(shell: str, commands: tuple[str, ...] = COMPLETED) -> str:
    """The shell code completing ``commands`` in ``shell`` (none for plain ``sh``)."""
    if shell == "bash":
        others = [c for c in commands if c not in ("roscd", "rosls")]
        return _BASH.replace("{commands}", " ".join(others))
    if shell == "zsh":
        return _ZSH.replace("{commands}", " ".join(commands))
    return ""


__all__ = ["COMPLETED", "completion"]
