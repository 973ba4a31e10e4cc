"""The ROS environment a Noetic installation sets, for rosx's own prefix.

Sourcing ``/opt/ros/noetic/setup.bash`` exports ``ROS_DISTRO=noetic``, ``ROS_VERSION=1``,
``ROS_PYTHON_VERSION=3``, ``ROS_ROOT`` (``share/ros``), ``ROS_ETC_DIR`` (``etc/ros``),
``ROS_PACKAGE_PATH`` (``share``), ``ROSLISP_PACKAGE_DIRECTORIES`` (empty) and, when it is not set
yet, ``ROS_MASTER_URI=http://localhost:11311``. rosx ships its packages under one prefix laid out
as ``/opt/ros/noetic`` (`rosx.packages.crawl.PREFIX`); ``rosx shell-init`` and a workspace's
``setup.sh`` export the same variables for it, so ``printenv | grep ROS`` reads as on Noetic.

`base_exports` is that list, as shell code; `ROS_VARIABLES` its values for a process.
"""

from __future__ import annotations

import shlex

from rosx.master.defaults import DEFAULT_MASTER_URI
from rosx.packages.crawl import PREFIX

DISTRO = "noetic"

SHARE = PREFIX / "share"
ROS_ROOT = SHARE / "ros"
ROS_ETC_DIR = PREFIX / "etc" / "ros"

#: The variables a Noetic setup file sets unconditionally, in its order.
ROS_VARIABLES: dict[str, str] = {
    "ROS_DISTRO": DISTRO,
    "ROS_ETC_DIR": str(ROS_ETC_DIR),
    "ROS_PYTHON_VERSION": "3",
    "ROS_VERSION": "1",
    "ROS_ROOT": str(ROS_ROOT),
    "ROSLISP_PACKAGE_DIRECTORIES": "",
}

_DISTRO_MIX = (
    "ROS_DISTRO was set to '$ROS_DISTRO' before. Please make sure that the environment does not "
    "mix paths from different distributions."
)


def append_path(variable: str, value: str) -> str:
    """Shell code adding ``value`` at the end of the path list ``variable`` (once)."""
    quoted = shlex.quote(value)
    return (
        f'case ":${{{variable}:-}}:" in\n'
        f"  *:{quoted}:*) ;;\n"
        f'  *) {variable}="${{{variable}:+${variable}:}}"{quoted} ;;\n'
        "esac\n"
        f"export {variable}\n"
    )


def prepend_path(variable: str, value: str) -> str:
    """Shell code adding ``value`` at the start of the path list ``variable`` (once)."""
    quoted = shlex.quote(value)
    return (
        f'case ":${{{variable}:-}}:" in\n'
        f"  *:{quoted}:*) ;;\n"
        f'  *) {variable}={quoted}"${{{variable}:+:${variable}}}" ;;\n'
        "esac\n"
        f"export {variable}\n"
    )


def base_exports() -> str:
    """POSIX shell code exporting Noetic's environment for rosx's prefix.

    ``ROS_PACKAGE_PATH`` gets rosx's ``share`` at its end (a workspace already sourced stays in
    front of it), ``ROS_MASTER_URI`` its default only when unset, as Noetic's hooks do.
    """
    lines = [
        f'if [ -n "${{ROS_DISTRO:-}}" ] && [ "$ROS_DISTRO" != {DISTRO} ]; then\n'
        f'  echo "{_DISTRO_MIX}"\nfi\n'
    ]
    lines += [f"export {name}={shlex.quote(value)}\n" for name, value in ROS_VARIABLES.items()]
    lines.append(append_path("ROS_PACKAGE_PATH", str(SHARE)))
    lines.append(append_path("CMAKE_PREFIX_PATH", str(PREFIX)))
    lines.append(
        f'if [ -z "${{ROS_MASTER_URI:-}}" ]; then export ROS_MASTER_URI={DEFAULT_MASTER_URI}; fi\n'
    )
    return "".join(lines)


__all__ = [
    "DEFAULT_MASTER_URI",
    "DISTRO",
    "ROS_ETC_DIR",
    "ROS_ROOT",
    "ROS_VARIABLES",
    "SHARE",
    "append_path",
    "base_exports",
    "prepend_path",
]
