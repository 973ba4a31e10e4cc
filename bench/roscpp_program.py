"""The roscpp (C++) workers of the benches: `bench/cpp/bench_node.cpp`, compiled at bench time.

`build` compiles a source (this one, or a roscpp node of the interop tests) against Debian's
``libroscpp-dev`` (``pkg-config roscpp``) and the message headers of ``libgeometry-msgs-dev``
and ``libsensor-msgs-dev``, once: the binary is kept in ``$XDG_CACHE_HOME/rosx-bench`` (else
``~/.cache/rosx-bench``), in a folder named after a checksum of the source and of the
compiler's command, so a changed source or library is built again. Where a compiler, roscpp or
a header is missing, `program` says so in one line, ``skipped: roscpp: …``, and returns None;
the benches then run without the C++ side (tests skip with the same reason).
"""

from __future__ import annotations

import functools
import hashlib
import os
import shutil
import subprocess
import sys
from pathlib import Path

SOURCE = Path(__file__).resolve().parent / "cpp" / "bench_node.cpp"

#: The headers the workers include, and the Debian package of each.
HEADERS = {
    "ros/ros.h": "libroscpp-dev",
    "std_msgs/Header.h": "libstd-msgs-dev",
    "geometry_msgs/Twist.h": "libgeometry-msgs-dev",
    "sensor_msgs/Image.h": "libsensor-msgs-dev",
    "sensor_msgs/PointCloud2.h": "libsensor-msgs-dev",
}

#: Optimized as Debian builds roscpp itself.
FLAGS = ["-O2", "-std=c++17", "-DNDEBUG"]


def _flags(*args: str) -> list[str] | None:
    done = subprocess.run(
        ["pkg-config", *args, "roscpp"], capture_output=True, text=True, check=False
    )
    return done.stdout.split() if done.returncode == 0 else None


@functools.cache
def build(source: Path) -> Path | str:
    """``source`` (a C++ file including `HEADERS` at most) compiled against roscpp, built now
    if needed; or why it cannot be, in a few words."""
    compiler = shutil.which("c++") or shutil.which("g++")
    if compiler is None:
        return "no C++ compiler (apt-get install g++)"
    if shutil.which("pkg-config") is None:
        return "no pkg-config (apt-get install pkg-config)"
    cflags, libs = _flags("--cflags"), _flags("--libs")
    if cflags is None or libs is None:
        return "pkg-config does not know roscpp (apt-get install libroscpp-dev)"
    include = [Path(flag[2:]) for flag in cflags if flag.startswith("-I")] + [Path("/usr/include")]
    for header, package in HEADERS.items():
        if not any((folder / header).is_file() for folder in include):
            return f"no {header} (apt-get install {package})"
    made_of = "\0".join([compiler, *FLAGS, *cflags, *libs]).encode() + source.read_bytes()
    key = hashlib.sha256(made_of).hexdigest()[:12]
    cache = os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache")  # noqa: PTH111
    binary = Path(cache, "rosx-bench", f"roscpp-{key}", source.stem)
    if binary.is_file():
        return binary
    binary.parent.mkdir(parents=True, exist_ok=True)
    print(f"(compiling {source.name} against roscpp into {binary.parent})", file=sys.stderr)
    partial = binary.with_suffix(".partial")
    done = subprocess.run(
        [compiler, *FLAGS, *cflags, str(source), "-o", str(partial), *libs],
        capture_output=True,
        text=True,
        check=False,
    )
    if done.returncode != 0:
        first = next((line for line in done.stderr.splitlines() if "error" in line), "")
        return f"{source.name} did not compile: {first or done.stderr.strip()[:200]}"
    partial.replace(binary)
    return binary


@functools.cache
def program() -> Path | None:
    """The benches' compiled worker (`SOURCE`), or None where it cannot be built: then it says
    why, once, in one line ``skipped: roscpp: …``."""
    built = build(SOURCE)
    if isinstance(built, str):
        print(f"skipped: roscpp: {built}", file=sys.stderr, flush=True)
        return None
    return built
