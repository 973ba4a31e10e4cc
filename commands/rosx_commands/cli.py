"""Argument parsing for the ROS-named tools, with ROS 1's own option parser.

ROS 1's rostopic, rosnode, rosmsg, rosservice and rosparam parse their arguments with the
standard library's optparse; parsing the same way gives the same ``-h`` text, the same usage
errors (``Usage: …`` / ``tool: error: …``, exit 2) and, unlike a richer framework, costs a tool
almost nothing at start-up, which is what keeps ``rosx rostopic list`` fast. The ``rosx`` menu
and rosx's own commands use typer (`rosx_commands.main`).
"""

from __future__ import annotations

from functools import cache
from types import SimpleNamespace

from rosx_commands.context import CommandError, Environment, ExitStatus

TYPE_CHECKING = False
if TYPE_CHECKING:
    import optparse
    from collections.abc import Callable
    from typing import Any, NoReturn


class HelpShown(Exception):  # noqa: N818 - a signal to stop, not an error
    """``-h`` was given: the help has been printed and the tool exits with status 0."""


class ToolParser:
    """ROS 1's optparse parser of one command, writing to its streams and raising, not exiting.

    optparse (with textwrap, gettext and locale) is imported only when the arguments hold an
    option, or for an error: ``rosparam get /`` or ``rostopic list`` gets the options' defaults
    and its words as they are, which is what optparse would return, 2-3 ms sooner.
    """

    def __init__(self, env: Environment, prog: str, usage: str) -> None:
        self.env = env
        self.prog = prog
        self.usage = usage
        self.description: str | None = None
        self.epilog: str | None = None
        self.formatter: optparse.HelpFormatter | None = None
        self._options: list[tuple[tuple[str, ...], dict[str, Any]]] = []
        self._parser: optparse.OptionParser | None = None

    def add_option(self, *flags: str, **settings: Any) -> None:
        """As `optparse.OptionParser.add_option`."""
        self._options.append((flags, settings))
        if self._parser is not None:
            self._parser.add_option(*flags, **settings)

    def parse(self, argv: list[str]) -> tuple[Any, list[str]]:
        """The options (by ``dest``) and the remaining arguments, as optparse gives them."""
        defaults = None if any(arg.startswith("-") for arg in argv) else self._defaults()
        if defaults is None:
            return self.optparse().parse_args(argv)
        return SimpleNamespace(**defaults), list(argv)

    def error(self, msg: str) -> NoReturn:
        """A usage error: ``Usage: …`` and ``prog: error: msg``, exit status 2."""
        self.optparse().error(msg)

    def optparse(self) -> optparse.OptionParser:
        """The optparse parser itself, built on first use."""
        if self._parser is None:
            self._parser = _option_parser_class()(self.env, self.prog, self.usage)
            self._parser.description = self.description
            self._parser.epilog = self.epilog
            if self.formatter is not None:
                self._parser.formatter = self.formatter
                self.formatter.set_parser(self._parser)
            for flags, settings in self._options:
                self._parser.add_option(*flags, **settings)
        return self._parser

    def _defaults(self) -> dict[str, Any] | None:
        """optparse's default values, or None where only optparse can tell them."""
        defaults: dict[str, Any] = {}
        for flags, settings in self._options:
            default = settings.get("default")
            if isinstance(default, str) and settings.get("type", "string") != "string":
                return None  # optparse converts such a default with the option's type
            dest = settings.get("dest")
            if dest is None and (settings.get("action", "store") in _STORING or "type" in settings):
                dest = _dest(flags)
            if dest is not None and ("default" in settings or dest not in defaults):
                defaults[dest] = default
        return defaults


#: optparse's actions that store a value, and so have a ``dest`` even when none is given.
_STORING = ("store", "store_const", "store_true", "store_false", "append", "append_const", "count")


def _dest(flags: tuple[str, ...]) -> str | None:
    """The ``dest`` optparse derives from an option's flags (``--dry-run`` → ``dry_run``)."""
    long = [flag for flag in flags if flag.startswith("--")]
    if long:
        return long[0][2:].replace("-", "_")
    short = [flag for flag in flags if len(flag) == 2 and flag[0] == "-"]
    return short[0][1] if short else None


@cache
def _option_parser_class() -> Callable[[Environment, str, str], optparse.OptionParser]:
    import optparse  # noqa: PLC0415 - see ToolParser

    class OptionParser(optparse.OptionParser):
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

    return OptionParser


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


def run_command(
    command: object, argv: list[str], env: Environment, *, error_status: int = ExitStatus.ERROR
) -> int:
    """Run one sub-command function ``command(argv, env) -> status`` with error mapping: the
    core's errors (`rosx_commands.errors`) exit with ``error_status``."""
    try:
        status = command(argv, env)  # type: ignore[operator]
    except HelpShown:
        return ExitStatus.OK
    except CommandError as error:
        if error.message:
            env.err(error.message)
        return error.status
    except BrokenPipeError:
        return ExitStatus.ERROR
    except KeyboardInterrupt:
        return ExitStatus.OK
    except Exception as error:
        from rosx_commands.errors import command_error  # noqa: PLC0415 - only on failure

        mapped = command_error(error, env, error_status)
        if mapped is None:
            raise
        env.err(mapped.message)
        return mapped.status
    return int(status or 0)
