"""``rospy.names`` for scripts that rosx runs (see the package docstring)."""

from rosx.client.names import *  # noqa: F403
from rosx.client.names import (
    __all__,  # noqa: F401
    _set_caller_id,  # noqa: F401
)
