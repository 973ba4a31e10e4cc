"""The part of ``roslib`` (and of ``genpy.message``) that ROS 1 scripts still call.

Scripts written before catkin start with ``import roslib; roslib.load_manifest('pkg')``. Under
catkin, ``load_manifest`` of a catkin package adds nothing to ``sys.path``, and rosx's modules
are importable already, so here it does nothing, for any package (ROS 1 raises
``ResourceNotFound`` for a package it cannot find; a script run from a file outside any
package, as ``rosx run-script`` allows, would then stop at its first line).

- packages: `get_pkg_dir`, `find_node`, `find_resource` (the package's ``lib/`` folder first,
  then the package, as catkin's ``find_resource``), with roslib's exceptions and texts;
- messages: `get_message_class`, `get_service_class` (None for an unknown type, as genpy's),
  `strify_message` (the text ``rostopic echo`` prints);
- names: roslib's resource-name helpers, beside rosgraph's (`rosx.client.rosgraph_names`).
"""

from __future__ import annotations

import os
import re
import stat
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.client.rospkg import RosPack
from rosx.msg.parser import package_resource_name

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.codec.message import Message, ServiceDefinition

PRN_SEPARATOR = "/"
TYPE_SEPARATOR = PRN_SEPARATOR
RESOURCE_NAME_LEGAL_CHARS_P = re.compile(r"^[A-Za-z][\w_\/]*$")
BASE_RESOURCE_NAME_LEGAL_CHARS_P = re.compile(r"^[A-Za-z][\w_]*$")

_interactive = False


def load_manifest(package_name: str, bootstrap_version: str = "0.7") -> None:
    """Nothing to do: catkin's packages need no path of their own (see the module docstring)."""


def set_interactive(interactive: bool) -> None:
    """Say whether the script runs in an interactive shell."""
    global _interactive  # noqa: PLW0603 - roslib's process-wide flag
    _interactive = interactive


def is_interactive() -> bool:
    """Whether `set_interactive` said so."""
    return _interactive


# -- roslib.packages ----------------------------------------------------------------------


class ROSPkgException(Exception):  # noqa: N818 - roslib's name
    """Base of roslib.packages' errors."""


class InvalidROSPkgException(ROSPkgException):
    """A package cannot be found, or is not a valid package."""


class MultipleNodesException(ROSPkgException):
    """Several programs of one name in a package."""


def get_pkg_dir(
    package: str,
    required: bool = True,
    ros_root: str | None = None,
    ros_package_path: str | None = None,
) -> str | None:
    """The directory of ``package``; `InvalidROSPkgException` (or None when not ``required``)
    when it cannot be found."""
    ros_root = ros_root if ros_root is not None else os.environ.get("ROS_ROOT")
    if ros_package_path is None:
        ros_package_path = os.environ.get("ROS_PACKAGE_PATH")
    paths = [p for p in [ros_root or "", *(ros_package_path or "").split(os.pathsep)] if p]
    try:
        return RosPack(paths).get_path(package)
    except Exception:  # roslib's own catch-all, then its text
        if not required:
            return None
        # rospack's stderr as roslib prints it on Python 3: the bytes' repr.
        error = f"[rospack] Error: package '{package}' not found".encode()
        raise InvalidROSPkgException(
            f"Cannot locate installation of package {package}: {error!r}. "
            f"ROS_ROOT[{ros_root}] ROS_PACKAGE_PATH[{ros_package_path}]"
        ) from None


def _executable(path: str) -> bool:
    flags = stat.S_IRUSR | stat.S_IXUSR
    return (Path(path).stat().st_mode & flags) == flags


def find_node(pkg: str, node_type: str, rospack: RosPack | None = None) -> list[str]:
    """The executables called ``node_type`` in package ``pkg`` (`find_resource`)."""
    return find_resource(pkg, node_type, filter_fn=_executable, rospack=rospack)


def find_resource(
    pkg: str,
    resource_name: str,
    filter_fn: Callable[[str], bool] | None = None,
    rospack: RosPack | None = None,
) -> list[str]:
    """The files called ``resource_name`` in package ``pkg`` (that ``filter_fn`` accepts): in
    its ``lib/`` folder first, then below the package. `rospkg.ResourceNotFound` when there
    is no such package."""
    from rosx.packages.crawl import bundled_libexec, libexec_dir  # noqa: PLC0415 - when asked

    package_dir = Path((rospack or RosPack()).get_path(pkg))
    roots = [libexec_dir(package_dir) or bundled_libexec(pkg), package_dir]
    matches: list[str] = []
    for root in [r for r in roots if r is not None]:
        for directory, subdirs, files in os.walk(root, followlinks=True):
            subdirs[:] = [d for d in subdirs if not d.startswith(".")]
            if resource_name in files:
                path = os.path.abspath(os.path.join(directory, resource_name))  # noqa: PTH100, PTH118 - roslib's strings
                if (filter_fn is None or filter_fn(path)) and path not in matches:
                    matches.append(path)
    return matches


# -- roslib.message / genpy.message -------------------------------------------------------


def _message_name(message_type: str) -> str:
    package, _, base = message_type.rpartition("/")
    if not package:
        if base != "Header":
            raise ValueError(f"message type is missing package name: {message_type}")
        return "std_msgs/Header"
    return message_type


def get_message_class(message_type: str, reload_on_error: bool = False) -> Any:
    """The class of message ``message_type`` (``time`` and ``duration`` too), or None if there
    is no such type; ValueError for a name without its package."""
    from rosx.msg.codec import rostime  # noqa: PLC0415 - on first use
    from rosx.msg.codec.classes import get_message_class as message_class  # noqa: PLC0415 - message classes load on first use
    from rosx.msg.store import UnknownTypeError  # noqa: PLC0415 - on first use

    if message_type in ("time", "duration"):
        return rostime.Time if message_type == "time" else rostime.Duration
    try:
        found: type[Message] = message_class(_message_name(message_type))
    except UnknownTypeError:
        return None
    return found


def get_service_class(service_type: str, reload_on_error: bool = False) -> Any:
    """The class of service ``service_type``, or None if there is no such type."""
    from rosx.msg.codec.classes import get_service_class as service_class  # noqa: PLC0415 - message classes load on first use
    from rosx.msg.store import UnknownTypeError  # noqa: PLC0415 - on first use

    if "/" not in service_type:
        raise ValueError(f"message type is missing package name: {service_type}")
    try:
        found: type[ServiceDefinition] = service_class(service_type)
    except UnknownTypeError:
        return None
    return found


def strify_message(
    val: object,
    indent: str = "",
    time_offset: Any = None,
    current_time: Any = None,
    field_filter: Callable[[object], Any] | None = None,
    fixed_numeric_width: int | None = None,
) -> str:
    """``val`` as YAML-like text, as ``rostopic echo`` prints it (``str(msg)``)."""
    from rosx.msg.text.echo import format_message  # noqa: PLC0415 - only for printing

    if field_filter is not None:
        raise NotImplementedError("rosx's strify_message takes no field_filter")
    return format_message(
        val, indent=indent, fixed_numeric_width=fixed_numeric_width, time_offset=time_offset
    )


# -- roslib.names -------------------------------------------------------------------------


def resource_name(res_pkg_name: str, name: str, my_pkg: str | None = None) -> str:
    """``res_pkg_name/name``, or ``name`` alone when it is ``my_pkg``'s."""
    return name if res_pkg_name == my_pkg else f"{res_pkg_name}{PRN_SEPARATOR}{name}"


def resource_name_base(name: str) -> str:
    """``Twist`` of ``geometry_msgs/Twist``."""
    return name[name.rfind(PRN_SEPARATOR) + 1 :]


def resource_name_package(name: str) -> str | None:
    """``geometry_msgs`` of ``geometry_msgs/Twist``; None without a package."""
    return name[: name.find(PRN_SEPARATOR)] if PRN_SEPARATOR in name else None


def is_legal_resource_name(name: str | None) -> bool:
    """A letter, then letters, digits, ``_`` and single ``/``."""
    if name is None:
        return False
    match = RESOURCE_NAME_LEGAL_CHARS_P.match(name)
    return match is not None and match.group(0) == name and "//" not in name


def is_legal_resource_base_name(name: str | None) -> bool:
    """A letter, then letters, digits and ``_``."""
    if name is None:
        return False
    match = BASE_RESOURCE_NAME_LEGAL_CHARS_P.match(name)
    return match is not None and match.group(0) == name


__all__ = [
    "BASE_RESOURCE_NAME_LEGAL_CHARS_P",
    "PRN_SEPARATOR",
    "RESOURCE_NAME_LEGAL_CHARS_P",
    "TYPE_SEPARATOR",
    "InvalidROSPkgException",
    "MultipleNodesException",
    "ROSPkgException",
    "find_node",
    "find_resource",
    "get_message_class",
    "get_pkg_dir",
    "get_service_class",
    "is_interactive",
    "is_legal_resource_base_name",
    "is_legal_resource_name",
    "load_manifest",
    "package_resource_name",
    "resource_name",
    "resource_name_base",
    "resource_name_package",
    "set_interactive",
    "strify_message",
]
