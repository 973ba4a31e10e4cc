"""``catkin_python_setup()``: a package's own Python modules and scripts, as catkin lays them out.

A package whose ``CMakeLists.txt`` calls ``catkin_python_setup()`` declares its Python in
``setup.py`` (`rosx.workspace.setup_py` reads it). Where catkin puts them, rosx does:

* each top-level package of ``packages`` gets ``devel/lib/python3/dist-packages/PKG/__init__.py``,
  which adds the package's folder in the source space to the package's ``__path__`` and runs the
  source's ``__init__.py``: ``import PKG.module`` reads the source, so an edit needs no rebuild;
* each top-level module of ``py_modules`` gets a ``PKG.py`` there that runs the source's file;
* each script of ``scripts`` gets ``devel/bin/NAME``, which runs the source's script (a Python
  script with rosx's ``rospy``, through ``rosx run-script``).

The devel space's ``setup.sh`` puts ``devel/lib/python3/dist-packages`` on ``PYTHONPATH`` and
``devel/bin`` on ``PATH``. ``catkin_make install`` copies the packages' modules to
``install/lib/python3/dist-packages`` and the scripts to ``install/bin`` (a Python script's
``#!`` line naming the Python rosx runs on, as setuptools does). catkin's checks are made with
its words: no ``setup.py``, a script that does not exist, a package whose folder has another
name, packages of one tree in different folders.
"""

from __future__ import annotations

import os
import re
import shlex
import sys
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING, NamedTuple

from rosx.workspace.errors import BuildError
from rosx.workspace.executables import is_python_script

if TYPE_CHECKING:
    from collections.abc import Iterator

    from rosx.workspace.setup_py import PythonSetup

#: Where a space holds Python packages (catkin's ``PYTHON_INSTALL_DIR`` on Debian's Noetic).
PYTHON_DIR = "lib/python3/dist-packages"

_PYTHON_FIRST_LINE = re.compile(rb"^#!.*python[0-9.]*([ \t].*)?$")


class PackagePython(NamedTuple):
    """What ``catkin_python_setup()`` makes of one package's ``setup.py``: folders and files
    in the package's source, by the name they are imported or run by."""

    package: str
    #: Every package of ``packages`` (dotted names too) → its folder.
    folders: dict[str, Path]
    #: The top-level modules of ``py_modules`` → their files.
    modules: dict[str, Path]
    scripts: list[Path]
    #: The dotted modules of ``py_modules`` outside the packages, which rosx does not relay.
    skipped: list[str]

    def top_level(self) -> dict[str, Path]:
        """The packages without a dot in their name, the ones a space relays."""
        return {name: folder for name, folder in self.folders.items() if "." not in name}


def _locations(names: list[str], package_dir: dict[str, str]) -> dict[str, str]:
    """Each of ``names`` (and each of their parents) → its folder, as setuptools places them:
    ``package_dir``'s own entry, else the parent's folder and the last part, else under the
    folder of ``""``."""
    found: dict[str, str] = {}
    everything = package_dir.get("", "")
    for name in names:
        parent: str | None = None
        parts = name.split(".")
        for length in range(1, len(parts) + 1):
            key = ".".join(parts[:length])
            if key not in found:
                if key in package_dir:
                    found[key] = package_dir[key]
                elif parent is not None:
                    found[key] = str(PurePosixPath(parent, parts[length - 1]))
                else:
                    found[key] = str(PurePosixPath(everything, key))
            parent = found[key]
    return found


def plan_package(directory: Path, package: str, setup: PythonSetup, heading: str) -> PackagePython:
    """The folders and files ``setup`` names in the package at ``directory``.

    Args:
        directory: the package's folder.
        package: the package's name.
        setup: its ``setup.py``'s arguments.
        heading: the first line of an error (``CMake Error at …``).

    Raises:
        BuildError: one of catkin's checks fails.
    """
    located = _locations(setup.packages, setup.package_dir)
    for name, folder in located.items():
        root, _, rest = name.partition(".")
        if not rest or rest.split(".")[0] in ("msg", "srv"):
            continue
        above = PurePosixPath(folder)
        for _ in range(name.count(".")):
            above = above.parent
        if above != PurePosixPath(located[root]):
            raise BuildError(
                f"{heading}\n  catkin_export_python does not support setup.py files that combine "
                f"across multiple directories: {name} in {folder}, {root} in {located[root]}"
            )
    folders = {name: directory / located[name] for name in setup.packages}
    for name in [n for n in setup.packages if "." not in n]:
        if PurePosixPath(located[name]).name != name:
            raise BuildError(
                f"{heading}\n  The package name '{name}' differs from the basename of the path "
                f"'{located[name]}' in project '{package}'"
            )
    modules: dict[str, Path] = {}
    skipped: list[str] = []
    for module in setup.modules:
        parents = [".".join(module.split(".")[:n]) for n in range(1, module.count(".") + 1)]
        if module in located or any(parent in located for parent in parents):
            continue  # in a package's folder: the package's relay serves it
        if "." in module:
            skipped.append(module)
            continue
        modules[module] = directory / setup.package_dir.get("", "") / f"{module}.py"
    scripts = []
    for script in setup.scripts:
        path = directory / script
        if not path.is_file():
            raise BuildError(
                f"{heading}\n  The script '{path.name}' as listed in 'setup.py' of '{package}' "
                "doesn't exist"
            )
        scripts.append(path)
    return PackagePython(package, folders, modules, scripts, skipped)


def find_packages(folder: Path) -> list[str]:
    """setuptools' ``find_packages(folder)``: the folders below ``folder`` holding an
    ``__init__.py`` whose names are identifiers, dotted, not looking inside other folders."""
    found: list[str] = []

    def walk(here: Path, prefix: str) -> None:
        for child in sorted(p for p in here.iterdir() if p.is_dir()):
            if child.name.isidentifier() and (child / "__init__.py").is_file():
                found.append(prefix + child.name)
                walk(child, f"{prefix}{child.name}.")

    if folder.is_dir():
        walk(folder, "")
    return found


def _package_relay(package: str, folder: Path) -> str:
    """The devel space's ``__init__.py`` of a package whose modules are in ``folder``."""
    return (
        f"# Generated by rosx catkin_make (catkin_python_setup() of {package}): this package's\n"
        f"# modules are in the source space, {folder}; its __init__.py runs from there too.\n"
        "import os as _rosx_os\n\n"
        f"__path__.append({str(folder)!r})\n"
        f"_rosx_source = _rosx_os.path.join({str(folder)!r}, '__init__.py')\n"
        "if _rosx_os.path.isfile(_rosx_source):\n"
        "    with open(_rosx_source, 'rb') as _rosx_file:\n"
        "        exec(compile(_rosx_file.read(), _rosx_source, 'exec'))\n"
        "    del _rosx_file\n"
        "del _rosx_os, _rosx_source\n"
    )


def _module_relay(package: str, path: Path) -> str:
    """The devel space's module running the source's module at ``path``."""
    return (
        f"# Generated by rosx catkin_make (catkin_python_setup() of {package}): this module is\n"
        f"# {path} in the source space, run from there.\n"
        f"with open({str(path)!r}, 'rb') as _rosx_file:\n"
        f"    exec(compile(_rosx_file.read(), {str(path)!r}, 'exec'))\n"
        "del _rosx_file\n"
    )


def _script_relay(package: str, path: Path, rosx: str) -> str:
    """``devel/bin/NAME``: the source's script run with its arguments."""
    run = f"{rosx} run-script " if is_python_script(path) else ""
    return (
        "#!/bin/sh\n"
        f"# Generated by rosx catkin_make (catkin_python_setup() of {package}): runs {path}.\n"
        f'exec {run}{shlex.quote(str(path))} "$@"\n'
    )


def _write(path: Path, text: str, mode: int | None = None) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.is_file() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")
    if mode is not None:
        path.chmod(mode)
    return path


def write_devel(devel: Path, python: PackagePython, rosx: str) -> list[Path]:
    """Write the devel space's relays of ``python``; the files written.

    Args:
        devel: the devel space.
        python: the package's Python.
        rosx: how the shell runs rosx (for the scripts' relays).
    """
    site = devel / PYTHON_DIR
    written = [
        _write(site / name / "__init__.py", _package_relay(python.package, folder))
        for name, folder in python.top_level().items()
    ]
    written += [
        _write(site / f"{name}.py", _module_relay(python.package, path))
        for name, path in python.modules.items()
        if path.is_file()
    ]
    written += [
        _write(devel / "bin" / path.name, _script_relay(python.package, path, rosx), 0o755)
        for path in python.scripts
    ]
    return written


def _installed_script(path: Path) -> bytes:
    """The script as setuptools installs it: a Python ``#!`` line names this Python."""
    content = path.read_bytes()
    first, newline, rest = content.partition(b"\n")
    match = _PYTHON_FIRST_LINE.match(first)
    if match is None:
        return content
    return b"#!" + os.fsencode(sys.executable) + (match[1] or b"") + newline + rest


def install_python(install: Path, python: PackagePython) -> Iterator[Path]:
    """Copy ``python``'s modules and scripts into the install space, yielding each file."""
    site = install / PYTHON_DIR
    for name, folder in python.folders.items():
        if not folder.is_dir():
            continue
        target = site.joinpath(*name.split("."))
        for module in sorted(folder.glob("*.py")):
            yield _copy(module.read_bytes(), target / module.name, 0o644)
    for name, path in python.modules.items():
        if path.is_file():
            yield _copy(path.read_bytes(), site / f"{name}.py", 0o644)
    for path in python.scripts:
        yield _copy(_installed_script(path), install / "bin" / path.name, 0o755)


def _copy(content: bytes, target: Path, mode: int) -> Path:
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_bytes(content)
    target.chmod(mode)
    return target


__all__ = [
    "PYTHON_DIR",
    "PackagePython",
    "find_packages",
    "install_python",
    "plan_package",
    "write_devel",
]
