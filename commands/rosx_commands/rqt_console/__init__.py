"""``rosx rqt_console``: every node's log (``/rosout_agg``) as a table, filtered and highlighted.

On a terminal, a full-screen table (`rosx_commands.rqt_console.app`); when stdout is not a
terminal (or with ``--text``), one line per record that passes the rules, as it arrives, until
Ctrl-C. Rules given with ``--include``, ``--exclude`` and ``--highlight`` (repeatable) are those
the ``i``, ``x`` and ``h`` keys add: ``FIELD:PATTERN``, field one of severity, node, text,
topic, location; a bare pattern is on the text.
"""

from __future__ import annotations

import time
from collections.abc import Sequence

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx_commands.rqt_console.model import Rules
    from rosx_commands.rqt_console.source import LiveSource

USAGE = """usage: %prog [options]

Show the log of every node (/rosout_agg): time, severity, node, message, topics, location.
On a terminal: i/x/h add an include/exclude/highlight rule, u undoes one, p pauses, c clears,
the arrows select an entry (its details show below), q or Ctrl-C quits."""


def _parser(env: Environment) -> ToolParser:
    parser = ToolParser(env, "rqt_console", USAGE)
    add = parser.add_option
    for flag, dest, text in (
        ("--include", "include", "show only entries that match RULE (any include rule)"),
        ("--exclude", "exclude", "hide entries that match RULE"),
        ("--highlight", "highlight", "highlight entries that match RULE"),
    ):
        add(flag, dest=dest, action="append", metavar="RULE", help=text)
    add(
        "--limit",
        dest="limit",
        type="int",
        default=100_000,
        metavar="N",
        help="entries kept; the oldest go first [default: %default]",
    )
    add(
        "--text",
        dest="text",
        default=False,
        action="store_true",
        help="print the records as lines instead of the table",
    )
    return parser


def rqt_console(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx rqt_console ARGV…``."""
    return run_command(_rqt_console, list(argv), env)


def _rqt_console(argv: list[str], env: Environment) -> int:
    from rosx_commands.rqt_console.model import Kind, Rule, RuleError, Rules  # noqa: PLC0415 - this tool's parts load only when used
    from rosx_commands.rqt_console.source import LiveSource  # noqa: PLC0415 - this tool's parts load only when used

    options, rest = _parser(env).parse(argv)
    if rest:
        raise CommandError(f"rqt_console: error: unexpected argument {rest[0]!r}", ExitStatus.USAGE)
    rules = Rules()
    for kind in Kind:
        for text in getattr(options, kind.value, None) or []:
            try:
                rules = rules.with_rule(Rule.parse(kind, text))
            except RuleError as error:
                raise CommandError(f"rqt_console: error: {error}", ExitStatus.USAGE) from None
    if options.limit < 1:
        raise CommandError("rqt_console: error: --limit must be at least 1", ExitStatus.USAGE)
    source = LiveSource(env, env.master_uri, options.limit)
    if not options.text and env.stdout_isatty:
        from rosx_commands.rqt_console.app import make_console_app  # noqa: PLC0415 - textual

        make_console_app(source, rules, limit=options.limit).run()
        return ExitStatus.OK
    return _print_lines(source, rules, env)


def _print_lines(source: LiveSource, rules: Rules, env: Environment) -> int:
    """Print each record that passes ``rules`` as ``[severity] [time] [node]: message``."""
    from rosx_commands.rqt_console.model import stamp_text  # noqa: PLC0415 - this tool's parts load only when used

    shows = rules.matcher()
    source.start()
    try:
        while True:
            for entry in source.inbox.take():
                if shows(entry):
                    env.out(
                        f"[{entry.severity.upper()}] [{stamp_text(entry.stamp)}] "
                        f"[{entry.node}]: {entry.message}"
                    )
            env.stdout.flush()
            time.sleep(0.1)
    finally:
        source.close()
