"""``rosx catkin_create_pkg``: create a catkin package, as catkin_pkg's ``catkin_create_pkg``.

ROS 1's tool parses with argparse (so do we: same help, same usage errors, exit 2) and
reports problems as usage errors: ``catkin_create_pkg: error: File exists: …``.
"""

from __future__ import annotations

import getpass
from collections.abc import Sequence

from rosx_commands.cli import run_command
from rosx_commands.context import CommandError, Environment, ExitStatus


def _catkin_create_pkg(argv: list[str], env: Environment) -> int:
    from rosx_commands.argparser import ToolArgumentParser  # noqa: PLC0415 - this tool's parts load only when used

    parser = ToolArgumentParser(env, "catkin_create_pkg")
    parser.description = "Creates a new catkin package"
    parser.add_argument("name", nargs=1, help="The name for the package")
    parser.add_argument("--meta", action="store_true", help="Creates meta-package files")
    parser.add_argument("dependencies", nargs="*", help="Catkin package Dependencies")
    parser.add_argument("-s", "--sys-deps", nargs="*", help="System Dependencies")
    parser.add_argument("-b", "--boost-comps", nargs="*", help="Boost Components")
    parser.add_argument("-V", "--pkg_version", action="store", help="Initial Package version")
    parser.add_argument("-D", "--description", action="store", help="Description")
    parser.add_argument(
        "-l", "--license", action="append", help="Name for License, (e.g. BSD, MIT, GPLv3...)"
    )
    parser.add_argument(
        "-a", "--author", action="append", help="A single author, may be used multiple times"
    )
    parser.add_argument(
        "-m",
        "--maintainer",
        action="append",
        help="A single maintainer, may be used multiple times",
    )
    parser.add_argument(
        "--rosdistro",
        default=env.environ.get("ROS_DISTRO", "noetic"),
        help="The ROS distro (default: environment variable ROS_DISTRO if defined)",
    )
    args = parser.parse(argv)

    from rosx.workspace.create import (  # noqa: PLC0415 - not for -h and usage errors
        CreateError,
        PackageRequest,
        create_package,
        plan_package,
    )
    from rosx_commands.invocation import working_directory  # noqa: PLC0415 - this tool's parts load only when used

    request = PackageRequest(
        name=args.name[0],
        dependencies=tuple(args.dependencies or ()),
        meta=args.meta,
        system_deps=tuple(args.sys_deps or ()),
        boost_comps=tuple(args.boost_comps or ()),
        version=args.pkg_version,
        description=args.description,
        licenses=tuple(args.license or ()),
        authors=tuple(args.author or ()),
        maintainers=tuple(args.maintainer or ()),
    )
    parent = working_directory(env)
    plan = plan_package(request, user=_user(env))
    errors, warnings = plan.manifest.problems()
    for line in [*plan.warnings, *(f"WARNING: {w}" for w in warnings)]:
        env.err(line)
    try:
        if errors:
            raise CreateError("\n".join(errors))
        lines = create_package(parent, plan)
    except (CreateError, OSError) as error:
        raise CommandError(
            f"{parser.format_usage().rstrip()}\ncatkin_create_pkg: error: {error}",
            ExitStatus.USAGE,
        ) from None
    for line in lines:
        env.out(line)
    env.out(
        f"Successfully created files in {parent / request.name}. "
        "Please adjust the values in package.xml."
    )
    return ExitStatus.OK


def _user(env: Environment) -> str:
    for variable in ("LOGNAME", "USER", "LNAME", "USERNAME"):
        if env.environ.get(variable):
            return env.environ[variable]
    return getpass.getuser()


def catkin_create_pkg(argv: Sequence[str], env: Environment) -> int:
    """Run ``catkin_create_pkg ARGV…``."""
    return run_command(_catkin_create_pkg, list(argv), env)
