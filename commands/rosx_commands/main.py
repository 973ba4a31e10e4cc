"""The ``rosx`` entry point: one sub-command per ROS tool, each loaded only when used.

``rosx rostopic list`` imports the rostopic module and nothing else of the CLI, so short
commands stay fast; ``rosx --help`` builds the whole menu.
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Sequence
from typing import Annotated

import typer

import rosx
from rosx_commands.cli import run_app
from rosx_commands.context import Environment

Tool = Callable[[Sequence[str], Environment], int]

#: Tool name → (module:function, one-line help).
TOOLS: dict[str, tuple[str, str]] = {
    "rosmsg": ("rosx_commands.rosmsg:rosmsg", "Show information about ROS message types."),
    "rossrv": ("rosx_commands.rosmsg:rossrv", "Show information about ROS service types."),
    "rostopic": ("rosx_commands.rostopic:rostopic", "Print information about ROS topics."),
    "rosnode": ("rosx_commands.rosnode:rosnode", "Print information about ROS nodes."),
}


def load_tool(name: str) -> Tool:
    module_name, _, function = TOOLS[name][0].partition(":")
    tool: Tool = getattr(importlib.import_module(module_name), function)
    return tool


def run_tool(argv: Sequence[str], env: Environment | None = None) -> int:
    """Run ``rosx ARGV…`` and return its exit status (the tests' way in)."""
    env = env or Environment()
    if argv and argv[0] in TOOLS:
        return load_tool(argv[0])(argv[1:], env)
    return _run_root(argv, env)


def build_root_app() -> typer.Typer:
    """The ``rosx`` menu: ``--help``, ``--version`` and every tool as a sub-command."""
    app = typer.Typer(
        help="The ROS 1 command-line world. Each sub-command is the ROS tool of that name.",
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


def _add_forwarder(app: typer.Typer, name: str, help_text: str) -> None:
    settings = {"ignore_unknown_options": True, "allow_extra_args": True, "help_option_names": []}

    @app.command(name, help=help_text, context_settings=settings, add_help_option=False)
    def forward(ctx: typer.Context) -> None:
        raise typer.Exit(load_tool(name)(ctx.args, ctx.obj))


def _run_root(argv: Sequence[str], env: Environment) -> int:

    return run_app(build_root_app(), list(argv) or ["--help"], env, tool="rosx", usages={})


def run() -> None:
    """Console-script entry point."""
    sys.exit(run_tool(sys.argv[1:]))
