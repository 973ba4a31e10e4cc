"""``catkin_make install``: a workspace's install space, laid out as ROS 1's.

``install/`` is a prefix like ``/opt/ros/noetic``: ``share/PKG/`` holds each package's
``package.xml`` and its ``msg/`` and ``srv/`` files (catkin installs those for every package that
generates messages), ``lib/PKG/`` the programs its ``CMakeLists.txt`` installs with
``catkin_install_python(PROGRAMS …)`` or ``install(PROGRAMS …)``; ``install(FILES|DIRECTORY …)``
rules copy the rest (launch files…); the Python modules and scripts of a package's ``setup.py``
(``catkin_python_setup()``) go to ``lib/python3/dist-packages`` and ``bin``.
``setup.sh``/``.bash``/``.zsh`` put ``install/share`` on ``ROS_PACKAGE_PATH``, so ``rospack``,
``roscd``, ``rosrun`` (which looks in ``lib/PKG`` too) and the type store use the installed
packages as they use ``devel``'s. An empty ``.catkin`` marks the prefix as catkin's does.
"""

from __future__ import annotations

import shutil
from typing import TYPE_CHECKING

from rosx.workspace.cmake import install_rules

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator, Sequence
    from pathlib import Path

    from rosx.packages.manifest import Manifest
    from rosx.workspace.build import Layout
    from rosx.workspace.python_setup import PackagePython


def _copy(source: Path, target: Path) -> Iterator[Path]:
    if source.is_dir():
        for child in sorted(source.iterdir()):
            if not child.name.startswith("."):
                yield from _copy(child, target / child.name)
        return
    target.parent.mkdir(parents=True, exist_ok=True)
    shutil.copy2(source, target)
    yield target


def _package(manifest: Manifest, install: Path) -> Iterator[Path]:
    directory = manifest.directory
    share = install / "share" / manifest.name
    yield from _copy(manifest.path, share / "package.xml")
    for kind in ("msg", "srv"):
        if (directory / kind).is_dir():
            yield from _copy(directory / kind, share / kind)
    for rule in install_rules(manifest.name, directory / "CMakeLists.txt"):
        destination = install / rule.destination
        for name in rule.sources:
            source = directory / name
            if not source.exists():
                continue
            if rule.kind == "DIRECTORY" and not name.endswith("/"):
                yield from _copy(source, destination / source.name)
            elif rule.kind == "DIRECTORY":
                yield from _copy(source, destination)
            else:
                yield from _copy(source, destination / source.name)


def install_space(
    layout: Layout,
    manifests: list[Manifest],
    setup_files: Callable[[Path, Path], dict[str, str]],
    pythons: Sequence[PackagePython] = (),
) -> Iterator[Path]:
    """Write ``install/`` for ``manifests``, yielding each file written.

    Args:
        layout: the workspace's spaces.
        manifests: the packages, in build order.
        setup_files: the setup files' texts by name, given where the packages are and the space.
        pythons: the packages' Python of ``catkin_python_setup()``.
    """
    install = layout.install
    install.mkdir(parents=True, exist_ok=True)
    (install / ".catkin").write_text("", encoding="utf-8")
    for name, text in setup_files(install / "share", install).items():
        (install / name).write_text(text, encoding="utf-8")
        yield install / name
    for manifest in manifests:
        yield from _package(manifest, install)
    if pythons:
        from rosx.workspace.python_setup import install_python  # noqa: PLC0415 - only for packages with a setup.py

        for python in pythons:
            yield from install_python(install, python)


__all__ = ["install_space"]
