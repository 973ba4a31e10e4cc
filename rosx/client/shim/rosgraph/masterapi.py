"""``rosgraph.masterapi`` for scripts that rosx runs (see the package docstring)."""

from rosx.client.rosgraph import (  # noqa: F401
    Error,
    Failure,
    Master,
    MasterError,
    MasterException,
    MasterFailure,
    ROSMasterException,
)
from rosx.client.rosgraph import is_master_online as is_online  # noqa: F401
