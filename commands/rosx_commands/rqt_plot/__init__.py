"""``rosx rqt_plot [TOPIC/FIELD…]``: numeric fields of messages plotted live in the terminal.

As rqt_plot: each argument names a field (``/turtle1/pose/x``), several separated by commas,
or sharing a topic with rqt_plot's colon shorthand (``/turtle1/pose/x:y``); unlike rqt_plot,
array elements plot too (``/scan/ranges[0]``). The view (`rosx_commands.rqt_plot.app`) needs a
terminal; the samples are kept in ring buffers (`rosx_commands.rqt_plot.series`).
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

USAGE = """usage: %prog [options] [TOPIC/FIELD ...]

Plot numeric fields of topics live: /turtle1/pose/x, /turtle1/pose/x:y (several fields of one
topic), /a/x,/b/y, /scan/ranges[0] (an array element). Keys: a add, x remove, space pause,
c clear, s autoscale or fixed y axes, [ ] time window, q quits."""


def _parser(env: Environment) -> ToolParser:
    parser = ToolParser(env, "rqt_plot", USAGE)
    add = parser.add_option
    add("-P", "--pause", dest="pause", default=False, action="store_true", help="start paused")
    add(
        "-e",
        "--empty",
        dest="empty",
        default=False,
        action="store_true",
        help="start without any series (the arguments are ignored)",
    )
    add(
        "-w",
        "--window",
        dest="window",
        type="float",
        default=10.0,
        metavar="SECONDS",
        help="the time window shown [default: %default]",
    )
    add("--ymin", dest="ymin", type="float", metavar="Y", help="fixed lower y limit")
    add("--ymax", dest="ymax", type="float", metavar="Y", help="fixed upper y limit")
    add(
        "--fps",
        dest="fps",
        type="float",
        default=10.0,
        metavar="N",
        help="most redraws a second [default: %default]",
    )
    return parser


def rqt_plot(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx rqt_plot ARGV…``."""
    return run_command(_rqt_plot, list(argv), env)


def _rqt_plot(argv: list[str], env: Environment) -> int:
    from rosx_commands.rqt_plot.series import SeriesError, expand_args  # noqa: PLC0415 - this tool's parts load only when used

    parser = _parser(env)
    options, args = parser.parse(argv)
    try:
        names = [] if options.empty else expand_args(args)
    except SeriesError as error:
        parser.error(str(error))
    if options.window <= 0:
        parser.error("--window must be positive")
    if options.fps <= 0:
        parser.error("--fps must be positive")
    if (options.ymin is None) != (options.ymax is None):
        parser.error("give both --ymin and --ymax (fixed axes), or neither (autoscale)")
    if options.ymin is not None and options.ymin >= options.ymax:
        parser.error("--ymin must be below --ymax")
    if not env.stdout_isatty:
        raise CommandError("rqt_plot: error: the plot needs a terminal", ExitStatus.USAGE)
    from rosx_commands.rqt_plot.app import PlotSettings, make_plot_app  # noqa: PLC0415 - this tool's parts load only when used
    from rosx_commands.rqt_plot.feed import LiveFeed  # noqa: PLC0415 - this tool's parts load only when used

    settings = PlotSettings(
        window=options.window,
        ymin=options.ymin,
        ymax=options.ymax,
        paused=options.pause,
        fps=options.fps,
    )
    make_plot_app(LiveFeed(env), names, settings).run()
    return ExitStatus.OK
