"""``actionlib`` for scripts that rosx runs: ROS 1's actionlib API, served by `rosx.actionlib`.

Like ``rospy`` (in the client layer's shim directory), this directory (`rosx.actionlib.SHIM_DIR`)
is on ``sys.path`` only for the scripts rosx runs. ROS 1's module paths are rosx's modules
(``actionlib.action_client`` is `rosx.actionlib.action_client` …), and the package has the
names ROS 1's ``actionlib/__init__.py`` gathers from them. ``actionlib.msg`` (TestAction …)
comes from the type store, as every ``<package>.msg`` does. A Python that cannot import rosx
gets the next ``actionlib`` on its path instead (``_rosx_shim``, in the client layer's shim
directory).
"""

from __future__ import annotations

import importlib
import sys

#: ROS 1's modules of actionlib, each served by rosx's module of the same name.
_MODULES = (
    "action_client",
    "action_server",
    "exceptions",
    "goal_id_generator",
    "handle_tracker_deleter",
    "server_goal_handle",
    "simple_action_client",
    "simple_action_server",
    "status_tracker",
)
#: The rosx module serving a ROS 1 module of another name.
_SERVED_BY = {"handle_tracker_deleter": "status_tracker"}


try:
    import rosx.actionlib  # noqa: F401 - whether this Python has rosx
    from rosx.client.modules import install as _install
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("actionlib")
else:
    _install()
    for _name in _MODULES:
        _module = importlib.import_module(f"rosx.actionlib.{_SERVED_BY.get(_name, _name)}")
        sys.modules[f"{__name__}.{_name}"] = _module
        globals()[_name] = _module
    from rosx.actionlib.action_client import *  # noqa: F403
    from rosx.actionlib.action_server import *  # noqa: F403
    from rosx.actionlib.exceptions import *  # noqa: F403
    from rosx.actionlib.goal_id_generator import *  # noqa: F403
    from rosx.actionlib.protocol import msgs as _msgs
    from rosx.actionlib.server_goal_handle import *  # noqa: F403
    from rosx.actionlib.simple_action_client import *  # noqa: F403
    from rosx.actionlib.simple_action_server import *  # noqa: F403
    from rosx.actionlib.status_tracker import *  # noqa: F403

    # ROS 1's package has these through its modules' own imports, and names GoalStatus's
    # constants (GoalStatus.to_string) on import.
    GoalID, GoalStatus, GoalStatusArray = _msgs()
    give_goal_status_its_names()  # noqa: F405 - from action_client
