"""actionlib_tools' ``axclient.py`` and ``axserver.py``: a goal client and a stand-in server
for any action, in the terminal (``rosx rosrun actionlib_tools axclient.py /fibonacci``).

Both are nodes of rosx's rospy API (``/axclient_<pid>_<ms>``, anonymous as ROS 1's): axclient
is a `SimpleActionClient` (`client_app`), axserver a `SimpleActionServer` whose goals the user
ends (`standin`, `server_app`). Their command lines and usage errors are ROS 1's; where ROS 1
needs a type it can find, axclient asks the master for the type of ``<action>/goal``, and
axserver takes ``pkg/Name`` as well as ``pkg/NameAction`` (ROS 1's own example, ``axserver.py
my_action actionlib/Test``, fails its assertion). The views need a terminal.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

if TYPE_CHECKING:
    from types import ModuleType

    from rosx_commands.actionlib_tools.forms import ActionTypes
    from rosx_commands.actionlib_tools.server_app import ServerPane
    from rosx_commands.actionlib_tools.standin import Standin

USAGE = "usage: %prog /action_name action_type"


def axclient(argv: Sequence[str], env: Environment) -> int:
    """Run ``axclient.py ARGV…``."""
    return run_command(_axclient, list(argv), env)


def axserver(argv: Sequence[str], env: Environment) -> int:
    """Run ``axserver.py ARGV…``."""
    return run_command(_axserver, list(argv), env)


def _arguments(prog: str, argv: list[str], env: Environment) -> tuple[ToolParser, list[str]]:
    from rosx.names import strip_remap_args  # noqa: PLC0415 - rospy.myargv's rule

    parser = ToolParser(env, prog, USAGE)
    _, args = parser.parse(strip_remap_args(argv))
    return parser, args


def _axclient(argv: list[str], env: Environment) -> int:
    parser, args = _arguments("axclient.py", argv, env)
    if len(args) == 1:
        name = args[0].rstrip("/")
        topic = f"{name}/goal" if name.startswith("/") else f"/{name}/goal"
        found = env.master("/axclient").topic_types().get(topic)
        if found is None:
            parser.error(
                f"unable to retrieve the topic type for goal topic '{name}/goal'\n"
                f"Are you sure the action server for '{name}' is running?"
            )
        if not found.endswith("ActionGoal"):
            parser.error(f"topic '{name}/goal' is not an action goal topic")
        action_type = found[: -len("Goal")]
    elif len(args) == 2:
        name, action_type = args
        env.out(action_type)
        if not action_type.endswith("Action"):
            parser.error(
                f"the action type provided '{action_type}' doesn't end with the 'Action' suffix"
            )
    else:
        parser.error(
            "You must specify the action topic name (and optionally type) Eg: ./axclient.py "
            "action_topic actionlib/TwoIntsAction "
        )
    types = _types(action_type, env)
    rospy = _node("axclient", env)
    from rosx.actionlib import SimpleActionClient  # noqa: PLC0415 - after the node
    from rosx_commands.actionlib_tools.client_app import make_client_app  # noqa: PLC0415 - TUI

    try:
        make_client_app(types, name, SimpleActionClient(name, types.action)).run()
    finally:
        rospy.signal_shutdown("GUI shutdown")
    return ExitStatus.OK


def _axserver(argv: list[str], env: Environment) -> int:
    parser, args = _arguments("axserver.py", argv, env)
    if len(args) != 2:
        parser.error(
            "You must specify the action name and type. Eg: ./axserver.py my_action actionlib/Test"
        )
    name, action_type = args
    types = _types(action_type, env)
    rospy = _node("axserver", env)
    from rosx_commands.actionlib_tools.server_app import make_server_app  # noqa: PLC0415 - TUI
    from rosx_commands.actionlib_tools.standin import Standin  # noqa: PLC0415 - after the node

    standins: list[Standin] = []

    def standin(pane: ServerPane) -> Standin:
        standins.append(Standin(types, name, pane.report))
        return standins[0]

    try:
        make_server_app(types, name, standin).run()
    finally:
        for made in standins:
            made.close()
        rospy.signal_shutdown("GUI shutdown")
    return ExitStatus.OK


def _types(action_type: str, env: Environment) -> ActionTypes:
    from rosx_commands.actionlib_tools.forms import FormError, action_types  # noqa: PLC0415 - this tool's parts load only when used

    try:
        return action_types(action_type)
    except FormError as error:
        raise CommandError(str(error), ExitStatus.ERROR) from None


def _node(name: str, env: Environment) -> ModuleType:
    """rosx's rospy, as the anonymous node ``name``, once the view can be shown."""
    if not env.stdout_isatty:
        raise CommandError(f"{name}.py: error: the view needs a terminal", ExitStatus.USAGE)
    import rosx.client as rospy  # noqa: PLC0415 - the node starts with the view

    rospy.init_node(name, anonymous=True, disable_signals=True)
    return rospy


__all__ = ["axclient", "axserver"]
