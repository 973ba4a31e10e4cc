"""``rospy.exceptions`` for scripts that rosx runs (see the package docstring)."""

from rosx.client.exceptions import *  # noqa: F403
from rosx.client.exceptions import __all__  # noqa: F401
