"""Running the command of a ``<param command="…">`` while a launch file is read, as roslaunch
does: the command line to its end, its standard output the parameter's text.

The plan (`rosx.launch.loader`) runs no process itself; whoever loads a plan for real passes
`run_command` as ``load_launch(run=…)``.
"""

from __future__ import annotations

import subprocess


def run_command(argv: list[str]) -> tuple[int, str]:
    """Run ``argv`` to its end; its exit code and standard output (UTF-8, errors replaced).

    Raises:
        OSError: it cannot be started (`FileNotFoundError` for a missing program).
    """
    done = subprocess.run(argv, stdout=subprocess.PIPE, check=False)
    return done.returncode, done.stdout.decode("utf-8", errors="replace")


__all__ = ["run_command"]
