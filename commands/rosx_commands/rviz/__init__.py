"""``rosx rviz [-d CONFIG.rviz] [-f FIXED_FRAME]``: rviz's 2-D displays and tools in a terminal.

It reads rviz's own ``.rviz`` files (`config`), draws each display through tf into the fixed
frame (`displays`, `manager`, `painter`, `cells`), shows rviz's statuses in a Displays panel
(`panel`), and publishes rviz's goal, pose-estimate and point tools (`tools`). The textual
app is `app`; the ROS side `live`. Without ``-d`` it loads ``~/.rviz/default.rviz`` if there
is one, else the bundled rviz package's ``default.rviz``, as rviz does; ``ctrl+s`` saves back
to the file it loaded (``~/.rviz/default.rviz`` for the bundled one).

rviz's other options (``-s``, ``-l``, ``--fullscreen``, ``--opengl``…) are accepted and have
nothing to do here.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

USAGE = """usage: %prog [-d CONFIG.rviz] [-f FIXED_FRAME]

rviz in the terminal: the fixed frame seen from above with rviz's 2-D displays (Grid, Map,
LaserScan, PointCloud2, TF, Path, Odometry, Pose, PoseArray, Polygon, Marker, MarkerArray,
RobotModel, Image) and tools. Keys: g 2D Nav Goal, p 2D Pose Estimate, c Publish Point (then
click, or Enter at the centre; [ ] turn), arrows pan, + - zoom, f follow a frame, 1-9 show or
hide a display, ctrl+s save the config, o write a PNG, q quits."""


def _parser(env: Environment) -> ToolParser:
    parser = ToolParser(env, "rviz", USAGE)
    add = parser.add_option
    add(
        "-d",
        "--display-config",
        dest="config",
        metavar="CONFIG",
        help="A display config file (.rviz) to load",
    )
    add("-f", "--fixed-frame", dest="fixed_frame", metavar="FRAME", help="Set the fixed frame")
    add(
        "-s",
        "--splash-screen",
        dest="splash",
        metavar="IMAGE",
        help="A custom splash-screen image to display (ignored)",
    )
    add("--help-file", dest="help_file", metavar="FILE", help="(ignored)")
    for flag in (
        "--fullscreen",
        "--in-mc-wrapper",
        "--disable-anti-aliasing",
        "--no-stereo",
        "--log-level-debug",
    ):
        add(flag, action="store_true", default=False, help="(ignored)")
    add("-l", "--ogre-log", dest="ogre_log", action="store_true", default=False, help="(ignored)")
    add("-v", "--verbose", dest="verbose", action="store_true", default=False, help="(ignored)")
    add("--opengl", dest="opengl", type="int", metavar="VERSION", help="(ignored)")
    return parser  # fmt: skip


def rviz(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx rviz ARGV…``."""
    return run_command(_rviz, list(argv), env)


def _rviz(argv: list[str], env: Environment) -> int:
    from rosx_commands.rviz.config import ConfigError, load_config  # noqa: PLC0415 - this tool's parts load only when used
    from rosx_commands.rviz.defaults import default_config_path, starting_config  # noqa: PLC0415 - this tool's parts load only when used

    parser = _parser(env)
    options, args = parser.parse(argv)
    args = [arg for arg in args if ":=" not in arg]  # remapping arguments, as ros::init takes
    if args:
        parser.error(f"unexpected argument {args[0]!r}")
    if options.fixed_frame is not None and not options.fixed_frame.strip("/"):
        parser.error("the fixed frame cannot be empty")
    try:
        if options.config is not None:
            save_path = Path(options.config)
            config = load_config(options.config)
        else:
            save_path = default_config_path(env)
            config = starting_config(save_path)
    except ConfigError as error:
        raise CommandError(f"rviz: {error}", ExitStatus.ERROR) from None
    if not env.stdout_isatty:
        raise CommandError("rviz: error: the view needs a terminal", ExitStatus.USAGE)
    from rosx_commands.rviz.run import run_rviz  # noqa: PLC0415 - this tool's parts load only when used

    run_rviz(env, config, options.fixed_frame, save_path)
    return ExitStatus.OK
