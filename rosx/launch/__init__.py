"""roslaunch's launch files as a plan: parse, resolve, print; and, in `rosx.launch.run`, run.

The plan is pure: no module of it starts a process, opens a socket, runs a thread, waits in
``select`` or handles a signal (two import contracts in pyproject.toml hold it, and
``tests/launch/test_plan_is_pure.py`` that they name every module of it). ``rosx roslaunch``
builds a `model.LaunchPlan` with `load_launch`, then `rosx.launch.run.runner.LaunchRun` runs it;
the printing options are functions of a plan.

Modules:

* `model`: the plan's dataclasses (`LaunchPlan`, `Node`, `Test`, `Param`, `Machine`…).
* `errors`: `LaunchError` (file, line, tag, message; one-line ``str()``).
* `loader`: `load_launch` (XML → plan), `resolve_launch_arguments` (``PKG FILE`` / paths,
  ``name:=value``), `roscore_params`; built on `xmldoc` (XML with line numbers), `context`
  (the scope rules), `substitution` (substitution args, ``$(eval)`` with `rosx.expression`) and
  `values` (``<param>`` typing, ``textfile``/``binfile``/``command``, rosparam YAML).
* `printing`: `summary_text` (the SUMMARY block), `nodes_text` (``--nodes``),
  `node_args_text` (``--args NODE``), `files_text` (``--files``), `dump_params_text`
  (``--dump-params``), `find_node_text` (``--find-node NODE``), `ros_args_text` (``--ros-args``).
* `process`: `node_command_line` and `node_environment`: how a `Node` is started (used by
  ``--args`` and by the runner alike).

Typical use::

    index = PackageIndex.from_environ(os.environ)
    files, cli_args = resolve_launch_arguments(argv, index)
    plan = load_launch(files, cli_args, os.environ, index, argv=argv, run=run_command)
    print(summary_text(plan), end="")

The printing options load as roslaunch does for each: ``with_core=False`` for ``--dump-params``
(roscore's part is not read), ``args_only=True`` for ``--ros-args``, ``core_params={}`` for all
(they do not show roscore's parameters).

``<param command="…">`` runs its command while the files are read, as roslaunch does: the
caller passes the runner (`rosx.launch.run.command.run_command`) as ``load_launch(run=…)``;
without one, such a parameter is refused.

The plan imports `rosx.names`, `rosx.msg` (rosparam's YAML rules), `rosx.packages` (the package
index, for ``$(find)``), `rosx.workspace` (how ``rosrun`` finds executables), `rosx.expression`,
`rosx.master.defaults` and, for roscore's parameters, `rosx.core.params`' constants. The runner
adds the core, the master client, the client's script runner and the transport.
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
