"""The plan roslaunch builds from launch files: parameters, nodes, tests, files, master.

Everything here is plain data, filled in by `rosx.launch.loader` and read by whoever prints or
runs the plan. It mirrors the parts of ROS 1's ``roslaunch.config.ROSLaunchConfig`` that a user
can observe: the parameter set, in the order its keys were first set (last setting wins), the
``clear_params`` namespaces, ``<rosparam command="delete|dump">`` steps, the nodes in launch
order, the tests (parsed, not run), the files read, and the master settings.

Names are ROS 1's resolved names: a parameter's `Param.name` is global (``/ns/node/param``), a
node's `Node.namespace` is global and ends with ``/`` and `Node.resolved_name` joins the two.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Literal

from rosx.master.defaults import DEFAULT_MASTER_URI

#: A parameter's value as the Parameter Server holds it: str, int, float, bool, bytes (from
#: ``binfile``), lists and string-keyed dictionaries of those.
ParamValue = Any

#: How roslaunch asks the master to be provided (``roslaunch.core.Master.auto``).
MasterAuto = Literal["no", "start", "restart"]


#: The `Source` file of what roscore's part of a launch adds (its parameters).
CORE_SOURCE = "roscore.xml"


@dataclass(frozen=True)
class Source:
    """Where a tag is: its launch file (absolute path) and 1-based line (0 if unknown)."""

    file: str
    line: int = 0

    def __str__(self) -> str:
        return f"{self.file}:{self.line}" if self.line else self.file


@dataclass(frozen=True)
class Param:
    """One parameter to set before the nodes start.

    Attributes:
        name: The global name, ``/ns/name`` or ``/ns/node/private``.
        value: The typed value, as ``<param type=…>`` or rosparam's YAML rules give it.
        source: The ``<param>``/``<rosparam>``/``<node>`` tag that set it last.
    """

    name: str
    value: ParamValue
    source: Source


@dataclass(frozen=True)
class RosparamCommand:
    """A ``<rosparam command="delete">`` or ``command="dump"``, run before parameters are set.

    Attributes:
        command: ``delete`` or ``dump``.
        param: The global parameter name it acts on (``/`` for the root).
        file: For ``dump``, the file written; "" for ``delete``.
        source: The tag.
    """

    command: Literal["delete", "dump"]
    param: str
    file: str
    source: Source


@dataclass(frozen=True)
class Machine:
    """A ``<machine>``: only the local machine can run nodes in rosx.

    Attributes:
        name: The machine's name in the launch files.
        address: Its host name or address.
        env_loader: The ``env-loader`` script, or None.
        ssh_port: The SSH port (roslaunch's default is 22).
        user: The ``user`` attribute, or None.
        password: The ``password`` attribute, or None.
        timeout: Seconds to wait for the remote launcher (roslaunch's default is 10.0).
        default: ``true``, ``false`` or ``never``.
        source: The tag.
    """

    name: str
    address: str
    env_loader: str | None = None
    ssh_port: int = 22
    user: str | None = None
    password: str | None = None
    timeout: float = 10.0
    default: str = "false"
    source: Source = Source("")


@dataclass(frozen=True)
class Node:
    """A ``<node>`` (or the node of a ``<test>``) to run, in launch order.

    Attributes:
        package: The ``pkg`` attribute.
        type: The executable's name in the package.
        name: The node's base name (``<test>`` may have none: "").
        namespace: The global namespace, ending with ``/``.
        args: The ``args`` attribute after substitution ("" when absent).
        remappings: ``(from, to)`` pairs, canonical, in roslaunch's order (the innermost
            ``<remap>`` of a ``from`` wins and moves to the end).
        env: ``(name, value)`` pairs from enclosing ``<env>`` tags, outer first.
        respawn: Restart the process when it exits.
        respawn_delay: Seconds to wait before a restart.
        required: The whole launch ends when this node exits.
        output: ``log``, ``screen`` or None (roslaunch's default: log).
        cwd: ``ROS_HOME``, ``node`` or None.
        launch_prefix: A command line put in front of the node's, or None.
        machine: The ``machine`` attribute, or None for the local machine.
        clear_params: Whether the node's private namespace is cleared first.
        source: The tag.
    """

    package: str
    type: str
    name: str
    namespace: str = "/"
    args: str = ""
    remappings: tuple[tuple[str, str], ...] = ()
    env: tuple[tuple[str, str], ...] = ()
    respawn: bool = False
    respawn_delay: float = 0.0
    required: bool = False
    output: str | None = None
    cwd: str | None = None
    launch_prefix: str | None = None
    machine: str | None = None
    clear_params: bool = False
    source: Source = Source("")

    @property
    def resolved_name(self) -> str:
        """``namespace + name``: ``/turtlesim1/sim``."""
        return self.namespace + self.name


@dataclass(frozen=True)
class Test(Node):
    """A ``<test>``: parsed and listed as roslaunch lists it, never run by roslaunch.

    Attributes:
        test_name: The ``test-name`` attribute.
        time_limit: Seconds before rostest gives up (default 60.0).
        retry: How many times rostest retries (default 0).
    """

    test_name: str = ""
    time_limit: float = 60.0
    retry: int = 0


@dataclass(frozen=True)
class MasterSettings:
    """How the master is reached and whether roslaunch starts one.

    Attributes:
        uri: ``ROS_MASTER_URI`` (or the ``-p PORT`` override).
        auto: ``no`` (use a running master), ``start`` (start one when none runs: ``roslaunch``'s
            default) or ``restart``.
    """

    uri: str = DEFAULT_MASTER_URI + "/"
    auto: MasterAuto = "start"


@dataclass
class LaunchPlan:
    """Everything a set of launch files asks for, in the order roslaunch does it.

    Attributes:
        params: Global name -> `Param`; insertion order is the order of first setting.
        clear_params: Namespaces (global, ending with ``/``) cleared before parameters are set.
        rosparam_commands: ``<rosparam command="delete|dump">`` steps, in file order.
        nodes: The nodes to run, in launch order.
        tests: The ``<test>`` tags, in file order.
        machines: Name -> `Machine` declared by ``<machine>``.
        files: Every launch file read (top-level and included), in reading order, absolute.
        master: How the master is reached.
        warnings: Messages roslaunch prints as warnings while loading (unknown attributes…).
        arg_docs: The args declared at the top level of the last file without a fixed
            ``value``: name -> (doc, default), for ``--ros-args``.
    """

    params: dict[str, Param] = field(default_factory=dict)
    clear_params: list[str] = field(default_factory=list)
    rosparam_commands: list[RosparamCommand] = field(default_factory=list)
    nodes: list[Node] = field(default_factory=list)
    tests: list[Test] = field(default_factory=list)
    machines: dict[str, Machine] = field(default_factory=dict)
    files: list[str] = field(default_factory=list)
    master: MasterSettings = field(default_factory=MasterSettings)
    warnings: list[str] = field(default_factory=list)
    arg_docs: dict[str, tuple[str | None, str | None]] = field(default_factory=dict)

    def param_values(self) -> dict[str, ParamValue]:
        """Global name -> value, as ``--dump-params`` and the master receive them."""
        return {name: p.value for name, p in self.params.items()}


__all__ = [
    "CORE_SOURCE",
    "LaunchPlan",
    "Machine",
    "MasterAuto",
    "MasterSettings",
    "Node",
    "Param",
    "ParamValue",
    "RosparamCommand",
    "Source",
    "Test",
]
