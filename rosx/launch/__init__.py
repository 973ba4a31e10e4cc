"""roslaunch's launch files as a plan: parse, resolve, print (layer 7b, "launch").

Pure: nothing here opens a socket or starts a node. The runner (``rosx roslaunch``) builds a
`model.LaunchPlan` with `load_launch` and then runs it; the printing options are functions of a
plan.

Modules:

* `model`: the plan's dataclasses (`LaunchPlan`, `Node`, `Test`, `Param`, `Machine`…).
* `errors`: `LaunchError` (file, line, tag, message; one-line ``str()``).
* `loader`: `load_launch` (XML → plan), `resolve_launch_arguments` (``PKG FILE`` / paths,
  ``name:=value``), `roscore_params`; built on `xmldoc` (XML with line numbers), `context`
  (the scope rules), `substitution` and `evaluate` (substitution args, ``$(eval)``) and
  `values` (``<param>`` typing, ``textfile``/``binfile``/``command``, rosparam YAML).
* `printing`: `summary_text` (the SUMMARY block), `nodes_text` (``--nodes``),
  `node_args_text` (``--args NODE``), `files_text` (``--files``), `dump_params_text`
  (``--dump-params``), `find_node_text` (``--find-node NODE``), `ros_args_text` (``--ros-args``).
* `process`: `node_command_line` and `node_environment`: how a `Node` is started (used by
  ``--args`` and by the runner alike).

Typical use::

    index = PackageIndex.from_environ(os.environ)
    files, cli_args = resolve_launch_arguments(argv, index)
    plan = load_launch(files, cli_args, os.environ, index, argv=argv)
    print(summary_text(plan), end="")

The printing options load as roslaunch does for each: ``with_core=False`` for ``--dump-params``
(roscore's part is not read), ``args_only=True`` for ``--ros-args``, ``core_params={}`` for all
(they do not show roscore's parameters).

The one exception to "pure": ``<param command="…">`` runs its command while loading, as
roslaunch does (`values.run_command`, replaceable through ``load_launch(run=…)``).

This layer imports `rosx.names`, `rosx.msg` (rosparam's YAML rules), `rosx.packages` (the
package index, for ``$(find)``), `rosx.workspace` (how ``rosrun`` finds executables) and, for
roscore's parameters, `rosx.core.params`' constants; nothing above.
"""

from __future__ import annotations

import importlib

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx.launch.errors import LaunchError
    from rosx.launch.loader import load_launch, resolve_launch_arguments, roscore_params
    from rosx.launch.model import LaunchPlan, Machine, MasterSettings, Node, Param, Source, Test
    from rosx.launch.printing import (
        dump_params_text,
        files_text,
        find_node_text,
        node_args_text,
        nodes_text,
        ros_args_text,
        summary_text,
    )
    from rosx.launch.process import node_command_line, node_environment

_HOMES = {
    "LaunchError": "rosx.launch.errors",
    "LaunchPlan": "rosx.launch.model",
    "Machine": "rosx.launch.model",
    "MasterSettings": "rosx.launch.model",
    "Node": "rosx.launch.model",
    "Param": "rosx.launch.model",
    "Source": "rosx.launch.model",
    "Test": "rosx.launch.model",
    "dump_params_text": "rosx.launch.printing",
    "files_text": "rosx.launch.printing",
    "find_node_text": "rosx.launch.printing",
    "load_launch": "rosx.launch.loader",
    "node_args_text": "rosx.launch.printing",
    "node_command_line": "rosx.launch.process",
    "node_environment": "rosx.launch.process",
    "nodes_text": "rosx.launch.printing",
    "resolve_launch_arguments": "rosx.launch.loader",
    "roscore_params": "rosx.launch.loader",
    "ros_args_text": "rosx.launch.printing",
    "summary_text": "rosx.launch.printing",
}


def __getattr__(name: str) -> object:
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(home), name)


__all__ = [
    "LaunchError",
    "LaunchPlan",
    "Machine",
    "MasterSettings",
    "Node",
    "Param",
    "Source",
    "Test",
    "dump_params_text",
    "files_text",
    "find_node_text",
    "load_launch",
    "node_args_text",
    "node_command_line",
    "node_environment",
    "nodes_text",
    "resolve_launch_arguments",
    "ros_args_text",
    "roscore_params",
    "summary_text",
]
