"""argparse with the streams and exits of `rosx_commands.cli`, for what ROS 1 parses with argparse.

A module of its own so the tools that do not need argparse do not import it.
"""

from __future__ import annotations

import argparse
import functools
import sys

from rosx_commands.cli import HelpShown
from rosx_commands.context import CommandError, Environment

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any, NoReturn


class ToolArgumentParser(argparse.ArgumentParser):
    """The argparse counterpart of `ToolParser`, for the sub-commands ROS 1 parses with argparse."""

    def __init__(self, env: Environment, prog: str, **options: Any) -> None:
        super().__init__(prog=prog, **options)
        self.env = env

    def add_commands(self, dest: str) -> Any:
        """Sub-commands (``add_subparsers``, required) whose parsers write where this one does."""
        # argparse builds each sub-command's parser as ``parser_class(prog=…)``.
        factory: Any = functools.partial(ToolArgumentParser, self.env)
        return self.add_subparsers(required=True, dest=dest, parser_class=factory)

    def _print_message(self, message: str, file: object = None) -> None:
        if message:
            (self.env.stderr if file is sys.stderr else self.env.stdout).write(message)

    def exit(self, status: int = 0, message: str | None = None) -> NoReturn:
        """Raise instead of exiting: `HelpShown` after ``--help`` (status 0), else `CommandError`
        with argparse's status, its message already written to the environment's stderr."""
        if message:
            self.env.stderr.write(message)
        if status == 0:
            raise HelpShown
        raise CommandError("", status)

    def parse(self, argv: list[str]) -> Any:
        """``argv`` parsed into a namespace; raises as `exit` does on a usage error."""
        return self.parse_args(argv)
