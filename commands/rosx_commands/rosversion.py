"""``rosx rosversion PKG | -d | -a [-s]``: a package's version, or the distribution's name.

As rospkg's rosversion: the ``<version>`` of the package's ``package.xml``
(``<unversioned>`` without one), ``Cannot locate [x]`` (stdout, status 1) for an unknown
package, ``-d`` the distribution (``ROS_DISTRO``, else ``noetic``: rosx is Noetic), ``-a`` every
package as ``name: version``, ``-s`` without the line breaks. Parsed with argparse, as there,
so ``-h`` and the usage errors read the same.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence

from rosx_commands.cli import run_command
from rosx_commands.context import Environment, ExitStatus


def _parser(env: Environment) -> argparse.ArgumentParser:
    from rosx_commands.argparser import ToolArgumentParser  # noqa: PLC0415 - this tool's parts load only when used

    parser = ToolArgumentParser(env, "rosversion")
    # rospkg's description has its two lines the wrong way round; kept as it prints.
    parser.description = (
        "rosversion -d: Output the version of the given package\n"
        "rosversion package: Output the ROS distribution name"
    )
    parser.formatter_class = argparse.RawTextHelpFormatter
    parser.add_argument("-s", "--skip-newline", action="store_true", help="Skip trailing newline")
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("package", nargs="?", help="The ROS package name (e.g. 'roscpp')")
    group.add_argument(
        "-d", "--distro", action="store_true", help="Output the ROS distribution name"
    )
    group.add_argument(
        "-a", "--all", action="store_true", help="Show all ROS package names and their versions"
    )
    return parser


def _rosversion(argv: list[str], env: Environment) -> int:
    from rosx.packages.index import PackageIndex, PackageNotFoundError  # noqa: PLC0415 - the package index loads only when used
    from rosx.packages.manifest import ManifestError  # noqa: PLC0415 - the package index loads only when used
    from rosx.workspace.environment import DISTRO  # noqa: PLC0415 - workspace code loads only when used

    args = _parser(env).parse_args(argv)
    end = "" if args.skip_newline else "\n"
    if args.distro:
        env.stdout.write((env.environ.get("ROS_DISTRO") or DISTRO) + end)
        return ExitStatus.OK
    index = PackageIndex.from_environ(env.environ)

    def version(name: str) -> str:
        try:
            manifest = index.manifest(name)
        except ManifestError:
            return "<unversioned>"
        return manifest.version if manifest is not None and manifest.version else "<unversioned>"

    if args.all:
        for name in index.packages:
            env.stdout.write(f"{name}: {version(name)}{end}")
        return ExitStatus.OK
    try:
        index.find(args.package)
    except PackageNotFoundError:
        env.out(f"Cannot locate [{args.package}]")
        return ExitStatus.ERROR
    env.stdout.write(version(args.package) + end)
    return ExitStatus.OK


def rosversion(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosversion ARGV…``."""
    return run_command(_rosversion, list(argv), env)


__all__ = ["rosversion"]
