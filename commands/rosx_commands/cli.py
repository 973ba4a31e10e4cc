"""Running one tool's typer app: ROS 1-style usage errors, exit codes, no tracebacks."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import typer

from rosx_commands.context import CommandError, Environment, ExitStatus

#: typer carries click's UsageError (its own copy in recent releases) as BadParameter's base.
UsageError: type[Exception] = next(
    c for c in typer.BadParameter.__mro__ if c.__name__ == "UsageError"
)

CONTEXT_SETTINGS = {"help_option_names": ["-h", "--help"]}


def tool_app(help_text: str) -> typer.Typer:
    """A typer app for one ROS tool, with ROS 1's ``-h``."""
    return typer.Typer(
        help=help_text,
        context_settings=CONTEXT_SETTINGS,
        add_completion=False,
        pretty_exceptions_enable=False,
        rich_markup_mode=None,
    )


def usage_error(tool: str, usage: str, message: str) -> CommandError:
    """An optparse-style usage error: ``Usage: …``, blank line, ``tool: error: …``; exit 2."""
    return CommandError(f"Usage: {usage}\n\n{tool}: error: {message}", ExitStatus.USAGE)


def run_app(
    app: typer.Typer,
    argv: Sequence[str],
    env: Environment,
    *,
    tool: str,
    usages: Mapping[str, str],
) -> int:
    """Run ``app`` on ``argv``; ``usages`` maps sub-command names to ROS 1's usage lines."""
    command = typer.main.get_command(app)
    try:
        result = command.main(args=list(argv), prog_name=tool, standalone_mode=False, obj=env)
    except CommandError as error:
        env.err(error.message)
        return error.status
    except UsageError as error:
        context = getattr(error, "ctx", None)
        name = getattr(context, "info_name", None)
        usage = usages.get(name or "", f"{tool} [options]")
        text = str(getattr(error, "format_message", error.__str__)())
        env.err(usage_error(tool, usage, text[:1].lower() + text[1:]).message)
        return ExitStatus.USAGE
    except typer.Exit as done:
        return int(done.exit_code)
    except typer.Abort:
        return ExitStatus.ERROR
    except BrokenPipeError:
        return ExitStatus.ERROR
    return result if isinstance(result, int) else ExitStatus.OK
