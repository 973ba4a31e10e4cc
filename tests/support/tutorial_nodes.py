"""The tutorial nodes' runs: roslaunch's logs read back, rospy's and roscpp's console lines."""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from tests.support.cli import clean_environ
from tests.support.procs import stop

ROSPY_LINE = r"\[INFO\] \[\d+\.\d+\]: "


ROSCPP_LINE = r"\[ INFO\] \[\d+\.\d{9}\]: "


class Runs:
    """``rosx rosrun`` processes on the test's master, their output in files."""

    def __init__(self, master: str, folder: Path) -> None:
        self.env = clean_environ(ROS_MASTER_URI=master)
        self.folder = folder
        self.count = 0

    def command(self, *argv: str) -> list[str]:
        return [sys.executable, "-m", "rosx_commands", "rosrun", *argv]

    @contextmanager
    def node(self, *argv: str) -> Iterator[Path]:
        """Run ``rosrun ARGV…`` for the block; yields the file its stdout and stderr go to."""
        with self.tool("rosrun", *argv, name=argv[1]) as log:
            yield log

    @contextmanager
    def tool(self, *argv: str, name: str | None = None) -> Iterator[Path]:
        """Run ``rosx ARGV…`` (``roslaunch``, ``rostopic echo``…) for the block; yields the
        file its stdout and stderr go to, named after ``name`` (else the tool)."""
        self.count += 1
        log = self.folder / f"{self.count}-{(name or argv[0]).replace('/', '_')}.log"
        with log.open("w") as out:
            process = subprocess.Popen(
                [sys.executable, "-m", "rosx_commands", *argv],
                env=self.env,
                stdin=subprocess.DEVNULL,
                stdout=out,
                stderr=subprocess.STDOUT,
                start_new_session=True,
            )
            try:
                yield log
            finally:
                stop(process)

    def run(self, *argv: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            self.command(*argv),
            env=self.env,
            capture_output=True,
            text=True,
            timeout=60,
            check=False,
        )


def lines(log: Path) -> list[str]:
    return log.read_text().splitlines()
