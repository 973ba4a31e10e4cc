"""The core: what ``roscore`` hosts, in this process, for every program that needs one.

    from rosx.core import Core, PortInUseError

    with Core(11311, os.environ) as core:   # master, parameters, /rosout
        print(core.uri, core.run_id)
        core.wait()                          # until a ``shutdown`` call (or `Core.stop`)

- `core`: `Core`: the master and parameter server (`rosx.master`), roscore's parameters and
  the ``/rosout`` node, started and stopped as one, from any thread but the event loop's.
- `errors`: `PortInUseError`, with roscore's words for a port that cannot be had.
- `params`: the parameters roscore sets (``/run_id``, ``/rosversion``, ``/rosdistro``, the
  launch URI).
- `rosout`: the ``/rosout`` node, which gathers every node's log on ``/rosout_agg``.

``rosx roscore``, ``rosx sim``, roslaunch (when no master answers) and the tests start their
core here; what roscore prints around it belongs to the roscore command.

Layering: above `rosx.node` and `rosx.master`, below the client API; this package uses
`rosx.master`, `rosx.node`, `rosx.msg`, `rosx.transport` and the standard library.
"""

from __future__ import annotations

from rosx._lazy import lazy_names

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx.core.core import Core
    from rosx.core.errors import PortInUseError

# `params` alone (roslaunch's printing options) does not start the node runtime's imports.
__getattr__ = lazy_names(__name__, {"Core": "rosx.core.core", "PortInUseError": "rosx.core.errors"})

__all__ = ["Core", "PortInUseError"]
