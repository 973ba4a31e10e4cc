"""``roslib.names`` for scripts that rosx runs (see the ``roslib`` package): rosgraph's names
and roslib's resource names."""

from rosx.client.rosgraph_names import *  # noqa: F403
from rosx.client.roslib import (
    BASE_RESOURCE_NAME_LEGAL_CHARS_P,
    PRN_SEPARATOR,
    RESOURCE_NAME_LEGAL_CHARS_P,
    TYPE_SEPARATOR,
    is_legal_resource_base_name,
    is_legal_resource_name,
    package_resource_name,
    resource_name,
    resource_name_base,
    resource_name_package,
)

__all__ = [  # noqa: PLE0604 - rosgraph's names, then roslib's own
    *__import__("rosx.client.rosgraph_names").client.rosgraph_names.__all__,
    "BASE_RESOURCE_NAME_LEGAL_CHARS_P",
    "PRN_SEPARATOR",
    "RESOURCE_NAME_LEGAL_CHARS_P",
    "TYPE_SEPARATOR",
    "is_legal_resource_base_name",
    "is_legal_resource_name",
    "package_resource_name",
    "resource_name",
    "resource_name_base",
    "resource_name_package",
]
