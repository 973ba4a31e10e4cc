"""``catkin_create_pkg``: a new package's ``package.xml``, ``CMakeLists.txt`` and folders.

The files are catkin_pkg's templates (``templates/``) filled in as catkin_pkg fills them, so a
package made by rosx is byte for byte the one ROS 1 makes:

* licenses, maintainers, authors and dependencies are sorted; the maintainer defaults to the
  user, with the e-mail address ``<last word of the name>@todo.todo``;
* each dependency becomes ``build_depend``, ``build_export_depend`` and ``exec_depend``, except
  ``catkin`` (dropped: it is always the ``buildtool_depend``), ``genmsg`` (a
  ``buildtool_depend``, with a warning), ``message_generation`` (``build_depend``) and
  ``message_runtime`` (``exec_depend``), each warned about when the other is missing;
* a system dependency (``-s``) is a ``depend``, or an ``exec_depend`` when it starts with
  ``python-``; Boost components (``-b``) add ``boost``;
* ``include/<name>/`` is made when the package depends on ``roscpp``, ``src/`` when it depends
  on ``roscpp`` or ``rospy``.

Nothing is written when a file is in the way (`CreateError`, catkin's ``File exists: …``).
"""

from __future__ import annotations

import string
from pathlib import Path
from typing import NamedTuple

from rosx.packages.manifest import Manifest, Person

_TEMPLATES = Path(__file__).parent / "templates"


class CreateError(ValueError):
    """The package cannot be created; ``str()`` is catkin_pkg's text."""


class PackageRequest(NamedTuple):
    """What ``catkin_create_pkg`` was asked for."""

    name: str
    dependencies: tuple[str, ...] = ()
    meta: bool = False
    system_deps: tuple[str, ...] = ()
    boost_comps: tuple[str, ...] = ()
    version: str | None = None
    description: str | None = None
    licenses: tuple[str, ...] = ()
    authors: tuple[str, ...] = ()
    maintainers: tuple[str, ...] = ()


class _Template(string.Template):
    delimiter = "@"


class Plan(NamedTuple):
    """A package's files before they are written, and the warnings about the request."""

    manifest: Manifest
    catkin_deps: list[str]
    system_deps: list[str]
    boost_comps: list[str]
    buildtool: list[str]
    build: list[str]
    build_export: list[str]
    exec_: list[str]
    warnings: list[str]


def _add(names: list[str], name: str) -> None:
    if name not in names:
        names.append(name)


def plan_package(request: PackageRequest, user: str) -> Plan:
    """Sort the request into catkin_pkg's dependency lists and a manifest to validate."""
    warnings: list[str] = []
    catkin_deps = sorted(request.dependencies)
    buildtool, build, exec_, depends = ["catkin"], [], [], []
    pair_warning = (
        "WARNING: Packages with messages or services should depend on both "
        "message_generation and message_runtime"
    )
    for dep in list(catkin_deps):
        lower = dep.lower()
        if lower == "catkin":
            catkin_deps.remove(dep)
        elif lower == "genmsg":
            warnings.append(
                "WARNING: Packages with messages or services should not depend on genmsg, "
                "but on message_generation and message_runtime"
            )
            buildtool.append("genmsg")
        elif lower == "message_generation":
            if "message_runtime" not in catkin_deps:
                warnings.append(pair_warning)
            build.append("message_generation")
        elif lower == "message_runtime":
            if "message_generation" not in catkin_deps:
                warnings.append(pair_warning)
            exec_.append("message_runtime")
        else:
            depends.append(dep)
    system_deps = list(request.system_deps)
    if request.boost_comps and "boost" not in system_deps:
        system_deps.append("boost")
    for dep in system_deps:
        (exec_ if dep.lower().startswith("python-") else depends).append(dep)
    build_export: list[str] = []
    for dep in depends:
        for names in (build, build_export, exec_):
            _add(names, dep)
    maintainers = sorted(request.maintainers or (user,))
    manifest = Manifest(
        path=Path(request.name) / "package.xml",
        format="2",
        name=request.name,
        version=request.version or "0.0.0",
        description=request.description or f"The {request.name} package",
        maintainers=tuple(
            Person(m, f"{m.split()[-1] if m.split() else m}@todo.todo") for m in maintainers
        ),
        authors=tuple(Person(a, None) for a in sorted(request.authors)),
        licenses=tuple(sorted(request.licenses or ("TODO",))),
        depends={
            "buildtool_depend": tuple(buildtool),
            "build_depend": tuple(build),
            "build_export_depend": tuple(build_export),
            "exec_depend": tuple(exec_),
        },
        metapackage=request.meta,
    )
    return Plan(
        manifest, catkin_deps, system_deps, list(request.boost_comps), buildtool, build,
        build_export, exec_, warnings,
    )  # fmt: skip


def _person(tag: str, person: Person) -> str:
    email = "" if person.email is None else f'email="{person.email}"'
    return f"  <{tag} {email}>{person.name}</{tag}>\n"


def render_package_xml(plan: Plan) -> str:
    """The ``package.xml`` text."""
    manifest = plan.manifest
    dependencies = ""
    for tag, names in (
        ("buildtool_depend", plan.buildtool),
        ("build_depend", plan.build),
        ("build_export_depend", plan.build_export),
        ("exec_depend", plan.exec_),
    ):
        dependencies += "".join(f"  <{tag}>{n}</{tag}>\n" for n in sorted(set(names)))
    template = _Template((_TEMPLATES / "package.xml.in").read_text(encoding="utf-8"))
    return template.substitute(
        name=manifest.name,
        version_compatibility="",
        version=manifest.version,
        description=manifest.description,
        maintainers="".join(_person("maintainer", p) for p in manifest.maintainers),
        licenses="".join(f"  <license>{text}</license>\n" for text in manifest.licenses),
        urls="",
        authors="".join(_person("author", p) for p in manifest.authors),
        dependencies=dependencies,
        exports="    <metapackage/>" if manifest.metapackage else "",
    )


def _include_directories(plan: Plan) -> str:
    lines = ["# include", ("  " if plan.catkin_deps else "# ") + "${catkin_INCLUDE_DIRS}"]
    if plan.boost_comps:
        lines.append("  ${Boost_INCLUDE_DIRS}")
    native = [dep for dep in plan.system_deps if not dep.startswith("python-")]
    if native:
        lines.append(
            "# TODO: Check names of system library include directories (" + ", ".join(native) + ")"
        )
        lines += [f"  ${{{dep}_INCLUDE_DIRS}}" for dep in native]
    return "\n".join(lines)


def render_cmakelists(plan: Plan) -> str:
    """The ``CMakeLists.txt`` text."""
    name = plan.manifest.name
    if plan.manifest.metapackage:
        meta = _Template((_TEMPLATES / "metapackage.cmake.in").read_text(encoding="utf-8"))
        return meta.substitute(name=name)
    deps = plan.catkin_deps
    components = " COMPONENTS\n  " + "\n  ".join(deps) + "\n" if deps else ""
    boost = (
        f"find_package(Boost REQUIRED COMPONENTS {' '.join(plan.boost_comps)})\n"
        if plan.boost_comps
        else ""
    )
    systems = "".join(
        ("# " if dep.startswith("python-") else "") + f"find_package({dep} REQUIRED)\n"
        for dep in plan.system_deps
        if dep != "boost"
    )
    message_pkgs = [dep for dep in deps if dep.endswith("_msgs")]
    libraries = "#   ${catkin_LIBRARIES}\n"
    if plan.boost_comps:
        libraries += "#   ${Boost_LIBRARIES}\n"
    libraries += "".join(f"#   ${{{dep}_LIBRARIES}}\n" for dep in plan.system_deps)
    template = _Template((_TEMPLATES / "CMakeLists.txt.in").read_text(encoding="utf-8"))
    return template.substitute(
        name=name,
        components=components,
        include_directories=_include_directories(plan),
        boost_find=boost,
        systems_find=systems,
        catkin_depends=" ".join(deps) if deps else "other_catkin_pkg",
        system_depends=" ".join(plan.system_deps) if plan.system_deps else "system_lib",
        target_libraries=libraries,
        message_dependencies=(
            "#   " + "#   ".join(message_pkgs)
            if message_pkgs
            else "#   std_msgs  # Or other packages containing msgs"
        ),
    )


def create_package(parent: Path, plan: Plan) -> list[str]:
    """Write the package below ``parent``; the lines catkin_create_pkg prints, in order.

    Raises:
        CreateError: a file or folder is in the way (nothing is written then).
    """
    name = plan.manifest.name
    target = parent / name
    files = {
        target / "package.xml": render_package_xml(plan),
        target / "CMakeLists.txt": render_cmakelists(plan),
    }
    for path in files:
        if path.exists() or path.is_symlink():
            raise CreateError(f"File exists: {path}")
        directory = path.parent
        while directory not in (target, directory.parent):
            if directory.is_file():
                raise CreateError(f"Cannot create directory, file exists: {directory}")
            directory = directory.parent
    folders = []
    if "roscpp" in plan.catkin_deps:
        folders.append(target / "include" / name)
    if "roscpp" in plan.catkin_deps or "rospy" in plan.catkin_deps:
        folders.append(target / "src")
    for folder in folders:
        if folder.exists():
            raise CreateError(f"File exists: {folder}")
    lines = []
    for path, text in files.items():
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
        lines.append(f"Created file {path.relative_to(parent)}")
    for folder in folders:
        folder.mkdir(parents=True)
        lines.append(f"Created folder {folder.relative_to(parent)}")
    return lines


__all__ = [
    "CreateError",
    "PackageRequest",
    "Plan",
    "create_package",
    "plan_package",
    "render_cmakelists",
    "render_package_xml",
]
