"""``rosx rqt_tf_tree``: the tf tree, live: each frame under its parent, with its broadcaster,
its average rate, how old its newest transform is and how much the buffer holds.

The view (`rosx_commands.rqt_tf_tree.app`) needs a terminal; the frames come from
`rosx_commands.rqt_tf_tree.source` (a buffer listening to ``/tf`` and ``/tf_static``), laid
out as a tree by `rosx_commands.rqt_tf_tree.source.tree_rows`.
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

USAGE = """usage: %prog

The tf tree of the running graph, live: each frame under its parent with its broadcaster,
rate, delay and buffer length (as rqt_tf_tree and view_frames show them); q quits."""


def rqt_tf_tree(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx rqt_tf_tree ARGV…``."""
    return run_command(_rqt_tf_tree, list(argv), env)


def _rqt_tf_tree(argv: list[str], env: Environment) -> int:
    _, rest = ToolParser(env, "rqt_tf_tree", USAGE).parse(argv)
    if rest:
        raise CommandError(f"rqt_tf_tree: error: unexpected argument {rest[0]!r}", ExitStatus.USAGE)
    if not env.stdout_isatty:
        raise CommandError("rqt_tf_tree: error: the view needs a terminal", ExitStatus.USAGE)
    from rosx_commands.rqt_tf_tree.app import make_tf_tree_app  # noqa: PLC0415 - this tool's parts load only when used
    from rosx_commands.rqt_tf_tree.source import LiveTfSource  # noqa: PLC0415 - this tool's parts load only when used

    make_tf_tree_app(LiveTfSource(env)).run()
    return ExitStatus.OK
