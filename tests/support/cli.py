"""Running rosx commands in-process or as the installed console script."""

from __future__ import annotations

import io
import os
import subprocess
import sys
from dataclasses import dataclass

from rosx_commands.context import Environment
from rosx_commands.main import run_tool


@dataclass
class Result:
    status: int
    out: str
    err: str


def rosx(*argv: str, stdin: str = "", environ: dict[str, str] | None = None) -> Result:
    """Run ``rosx ARGV…`` in this process with captured streams and a clean ROS environment."""
    out, err = io.StringIO(), io.StringIO()
    env = Environment(
        stdout=out,
        stderr=err,
        stdin=io.StringIO(stdin),
        environ=clean_environ() if environ is None else environ,
    )
    status = run_tool(list(argv), env)
    return Result(int(status), out.getvalue(), err.getvalue())


def clean_environ(**extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ROS_")}
    env.update(extra)
    return env


def rosx_process(*argv: str, stdin: str = "", timeout: float = 60, **extra: str) -> Result:
    """Run the installed ``rosx`` entry point in a child process."""
    done = subprocess.run(
        [sys.executable, "-c", "from rosx_commands.main import run; run()", *argv],
        input=stdin,
        capture_output=True,
        text=True,
        env=clean_environ(**extra),
        timeout=timeout,
        check=False,
    )
    return Result(done.returncode, done.stdout, done.stderr)
