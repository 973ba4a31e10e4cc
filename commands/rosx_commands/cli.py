"""Argument parsing for the ROS-named tools, with ROS 1's own option parser.

ROS 1's rostopic, rosnode, rosmsg, rosservice and rosparam parse their arguments with the
standard library's optparse; parsing the same way gives the same ``-h`` text, the same usage
errors (``Usage: …`` / ``tool: error: …``, exit 2) and, unlike a richer framework, costs a tool
almost nothing at start-up, which is what keeps ``rosx rostopic list`` fast. The ``rosx`` menu
and rosx's own commands use typer (`rosx_commands.main`).
"""

from __future__ import annotations

import optparse
from typing import NoReturn

from rosx_commands.context import CommandError, Environment, ExitStatus


class HelpShown(Exception):  # noqa: N818 - a signal to stop, not an error
    """``-h`` was given: the help has been printed and the tool exits with status 0."""


class ToolParser(optparse.OptionParser):
    """An OptionParser that writes to the command's streams and raises instead of exiting."""

    def __init__(self, env: Environment, prog: str, usage: str) -> None:
        super().__init__(usage=usage, prog=prog)
        self.env = env

    def print_help(self, file: object = None) -> None:
        self.env.stdout.write(self.format_help())

    def exit(self, status: int = 0, msg: str | None = None) -> NoReturn:
        if msg:
            self.env.stderr.write(msg)
        if status == 0:
            raise HelpShown
        raise CommandError("", status)

    def error(self, msg: str) -> NoReturn:
        raise CommandError(
            f"{self.get_usage()}\n{self.get_prog_name()}: error: {msg}", ExitStatus.USAGE
        )

    def parse(self, argv: list[str]) -> tuple[optparse.Values, list[str]]:
        return self.parse_args(argv)


def commands_overview(
    tool: str,
    commands: list[tuple[str, str]],
    *,
    intro: str | None = None,
    footer: str | None = None,
) -> str:
    """What a ROS 1 tool prints without a (known) sub-command: intro, ``Commands:``, footer."""
    lines = [intro, ""] if intro else []
    lines += ["Commands:", *(f"\t{tool} {name}\t{text}" for name, text in commands)]
    lines += ["", footer, ""] if footer else [""]
    return "\n".join(lines)


def run_command(command: object, argv: list[str], env: Environment) -> int:
    """Run one sub-command function ``command(argv, env) -> status`` with error mapping."""
    try:
        status = command(argv, env)  # type: ignore[operator]
    except HelpShown:
        return ExitStatus.OK
    except CommandError as error:
        error.report(env)
        return error.status
    except BrokenPipeError:
        return ExitStatus.ERROR
    except KeyboardInterrupt:
        return ExitStatus.OK
    return int(status or 0)
