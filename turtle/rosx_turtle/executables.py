"""``python -m rosx_turtle [PACKAGE/]NAME [ARGS…]``: run one of the programs rosx ships.

The programs are the files rosrun and roslaunch start (`rosx.workspace.programs`): turtlesim's
in rosx's ``lib/turtlesim``, roscpp_tutorials' in ``lib/roscpp_tutorials``. ``NAME``
alone is turtlesim's (``python -m rosx_turtle turtlesim_node __name:=sim``), another package's
is named with it (``python -m rosx_turtle roscpp_tutorials/talker``).
"""

from __future__ import annotations

import runpy
import sys
from typing import TYPE_CHECKING

from rosx.workspace.programs import bundled_program, program_names

if TYPE_CHECKING:
    from collections.abc import Sequence

_OTHERS = ("roscpp_tutorials",)


def main(argv: Sequence[str] | None = None) -> int:
    """Run ``argv[0]`` with the rest of ``argv``; 2 with a usage line when there is none."""
    argv = list(sys.argv[1:] if argv is None else argv)
    package, _, name = argv[0].rpartition("/") if argv else ("", "", "")
    program = bundled_program(package or "turtlesim", name) if name else None
    if program is None:
        names = program_names("turtlesim")
        names += [f"{other}/{n}" for other in _OTHERS for n in program_names(other)]
        print(
            f"usage: python -m rosx_turtle EXECUTABLE [ARGS...]  (one of: {', '.join(names)})",
            file=sys.stderr,
        )
        return 2
    sys.argv = [str(program), *argv[1:]]
    try:
        runpy.run_path(str(program), run_name="__main__")
    except SystemExit as done:
        if done.code is None or isinstance(done.code, int):
            return done.code or 0
        print(done.code, file=sys.stderr)
        return 1
    return 0
