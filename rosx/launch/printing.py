"""The texts of roslaunch's printing options and its SUMMARY block, from a `LaunchPlan`.

Each function returns the whole text roslaunch prints on stdout, newline-terminated, or raises
`LaunchError` with what roslaunch prints on stderr (``status`` is roslaunch's exit status for
it). The plan is loaded as roslaunch loads it for that option: with roscore's part for all but
``--dump-params``, ``args_only`` for ``--ros-args``.

Two outputs of roslaunch vary from run to run and rosx fixes them: ``--files`` lists a Python
set (rosx lists the files in reading order), and ``--dump-params`` of a ``binfile`` parameter
fails in roslaunch (rosx writes it as YAML ``!!binary``).
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.launch.errors import LaunchError
from rosx.launch.process import node_command_line, node_environment

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

    from rosx.launch.model import LaunchPlan, Node
    from rosx.launch.process import Provided
    from rosx.packages.index import PackageIndex

_SUMMARY_WIDTH = 20


def summary_text(plan: LaunchPlan) -> str:
    """The SUMMARY block roslaunch prints before starting: PARAMETERS, then NODES by namespace.

    (roslaunch prints a MACHINES section too when remote machines are used; rosx runs local
    nodes only.)
    """
    text = "\nSUMMARY\n========"
    if plan.clear_params:
        text += "\n\nCLEAR PARAMETERS\n" + "\n".join(sorted(f" * {p}" for p in plan.clear_params))
    if plan.params:
        lines = sorted(f" * {name}: {summary_value(p.value)}" for name, p in plan.params.items())
        text += "\n\nPARAMETERS\n" + "\n".join(lines)
    text += "\n\nNODES\n"
    by_namespace: dict[str, list[Node]] = {}
    for node in plan.nodes:
        by_namespace.setdefault(node.namespace, []).append(node)
    for namespace in sorted(by_namespace):
        labels = sorted(f"    {_label(node)}" for node in by_namespace[namespace])
        text += f"  {namespace}\n" + "\n".join(labels) + "\n"
    return text + "\n"


def summary_value(value: Any) -> str:
    """A parameter value as the summary shows it: ``str()``, at most 20 characters, printable."""
    text = value.decode("latin-1") if isinstance(value, bytes) else str(value)
    if len(text) > _SUMMARY_WIDTH:
        text = text[: _SUMMARY_WIDTH - 3] + "..."
    for index, char in enumerate(text):
        if not 32 <= ord(char) <= 126:
            text = text.rstrip()
            if index >= len(text):
                break
            return "<...>"
    return text


def _label(node: Node) -> str:
    if node.name:
        return f"{node.name} ({node.package}/{node.type})"
    return f"{node.package}/{node.type}"


def _names(plan: LaunchPlan) -> list[str]:
    return [n.resolved_name for n in [*plan.nodes, *plan.tests] if n.name]


def nodes_text(plan: LaunchPlan) -> str:
    """``--nodes``: the resolved names of the nodes, then of the tests, one a line."""
    return "\n".join(_names(plan)) + "\n"


def _wanted(name: str, environ: Mapping[str, str]) -> str:
    from rosx.names.script import ros_namespace, script_resolve_name  # noqa: PLC0415 - name rules load only when used

    try:
        namespace = ros_namespace(environ)
    except ValueError:
        namespace = "/"
    return script_resolve_name("roslaunch", name, namespace)


def _only_node(plan: LaunchPlan, name: str, files: Sequence[str]) -> Node:
    found = [n for n in [*plan.nodes, *plan.tests] if n.name and n.resolved_name == name]
    if len(found) > 1:
        raise LaunchError(
            "",
            0,
            "",
            f"ERROR: multiple nodes named [{name}] in [{', '.join(files)}].\n"
            "Please fix the launch files as duplicate names are not allowed.",
        )
    if not found:
        listing = "\n".join(f" * {n}" for n in _names(plan))
        raise LaunchError(
            "",
            0,
            "",
            f"ERROR: Cannot find node named [{name}] in [{', '.join(files)}].\n"
            f"Node names are:\n{listing}",
        )
    return found[0]


def node_args_text(
    plan: LaunchPlan,
    node_name: str,
    files: Sequence[str],
    environ: Mapping[str, str],
    package_index: PackageIndex,
    provided: Provided | None = None,
) -> str:
    """``--args NODE``: the environment assignments and command line that start ``NODE``.

    ``files`` are the launch files as given (for roslaunch's error texts). Variables are shown
    as ``NAME="value"`` when the node's environment differs from ``environ`` there.
    """
    node = _only_node(plan, _wanted(node_name, environ), files)
    master_uri = environ.get("ROS_MASTER_URI") or plan.master.uri
    full = node_environment(node, environ, master_uri)
    changed = [f'{k}="{v}"' for k, v in full.items() if environ.get(k) != v]
    return " ".join([*changed, *node_command_line(node, package_index, provided)]) + "\n"


def find_node_text(
    plan: LaunchPlan, node_name: str, files: Sequence[str], environ: Mapping[str, str]
) -> str:
    """``--find-node NODE``: the launch file that declares ``NODE``, as it was named.

    A node that is not found is a `LaunchError` with status 0, as roslaunch exits.
    """
    name = _wanted(node_name, environ)
    found = [n for n in [*plan.nodes, *plan.tests] if n.name and n.resolved_name == name]
    if len(found) > 1:
        _only_node(plan, name, files)
    if not found:
        error = LaunchError(
            "",
            0,
            "",
            f"ERROR: cannot find node named [{name}]. Run \n\troslaunch --nodes <files>\n"
            "to see list of node names.",
        )
        error.status = 0
        raise error
    return found[0].source.file + "\n"


def files_text(plan: LaunchPlan) -> str:
    """``--files``: every launch file read, one absolute path a line, each once."""
    seen = dict.fromkeys(os.path.normpath(Path(f).absolute()) for f in plan.files)
    return "\n".join(seen) + "\n"


def dump_params_text(plan: LaunchPlan) -> str:
    """``--dump-params``: the parameters as YAML (``yaml.safe_dump`` of name -> value)."""
    from rosx.msg.text.yamldump import dump  # noqa: PLC0415 - the text forms load on first use

    return dump({name: p.value for name, p in plan.params.items()}) + "\n"


def ros_args_text(plan: LaunchPlan) -> str:
    """``--ros-args``: the args of the (last) file, required ones first, with docs/defaults."""
    if not plan.arg_docs:
        return "No arguments.\n"
    required = sorted((n, d) for n, (d, default) in plan.arg_docs.items() if not default)
    optional = sorted((n, d, v) for n, (d, v) in plan.arg_docs.items() if v)
    lines: list[str] = []
    if required:
        lines.append("Required Arguments:")
        lines += [f"  {name}: {doc or 'undocumented'}" for name, doc in required]
    if optional:
        lines.append("Optional Arguments:")
        lines += [
            f'  {name} (default "{default}"): {doc or "undocumented"}'
            for name, doc, default in optional
        ]
    return "\n".join(lines) + "\n"


__all__ = [
    "dump_params_text",
    "files_text",
    "find_node_text",
    "node_args_text",
    "nodes_text",
    "ros_args_text",
    "summary_text",
    "summary_value",
]
