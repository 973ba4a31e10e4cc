"""``rosx rqt``: rqt's tools (graph, plot, topic monitor, …) as tabs of one terminal app.

The tabs are registered in `rosx_commands.rqt.tabs` (the tools add themselves there); the
app is `rosx_commands.rqt.app`. ``-s NAME`` opens on the tab of that name.
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

USAGE = """usage: %prog [-s TAB]

The rqt tools as tabs of one terminal app: ctrl+pageup/pagedown or f1…f9 switch tabs,
q quits."""


def rqt(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx rqt ARGV…``."""
    return run_command(_rqt, list(argv), env)


def _rqt(argv: list[str], env: Environment) -> int:
    from rosx_commands.rqt.tabs import TABS  # noqa: PLC0415 - this tool's parts load only when used

    parser = ToolParser(env, "rqt", USAGE)
    names = [tab.name for tab in TABS]
    parser.add_option(
        "-s",
        "--standalone",
        dest="tab",
        metavar="TAB",
        help=f"open on this tab: {', '.join(names)}",
    )
    options, rest = parser.parse(argv)
    if rest:
        parser.error(f"unexpected argument {rest[0]!r}")
    tab = options.tab.removeprefix("rqt_") if options.tab else None
    if tab is not None and tab not in names:
        parser.error(f"unknown tab {options.tab!r} (one of: {', '.join(names)})")
    if not env.stdout_isatty:
        raise CommandError("rqt: error: the app needs a terminal", ExitStatus.USAGE)
    from rosx_commands.rqt.app import make_rqt_app  # noqa: PLC0415 - this tool's parts load only when used

    make_rqt_app(env, first=tab).run()
    return ExitStatus.OK
