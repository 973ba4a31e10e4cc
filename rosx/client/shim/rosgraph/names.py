"""``rosgraph.names`` for scripts that rosx runs (see the package docstring)."""

from rosx.client.rosgraph_names import *  # noqa: F403
from rosx.client.rosgraph_names import __all__  # noqa: F401
