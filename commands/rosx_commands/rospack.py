"""``rosx rospack``: find packages and their dependencies, with rospack's output and errors.

ROS 1's rospack is a C++ program with its own argument handling; this follows its texts:
``[rospack] Error: package 'x' not found`` (find), ``[rospack] Error: no such package x``
(the dependency commands), ``[rospack] Error: no command given.  Try 'rospack help'``, status 1
for errors. A command given no package uses the package in the current directory. ``-q``
quiets the error reports.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from rosx_commands.context import Environment, ExitStatus

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx.packages.index import PackageIndex

USAGE = """\
USAGE: rospack <command> [options] [package]
  Allowed commands:
    help
    depends           [package] (alias: deps)
    depends-on        [package]
    depends-on1       [package]
    depends1          [package] (alias: deps1)
    find [package]
    list
    list-names
  Extra options:
    -q     Quiets error reports.

 If [package] is omitted, the current working directory
 is used (if it contains a package.xml or manifest.xml).
"""

_PACKAGE_COMMANDS = {
    "find",
    "depends",
    "deps",
    "depends1",
    "deps1",
    "depends-on",
    "depends-on1",
}
_LIST_COMMANDS = {"list", "list-names", "help"}


class _Failed(Exception):  # noqa: N818 - a report, worded by rospack
    """rospack's error: the text after ``[rospack] Error: ``."""


def _package_here(env: Environment) -> str | None:
    from rosx.packages.manifest import package_in  # noqa: PLC0415 - the package index loads only when used
    from rosx_commands.invocation import working_directory  # noqa: PLC0415 - this tool's parts load only when used

    return package_in(working_directory(env))


def _provided(package: str) -> bool:
    """Whether rosx provides ``package``'s types without a directory (``std_msgs``…)."""
    from rosx.msg.store import default_store  # noqa: PLC0415 - standard types load lazily

    return default_store().has_package(package)


def _listed(env: Environment) -> Mapping[str, object]:
    """Every package's folder by name: from the kept crawl while it holds (without the
    index's code: rospack list is ~10 ms in C++), else from the index."""
    from rosx.packages.kept import listed_packages  # noqa: PLC0415 - the package index loads only when used

    listed = listed_packages(env.environ)
    if listed is not None:
        return listed
    from rosx.packages.index import PackageIndex  # noqa: PLC0415 - the package index loads only when used

    return PackageIndex.from_environ(env.environ, provides=_provided).packages


def _answer(command: str, package: str, index: PackageIndex) -> list[str]:
    from rosx.packages.index import PackageNotFoundError  # noqa: PLC0415 - the package index loads only when used

    if command == "find":
        try:
            return [str(index.find(package))]
        except PackageNotFoundError:
            raise _Failed(f"package '{package}' not found") from None
    # Manifests (and XML) only past find: a <TAB> and rosbash's functions run find often.
    from rosx.packages.manifest import ManifestError  # noqa: PLC0415 - XML past find only

    if not index.is_known(package):
        raise _Failed(f"no such package {package}")
    try:
        if command in ("depends1", "deps1"):
            return index.depends1(package)
        if command in ("depends", "deps"):
            return index.depends(package)
        if command == "depends-on1":
            return index.depends_on1(package)
        return [name for name in index.packages if package in index.depends(name)]
    except ManifestError as error:
        raise _Failed(str(error)) from None


def rospack(argv: Sequence[str], env: Environment) -> int:
    """Run ``rospack ARGV…``."""
    args = list(argv)
    quiet = "-q" in args
    args = [a for a in args if a != "-q"]

    def fail(text: str) -> int:
        if not quiet:
            env.err(f"[rospack] Error: {text}")
        return ExitStatus.ERROR

    if not args or args[0].startswith("-"):
        fail("no command given.  Try 'rospack help'")
        return ExitStatus.OK  # as rospack's own status for it
    command, rest = args[0], args[1:]
    if command not in _PACKAGE_COMMANDS | _LIST_COMMANDS:
        return fail(f"command {command} not implemented")
    if any(a.startswith("-") for a in rest):
        return fail("invalid option(s) given")
    if len(rest) > 1:
        return fail(
            "failed to parse command-line options: too many positional options have been "
            "specified on the command line"
        )
    if command == "help":
        env.stdout.write(USAGE)
        return ExitStatus.OK

    if command in _LIST_COMMANDS:
        if rest:
            return fail("invalid option(s) given")
        listed = _listed(env)
        if command == "list-names":
            env.stdout.write("".join(f"{name}\n" for name in listed))
        else:
            env.stdout.write("".join(f"{name} {folder}\n" for name, folder in listed.items()))
        return ExitStatus.OK

    package = rest[0] if rest else _package_here(env)
    if package is None:
        return fail("no package given")
    if command == "find":
        from rosx.packages.kept import kept_find  # noqa: PLC0415 - the package index loads only when used

        found = kept_find(env.environ, package)  # without the index's code, while it holds
        if found is not None:
            env.out(found)
            return ExitStatus.OK
    from rosx.packages.index import PackageIndex  # noqa: PLC0415 - the package index loads only when used

    index = PackageIndex.from_environ(env.environ, provides=_provided)
    try:
        lines = _answer(command, package, index)
    except _Failed as error:
        return fail(str(error))
    for line in lines:
        env.out(line)
    return ExitStatus.OK
