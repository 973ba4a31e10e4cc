"""The texts of roslaunch's printing options and its SUMMARY block, from a `LaunchPlan`.

(Being written: the signatures are final.) Each function returns the whole text printed on
stdout, newline-terminated, or raises `LaunchError` with what roslaunch prints on stderr.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.launch.model import LaunchPlan
    from rosx.workspace.index import PackageIndex


def summary_text(plan: LaunchPlan) -> str:
    """The SUMMARY block roslaunch prints before starting: PARAMETERS, then NODES by namespace."""
    raise NotImplementedError


def nodes_text(plan: LaunchPlan) -> str:
    """``--nodes``: resolved node names (tests last), one a line (load with resolve_anon=False)."""
    raise NotImplementedError


def node_args_text(
    plan: LaunchPlan, node_name: str, environ: Mapping[str, str], package_index: PackageIndex
) -> str:
    """``--args NODE``: the environment assignments and command line that start ``NODE``."""
    raise NotImplementedError


def find_node_text(plan: LaunchPlan, node_name: str) -> str:
    """``--find-node NODE``: the launch file that declares ``NODE``."""
    raise NotImplementedError


def files_text(plan: LaunchPlan) -> str:
    """``--files``: every launch file read, one absolute path a line."""
    raise NotImplementedError


def dump_params_text(plan: LaunchPlan) -> str:
    """``--dump-params``: the parameters as YAML (``yaml.safe_dump`` of name -> value)."""
    raise NotImplementedError


def ros_args_text(plan: LaunchPlan) -> str:
    """``--ros-args``: the ``<arg>`` names with their docs and defaults (required first)."""
    raise NotImplementedError
