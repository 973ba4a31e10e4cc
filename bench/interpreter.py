"""The Python that runs rosx in the benchmarks that compare it with ROS 1.

Two builds of one CPython version differ in speed by themselves. Debian's ``python3.11``, which
runs rospy and ROS 1's tools, is one static binary built with profile-guided and link-time
optimization; a Python built by pyenv (this machine's 3.11.7) links ``libpython`` as a shared
library, without either, and runs the same code at about half the speed (`bench_codec.py`: a
Twist serialized by rosx in 0.51 µs there, 0.27 µs on Debian's). So by default rosx runs on
ROS 1's own interpreter, in a virtual environment made from it with this checkout installed
(editable, with the test extras some benches import), as pipx installs rosx on Debian and
Ubuntu: the figures then compare the libraries, not the interpreters.

``--python current`` keeps the Python the bench was started with; ``--python PATH`` names one.
The environment is kept in ``$XDG_CACHE_HOME/rosx-bench`` (else ``~/.cache/rosx-bench``) and
made again for another checkout, interpreter or ``pyproject.toml``.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
ROS1_PYTHON = os.environ.get("ROS1_PYTHON", "/usr/bin/python3")

#: Set in the environment of the bench once it runs on the chosen Python (so it is chosen once).
_CHOSEN = "ROSX_BENCH_PYTHON"


def add_option(parser: argparse.ArgumentParser) -> None:
    """The ``--python`` option of a bench."""
    parser.add_argument(
        "--python",
        default="ros1",
        metavar="ros1|current|PATH",
        help="the Python that runs rosx: ROS 1's own interpreter in a virtual environment"
        " of this checkout (default), this one, or the one at PATH",
    )


def run_on(choice: str) -> None:
    """Run this bench again, with the same arguments, on the Python ``choice`` names (see
    `add_option`), unless it already runs on it, where it prints which Pythons run rosx and
    ROS 1; rosx's workers then use ``sys.executable``."""
    if os.environ.get(_CHOSEN) != choice:
        os.environ[_CHOSEN] = choice
        python = sys.executable if choice == "current" else choice
        if choice == "ros1":
            if Path(ROS1_PYTHON).exists():
                python = str(_environment(ROS1_PYTHON))
            else:
                python = sys.executable
                print(f"({ROS1_PYTHON} not found: rosx runs on this Python)", file=sys.stderr)
        if python != sys.executable:
            os.execv(python, [python, *sys.argv])
    ros1 = _version(ROS1_PYTHON) if Path(ROS1_PYTHON).exists() else "absent"
    mine = f"Python {sys.version.split()[0]} ({sys.executable})"
    print(f"rosx on {mine}; ROS 1 on {ros1}", flush=True)


def _version(python: str) -> str:
    done = subprocess.run(
        [python, "-c", "import sys; print(sys.version.split()[0])"],
        capture_output=True,
        text=True,
        check=True,
    )
    return f"Python {done.stdout.strip()} ({os.path.realpath(python)})"


def _environment(base: str) -> Path:
    """A virtual environment made from ``base`` with this checkout installed; made once."""
    # Another interpreter, checkout or list of dependencies: another environment.
    made_of = (
        f"{os.path.realpath(base)}\0{ROOT}\0".encode() + (ROOT / "pyproject.toml").read_bytes()
    )
    key = hashlib.sha256(made_of).hexdigest()[:12]
    cache = os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache")  # noqa: PTH111
    venv = Path(cache, "rosx-bench", f"venv-{key}")
    python = venv / "bin" / "python"
    mine = str(ROOT / "rosx" / "__init__.py")
    probe = [str(python), "-c", f"import rosx, pytest, sys; sys.exit(rosx.__file__ != {mine!r})"]
    if python.exists():
        found = subprocess.run(probe, capture_output=True, cwd="/", check=False)
        if found.returncode == 0:
            return python
    print(f"(making a virtual environment of {base} with rosx in {venv})", file=sys.stderr)
    for step in (
        [base, "-m", "venv", "--clear", str(venv)],
        [str(python), "-m", "pip", "install", "-q", "-e", f"{ROOT}[test]"],
    ):
        done = subprocess.run(step, capture_output=True, text=True, check=False)
        if done.returncode != 0:
            raise SystemExit(f"{' '.join(step)} failed:\n{done.stdout}{done.stderr}")
    return python
