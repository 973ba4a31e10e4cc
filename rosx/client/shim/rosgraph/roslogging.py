"""``rosgraph.roslogging`` for scripts that rosx runs (see the package docstring)."""

from rosx.client.roslogging import *  # noqa: F403
from rosx.client.roslogging import __all__  # noqa: F401
