"""The ``rosx`` menu (typer): ``--help``, ``--version`` and every tool as a sub-command."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Annotated

import typer

import rosx
from rosx_commands.context import CommandError, Environment, ExitStatus
from rosx_commands.tools import TOOLS, load_tool

#: typer carries click's UsageError (its own copy in recent releases) as BadParameter's base.
UsageError: type[Exception] = next(
    c for c in typer.BadParameter.__mro__ if c.__name__ == "UsageError"
)


def build_menu() -> typer.Typer:
    """The typer app of ``rosx --help``: every tool as a sub-command that forwards its arguments."""
    app = typer.Typer(
        help="The ROS 1 command-line world. Each sub-command is the ROS tool of that name.",
        epilog=_packages_epilog(),
        context_settings={"help_option_names": ["-h", "--help"]},
        add_completion=False,
        pretty_exceptions_enable=False,
    )

    @app.callback(invoke_without_command=True)
    def root(
        ctx: typer.Context,
        version: Annotated[
            bool, typer.Option("--version", help="Print the version and exit.")
        ] = False,
    ) -> None:
        if version:
            ctx.obj.out(f"rosx {rosx.__version__}")
            raise typer.Exit(0)
        if ctx.invoked_subcommand is None:
            ctx.obj.out(ctx.get_help())

    for name, (_, help_text) in TOOLS.items():
        _add_forwarder(app, name, help_text)
    return app


def _packages_epilog() -> str:
    """The ROS packages that come with rosx, for the end of ``rosx --help``."""
    from rosx.workspace.programs import provided_packages  # noqa: PLC0415 - the help only

    return (
        "ROS packages that come with rosx (rospack, roscd, rosrun and roslaunch find them): "
        + ", ".join(provided_packages())
        + ". Others, such as gazebo_ros or move_base, are not part of rosx: use your own "
        "packages on ROS_PACKAGE_PATH."
    )


def _add_forwarder(app: typer.Typer, name: str, help_text: str) -> None:
    settings = {"ignore_unknown_options": True, "allow_extra_args": True, "help_option_names": []}

    @app.command(name, help=help_text, context_settings=settings, add_help_option=False)
    def forward(ctx: typer.Context) -> None:
        raise typer.Exit(load_tool(name)(ctx.args, ctx.obj))


def run_typer(app: typer.Typer, argv: Sequence[str], env: Environment, prog: str) -> int:
    """Run a typer app on ``argv`` with ``env`` as its context object; errors become statuses."""
    command = typer.main.get_command(app)
    try:
        result = command.main(args=list(argv), prog_name=prog, standalone_mode=False, obj=env)
    except CommandError as error:
        env.err(error.message)
        return error.status
    except UsageError as error:
        text = str(getattr(error, "format_message", error.__str__)())
        env.err(f"{prog}: error: {text}")
        return ExitStatus.USAGE
    except typer.Exit as done:
        return int(done.exit_code)
    except typer.Abort:
        return ExitStatus.ERROR
    return result if isinstance(result, int) else ExitStatus.OK


def run_menu(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx ARGV…`` through the menu; the exit status."""
    return run_typer(build_menu(), argv, env, "rosx")
