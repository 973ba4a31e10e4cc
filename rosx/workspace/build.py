"""``catkin_make`` for rosx: find a workspace's packages, build their types, write ``devel/``.

A workspace is a directory with ``src/`` (the source space); ``build/`` and ``devel/`` are
made next to it. There is nothing to compile: building a package means checking its manifest
as catkin does and loading each of its ``msg/*.msg`` and ``srv/*.srv`` types and the messages of
its ``action/*.action`` files the way a node will (parsed, embedded types found, md5 sums
computed, classes built), so a mistake is reported now, naming the file and the line, rather
than when a script imports the type. The package's ``CMakeLists.txt`` chooses the files
(``add_message_files``, ``add_service_files``, ``add_action_files`` with ``FILES``); a command
of it that rosx does not carry out gets a CMake warning naming its file and line
(`rosx.workspace.cmake.unsupported`), never silence. ``catkin_python_setup()`` makes the
Python packages and scripts of the package's ``setup.py`` importable and runnable from
``devel/`` as catkin does (`rosx.workspace.python_setup`). ``devel/``
receives ``setup.sh``, ``setup.bash`` and ``setup.zsh``, which export Noetic's environment
with the source space in front of ``ROS_PACKAGE_PATH`` (where rosx finds packages and their
types; ``devel/share/<pkg>/msg/`` holds the messages generated from ``.action`` files, as
genaction writes them), put rosx's ``rospy`` on ``PYTHONPATH``, define ``roscd``/``rosls``
and put ROS 1's command names (programs in ``devel/bin``) in front of ``PATH``, and
``.catkin``, which marks ``devel/`` as a workspace (``roscd`` with no argument goes there). With the
``install`` target, ``install/`` is written too (`rosx.workspace.install`). C++ targets are
named once, as not built: rosx compiles nothing.

`CatkinMake.run` yields the lines catkin_make prints while it works, in its style
(``-- +++ processing catkin package: 'lab2'``, ``[100%] Built target …``), and raises
`BuildError` with the report of what is wrong.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from rosx.packages.manifest import Manifest, ManifestError, check_manifest, read_manifest
from rosx.workspace.errors import BuildError
from rosx.workspace.shell import setup_for_shell, setup_sh

if TYPE_CHECKING:
    from collections.abc import Iterator, Mapping, Sequence

    from rosx.workspace.cmake import Call
    from rosx.workspace.python_setup import PackagePython
    from rosx.workspace.types import PackageTypes

_RULE = "-- ~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~"


class Declared(NamedTuple):
    """What rosx follows of a package's ``CMakeLists.txt``: the type files it names, by kind
    (None: every file of the kind), and its ``catkin_python_setup()`` call, if any."""

    types: dict[str, list[str] | None]
    python_setup: Call | None


class Layout(NamedTuple):
    """A workspace's spaces."""

    base: Path
    source: Path
    build: Path
    devel: Path
    install: Path


def _space(cwd: Path, base: Path, given: str | None, default: str) -> Path:
    if given is None:
        return base / default
    return Path(os.path.normpath(cwd / given))


def workspace_layout(
    cwd: Path, directory: str = ".", source: str | None = None, build: str | None = None
) -> Layout:
    """The spaces of the workspace at ``directory`` (relative to ``cwd``)."""
    base = Path(os.path.normpath(cwd / directory))
    return Layout(
        base,
        _space(cwd, base, source, "src"),
        _space(cwd, base, build, "build"),
        base / "devel",
        base / "install",
    )


def _crawl(directory: Path, found: list[Path]) -> None:
    if (directory / "package.xml").is_file():
        found.append(directory)
        return
    try:
        entries = sorted(os.scandir(directory), key=lambda e: e.name)
    except OSError:
        return
    names = {e.name for e in entries}
    if "CATKIN_IGNORE" in names:
        return
    for entry in entries:
        if not entry.name.startswith(".") and entry.is_dir():
            _crawl(Path(entry.path), found)


def discover(source: Path) -> tuple[list[Manifest], list[str]]:
    """The workspace's packages and catkin's warnings about them.

    Raises:
        BuildError: a manifest is invalid, or two packages have the same name.
    """
    directories: list[Path] = []
    _crawl(source, directories)
    manifests: list[Manifest] = []
    warnings: list[str] = []
    for directory in directories:
        try:
            manifest = read_manifest(directory)
            warnings += [f"WARNING: {w}" for w in check_manifest(manifest)]
        except ManifestError as error:
            raise BuildError(str(error)) from None
        manifests.append(manifest)
    by_name: dict[str, list[Path]] = {}
    for manifest in manifests:
        by_name.setdefault(manifest.name, []).append(manifest.directory)
    for name, places in by_name.items():
        if len(places) > 1:
            listing = "".join(f"\n- {place}" for place in places)
            raise BuildError(f'Multiple packages found with the same name "{name}":{listing}')
    return manifests, warnings


def _needs(manifest: Manifest, workspace: Mapping[str, Manifest]) -> set[str]:
    """The packages of ``workspace`` that ``manifest``'s package depends on."""
    deps = (*manifest.build_depends(), *manifest.run_depends())
    return {dep for dep in deps if dep in workspace and dep != manifest.name}


def topological_order(manifests: list[Manifest]) -> list[Manifest]:
    """Packages ordered so that each comes after the workspace packages it depends on.

    Raises:
        BuildError: packages depend on each other in a circle.
    """
    by_name = {m.name: m for m in sorted(manifests, key=lambda m: m.name)}
    needs = {name: _needs(m, by_name) for name, m in by_name.items()}
    ordered: list[Manifest] = []
    while needs:
        ready = sorted(name for name, deps in needs.items() if not deps)
        if not ready:
            listing = "".join(f"\n- {name}" for name in sorted(needs))
            raise BuildError(f"Circular dependency in subset of packages:{listing}")
        name = ready[0]
        ordered.append(by_name[name])
        del needs[name]
        for deps in needs.values():
            deps.discard(name)
    return ordered


class CatkinMake:
    """One ``catkin_make`` run over a workspace (see the module docstring)."""

    def __init__(
        self,
        layout: Layout,
        environ: Mapping[str, str],
        *,
        shim_dirs: Sequence[Path],
        rosx: str,
        commands: Sequence[str] = (),
        only: list[str] | None = None,
        install: bool = False,
        complete: str | None = None,
    ) -> None:
        self.layout = layout
        self.environ = environ
        self.shim_dirs = list(shim_dirs)
        self.rosx = rosx
        #: How the setup files' <TAB> runs ``rosx complete`` (`rosx.workspace.completion`).
        self.complete = complete
        #: ROS 1's command names, written as programs in each space's ``bin/``.
        self.commands = list(commands)
        self.only = only
        self.install = install
        self.warnings: list[str] = []
        #: The packages' Python of ``catkin_python_setup()``, found by `run`.
        self.pythons: list[PackagePython] = []

    def check_layout(self) -> None:
        """catkin_make's checks of where it was run.

        Raises:
            BuildError: not at a workspace's root.
        """
        base, source = self.layout.base, self.layout.source
        if not base.exists():
            raise BuildError(f'The specified base path "{base}" does not exist')
        if (base / "package.xml").exists():
            raise BuildError(
                f'The specified base path "{base}" contains a package but "catkin_make" must be '
                "invoked in the root of workspace"
            )
        if not source.exists():
            raise BuildError(f'The specified source space "{source}" does not exist')
        if base.resolve() != source.resolve() and (base / "CMakeLists.txt").exists():
            raise BuildError(
                f'The specified base path "{base}" contains a CMakeLists.txt but "catkin_make" '
                "must be invoked in the root of workspace"
            )

    def header(self) -> list[str]:
        """The lines naming the spaces, printed first."""
        layout = self.layout
        return [
            f"Base path: {layout.base}",
            f"Source space: {layout.source}",
            f"Build space: {layout.build}",
            f"Devel space: {layout.devel}",
            f"Install space: {layout.install}",
        ]

    def _package_path(self) -> list[Path]:
        entries = self.environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep)
        return [self.layout.source, *[Path(e) for e in entries if e]]

    def run(self) -> Iterator[str]:
        """Build the workspace, yielding what catkin_make prints as it goes.

        Raises:
            BuildError: a manifest or a type is wrong (nothing is written to ``devel/`` then).
        """
        layout = self.layout
        manifests, self.warnings = discover(layout.source)
        self.pythons = []
        if self.only:
            manifests = _with_dependencies(manifests, self.only)
            yield f"Whitelisted packages: {', '.join(sorted(m.name for m in manifests))}"
        ordered = topological_order(manifests)
        layout.build.mkdir(parents=True, exist_ok=True)
        yield f"-- Using CATKIN_DEVEL_PREFIX: {layout.devel}"
        yield _RULE
        yield f"-- ~~  traversing {len(ordered)} packages in topological order:"
        for manifest in ordered:
            yield f"-- ~~  - {manifest.name}"
        yield _RULE
        built: list[PackageTypes] = []
        actions: list[tuple[str, Path]] = []
        cpp = _cpp_targets(ordered)
        if cpp:
            yield NO_CPP + "; ".join(f"{pkg} ({', '.join(names)})" for pkg, names in cpp)
        for manifest in ordered:
            yield f"-- +++ processing catkin package: '{manifest.name}'"
            yield f"-- ==> add_subdirectory({manifest.directory.relative_to(layout.source)})"
            declared = self._read_cmakelists(manifest)
            if declared.python_setup is not None:
                self._python_setup(manifest, declared.python_setup)
            chosen = declared.types
            if not any((manifest.directory / kind).is_dir() for kind in ("msg", "srv", "action")):
                continue
            # The message system loads only for packages that have types.
            from rosx.workspace.types import build_types, type_paths  # noqa: PLC0415 - workspace code loads only when used

            for path in type_paths(manifest, chosen)["action"]:
                yield f"-- Generating .msg files for action {manifest.name}/{path.stem} {path}"
                yield f"Generating for action {path.stem}"
                actions.append((manifest.name, path))
            types = build_types(manifest, self._package_path(), chosen)
            yield (
                f"-- {manifest.name}: {len(types.messages)} messages, "
                f"{len(types.services)} services"
            )
            built.append(types)
        yield "-- Configuring done"
        yield "-- Generating done"
        yield f"-- Build files have been written to: {layout.build}"
        self._write(built, actions)
        yield from _progress(built)
        if self.install:
            from rosx.workspace.install import install_space  # noqa: PLC0415 - workspace code loads only when used

            yield "Install the project..."
            for path in install_space(layout, ordered, self._setup_files, self.pythons):
                yield f"-- Installing: {path}"

    def _read_cmakelists(self, manifest: Manifest) -> Declared:
        """Check the package's ``CMakeLists.txt`` as far as rosx follows it: warnings for the
        commands it does not carry out; the type files it names and its
        ``catkin_python_setup()``.

        Raises:
            BuildError: a folder or file it names does not exist, or ``generate_messages()``
                comes before ``catkin_python_setup()`` (CMake's and catkin's errors).
        """
        from rosx.workspace.cmake import TYPE_FOLDERS, calls, type_files, unsupported  # noqa: PLC0415 - workspace code loads only when used

        path = manifest.directory / "CMakeLists.txt"
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError:
            return Declared({}, None)
        where = os.path.relpath(path, self.layout.source)
        python_setup = next((c for c in calls(text) if c.name == "catkin_python_setup"), None)
        generate = next((c for c in calls(text) if c.name == "generate_messages"), None)
        if python_setup is not None and generate is not None and generate.line < python_setup.line:
            raise BuildError(
                f"CMake Error at {where}:{python_setup.line} (catkin_python_setup):\n"
                "  generate_messages() must be called after catkin_python_setup() in project "
                f"'{manifest.name}'"
            )
        for call, reason in unsupported(text):
            self.warnings.append(f"CMake Warning at {where}:{call.line} ({call.name}):\n  {reason}")
        chosen: dict[str, list[str] | None] = {}
        for declared in type_files(text):
            call, folder = declared.call, TYPE_FOLDERS[declared.call.name]
            directory = manifest.directory / declared.directory
            heading = f"CMake Error at {where}:{call.line} ({call.name}):\n  {call.name}()"
            if not directory.is_dir():
                raise BuildError(f"{heading} directory not found: {directory}")
            if os.path.normpath(declared.directory) != folder:
                self.warnings.append(
                    f"CMake Warning at {where}:{call.line} ({call.name}):\n  rosx finds "
                    f"{folder} files in {folder}/ only: those in {declared.directory}/ are "
                    "not built"
                )
                continue
            if declared.files is None:
                continue
            for name in declared.files:
                if not (directory / name).is_file():
                    raise BuildError(f"{heading} file not found: {directory / name}")
            chosen[folder] = [*(chosen.get(folder) or []), *declared.files]
        return Declared(chosen, python_setup)

    def _python_setup(self, manifest: Manifest, call: Call) -> None:
        """Read the package's ``setup.py`` for ``catkin_python_setup()`` (`self.pythons`); a
        warning where rosx cannot work it out without running it.

        Raises:
            BuildError: one of catkin's errors (no ``setup.py``, a script missing…).
        """
        from rosx.workspace.python_setup import find_packages, plan_package  # noqa: PLC0415 - workspace code loads only when used
        from rosx.workspace.setup_py import NotUnderstood, read_setup_py  # noqa: PLC0415 - workspace code loads only when used

        directory = manifest.directory
        cmakelists = os.path.relpath(directory / "CMakeLists.txt", self.layout.source)
        heading = f"CMake Error at {cmakelists}:{call.line} (catkin_python_setup):"
        setup_py = directory / "setup.py"
        try:
            text = setup_py.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError):
            raise BuildError(
                f"{heading}\n  catkin_python_setup() called without 'setup.py' in project folder "
                f"' {directory}'"
            ) from None
        where = os.path.relpath(setup_py, self.layout.source)
        setup = read_setup_py(
            text, manifest.name, manifest.version, lambda under: find_packages(directory / under)
        )
        if isinstance(setup, NotUnderstood):
            self.warnings.append(
                f"CMake Warning at {where}:{setup.line} (catkin_python_setup):\n  rosx reads "
                f"setup.py without running it and cannot work out `{setup.text}`: the "
                "package's Python modules and scripts are not set up"
            )
            return
        if setup.version is not None and setup.version != manifest.version:
            raise BuildError(
                f"{heading}\n  catkin_python_setup() version in setup.py ({setup.version}) "
                f"differs from version in package.xml ({manifest.version})"
            )
        if setup.unsupported:
            self.warnings.append(
                f"*** Arguments {setup.unsupported} to setup() not supported in catkin devel "
                f"space in setup.py of {manifest.name}"
            )
        python = plan_package(directory, manifest.name, setup, heading)
        if python.skipped:
            self.warnings.append(
                f"CMake Warning at {where}:{setup.line} (catkin_python_setup):\n  rosx makes "
                "packages and top-level modules importable from the devel space, not "
                f"{', '.join(python.skipped)}"
            )
        self.pythons.append(python)

    def _write(self, built: list[PackageTypes], actions: list[tuple[str, Path]]) -> None:
        layout = self.layout
        (layout.build / "CATKIN_IGNORE").touch()
        (layout.build / ".built_by").write_text("catkin_make", encoding="utf-8")
        summary = "".join(f"{name}\n" for types in built for name in types.all_names())
        (layout.build / "rosx_types.txt").write_text(summary, encoding="utf-8")
        devel = layout.devel
        devel.mkdir(parents=True, exist_ok=True)
        (devel / ".catkin").write_text(str(layout.source), encoding="utf-8")
        (devel / ".built_by").write_text("catkin_make", encoding="utf-8")
        for name, text in self._setup_files(layout.source, devel).items():
            (devel / name).write_text(text, encoding="utf-8")
        if actions:
            from rosx.msg.parser import action_texts  # noqa: PLC0415 - for packages with actions

        for package, path in actions:
            # genaction's seven messages, where catkin puts them (`ls devel/share/PKG/msg/`)
            folder = devel / "share" / package / "msg"
            folder.mkdir(parents=True, exist_ok=True)
            text = path.read_text(encoding="utf-8")
            for suffix, message in action_texts(path.stem, text).items():
                (folder / f"{path.stem}{suffix}.msg").write_text(message, encoding="utf-8")
        if self.pythons:
            from rosx.workspace.python_setup import write_devel  # noqa: PLC0415 - workspace code loads only when used

            for python in self.pythons:
                write_devel(devel, python, self.rosx)

    def _setup_files(self, source: Path, space: Path) -> dict[str, str]:
        """The setup files of a space (devel or install) whose packages are in ``source``;
        the command programs they put on ``PATH`` are written in its ``bin/`` meanwhile."""
        from rosx.workspace.path_commands import write_commands  # noqa: PLC0415 - on writing

        write_commands(space / "bin", self.rosx, self.commands, prune=False)
        files = {
            "setup.sh": setup_sh(
                source=str(source),
                devel=str(space),
                shims=[str(d) for d in self.shim_dirs],
                rosx=self.rosx,
                commands=self.commands,
            )
        }
        for shell in ("bash", "zsh"):
            files[f"setup.{shell}"] = setup_for_shell(
                shell, str(space), self.rosx, self.commands, self.complete
            )
        return files


def _with_dependencies(manifests: list[Manifest], names: list[str]) -> list[Manifest]:
    """``names`` and the workspace packages they depend on, recursively.

    Raises:
        BuildError: none of ``names`` is in the workspace.
    """
    by_name = {m.name: m for m in manifests}
    if not any(name in by_name for name in names):
        raise BuildError(f'Packages "{", ".join(names)}" not found in the workspace')
    wanted: set[str] = set()
    todo = [name for name in names if name in by_name]
    while todo:
        name = todo.pop()
        if name not in wanted:
            wanted.add(name)
            todo += _needs(by_name[name], by_name)
    return [m for m in manifests if m.name in wanted]


#: What catkin_make says, once, when packages have C++ targets.
NO_CPP = "-- rosx compiles no C++: these C++ targets are not built (rosx runs Python nodes only): "


def _cpp_targets(manifests: list[Manifest]) -> list[tuple[str, list[str]]]:
    from rosx.workspace.cmake import cpp_targets  # noqa: PLC0415 - workspace code loads only when used

    found = []
    for manifest in manifests:
        names = cpp_targets(manifest.directory / "CMakeLists.txt")
        if names:
            found.append((manifest.name, names))
    return found


def _progress(built: list[PackageTypes]) -> Iterator[str]:
    steps = [(types.package, kind, name) for types in built for kind, name in types.steps()]
    for index, (_, kind, name) in enumerate(steps, start=1):
        percent = index * 100 // len(steps)
        if kind == "msg":
            yield f"[{percent:3d}%] Generating Python from MSG {name}"
        else:
            yield f"[{percent:3d}%] Generating Python code from SRV {name}"
    for types in built:
        if types.messages or types.services:
            yield f"[100%] Built target {types.package}_generate_messages_py"


__all__ = [
    "BuildError",
    "CatkinMake",
    "Declared",
    "Layout",
    "discover",
    "topological_order",
    "workspace_layout",
]
