"""Running rosx commands in-process or as the installed console script."""

from __future__ import annotations

import contextlib
import io
import os
import subprocess
import sys
from collections.abc import Iterator
from dataclasses import dataclass

from rosx_commands.context import Environment
from rosx_commands.main import run_tool

#: The ``rosx`` command as the installed entry point runs it, with this interpreter.
ROSX_COMMAND = [sys.executable, "-c", "from rosx_commands.main import run; run()"]


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
        [*ROSX_COMMAND, *argv],
        input=stdin,
        capture_output=True,
        text=True,
        env=clean_environ(**extra),
        timeout=timeout,
        check=False,
    )
    return Result(done.returncode, done.stdout, done.stderr)


@contextlib.contextmanager
def rosx_popen(*argv: str, **extra: str) -> Iterator[subprocess.Popen[str]]:
    """``rosx ARGV…`` as a child process for the duration of the block (a clean ROS environment
    plus ``extra``), its output and errors piped as text; killed at the end if still running."""
    process = subprocess.Popen(
        [*ROSX_COMMAND, *argv],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=clean_environ(**extra),
    )
    try:
        yield process
    finally:
        if process.poll() is None:
            process.kill()
        process.wait()
