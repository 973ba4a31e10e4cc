"""actionlib for scripts: long-running goals with feedback, cancel and preempt, as ROS 1's
``actionlib`` (python3-actionlib) serves them, wire-compatible with it.

Modules, named as ROS 1's (scripts import them by those names from `SHIM_DIR`):

- `states`: the goal state machines as tables (server status, client comm state, simple
  state), pure, tested without sockets.
- `protocol`: the topics of an action, ``actionlib_msgs``' classes, an action's types.
- `action_server` (`ActionServer`), `server_goal_handle`, `status_tracker`,
  `goal_id_generator`: the server side.
- `action_client` (`ActionClient`, `ClientGoalHandle`, `CommState`, `TerminalState`): the
  client side.
- `simple_action_server` and `simple_action_client`: one goal at a time.
- `exceptions`: `ActionException`.

Everything stands on rosx's rospy API (`rosx.client`): servers and clients are parts of the
process's node, as in a rospy script. This package imports `rosx.client` and below; importing
it loads none of its modules.
"""

from __future__ import annotations

from pathlib import Path

from rosx._lazy import lazy_names

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx.actionlib.action_client import (
        ActionClient,
        ClientGoalHandle,
        CommState,
        TerminalState,
        get_name_of_constant,
    )
    from rosx.actionlib.action_server import ActionServer
    from rosx.actionlib.exceptions import ActionException
    from rosx.actionlib.goal_id_generator import GoalIDGenerator
    from rosx.actionlib.server_goal_handle import ServerGoalHandle
    from rosx.actionlib.simple_action_client import SimpleActionClient
    from rosx.actionlib.simple_action_server import SimpleActionServer
    from rosx.actionlib.states import SimpleGoalState

#: The import-path entry holding the ``actionlib`` module of users' scripts (the commands put
#: it on the path beside the client's, `rosx_commands.scripts.shim_dirs`).
SHIM_DIR = Path(__file__).resolve().parent / "shim"

_HOMES = {
    "ActionClient": "rosx.actionlib.action_client",
    "ActionException": "rosx.actionlib.exceptions",
    "ActionServer": "rosx.actionlib.action_server",
    "ClientGoalHandle": "rosx.actionlib.action_client",
    "CommState": "rosx.actionlib.action_client",
    "GoalIDGenerator": "rosx.actionlib.goal_id_generator",
    "ServerGoalHandle": "rosx.actionlib.server_goal_handle",
    "SimpleActionClient": "rosx.actionlib.simple_action_client",
    "SimpleActionServer": "rosx.actionlib.simple_action_server",
    "SimpleGoalState": "rosx.actionlib.states",
    "TerminalState": "rosx.actionlib.action_client",
    "get_name_of_constant": "rosx.actionlib.action_client",
}

__all__ = [
    "SHIM_DIR",
    "ActionClient",
    "ActionException",
    "ActionServer",
    "ClientGoalHandle",
    "CommState",
    "GoalIDGenerator",
    "ServerGoalHandle",
    "SimpleActionClient",
    "SimpleActionServer",
    "SimpleGoalState",
    "TerminalState",
    "get_name_of_constant",
]

__getattr__ = lazy_names(__name__, _HOMES)
