"""``rosx rqt_topic``: every topic with its type, bandwidth, rate and latest message, live.

The view (`rosx_commands.rqt_topic.app`) needs a terminal; what it measures comes from
`rosx_commands.rqt_topic.monitor`, with the statistics of ``rostopic hz`` and ``bw``.
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

USAGE = """usage: %prog

Every published topic with its type; space monitors the topic under the cursor (its
bandwidth, rate and latest message, a tree enter expands), q quits."""


def rqt_topic(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx rqt_topic ARGV…``."""
    return run_command(_rqt_topic, list(argv), env)


def _rqt_topic(argv: list[str], env: Environment) -> int:
    _, rest = ToolParser(env, "rqt_topic", USAGE).parse(argv)
    if rest:
        raise CommandError(f"rqt_topic: error: unexpected argument {rest[0]!r}", ExitStatus.USAGE)
    if not env.stdout_isatty:
        raise CommandError("rqt_topic: error: the view needs a terminal", ExitStatus.USAGE)
    from rosx_commands.rqt_topic.app import make_topic_app  # noqa: PLC0415 - this tool's parts load only when used
    from rosx_commands.rqt_topic.monitor import LiveTopicSource  # noqa: PLC0415 - this tool's parts load only when used

    make_topic_app(LiveTopicSource(env)).run()
    return ExitStatus.OK
