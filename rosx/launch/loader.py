"""Launch files to a `LaunchPlan`, as roslaunch's ``XmlLoader`` reads them.

Tags are read depth-first in document order; ``<include>``d files are read where they are
included; the last setting of a parameter wins. The tags and attributes are roslaunch's
(wiki roslaunch/XML): ``launch``, ``node``, ``test``, ``param``, ``rosparam``, ``remap``,
``env``, ``arg``, ``include``, ``group``, ``machine`` and ``if``/``unless`` on each; unknown
tags and attributes are warnings (`LaunchPlan.warnings`), as roslaunch's "config errors".

Every error is a `LaunchError` naming the file, the line and the tag, with roslaunch's words
for what is wrong; nothing is returned for a file set with any error. One deliberate
difference: an ``<arg>``'s ``default`` is not resolved when the arg already has a value
(ros_comm#422: ``default="$(find pkg)"`` failed even when the arg was given).
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

from rosx.launch import substitution
from rosx.launch.context import ContextError, LoadContext, LocalParam
from rosx.launch.errors import LaunchError
from rosx.launch.model import (
    LaunchPlan,
    Machine,
    MasterSettings,
    Node,
    Param,
    RosparamCommand,
    Source,
    Test,
)
from rosx.launch.values import (
    ValueConversionError,
    binary_value,
    command_value,
    convert_value,
    flatten,
    load_yaml,
    run_command,
    text_value,
)
from rosx.launch.xmldoc import Element, XmlSyntaxError, parse_launch
from rosx.names.resolution import canonicalize, make_global_ns, ns_join
from rosx.names.validation import is_legal_name, is_private

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator, Mapping, Sequence

    from rosx.launch.values import CommandRunner
    from rosx.packages.index import PackageIndex

_NODE_ATTRS = [
    "pkg",
    "type",
    "machine",
    "name",
    "args",
    "output",
    "respawn",
    "respawn_delay",
    "cwd",
    "ns",
    "clear_params",
    "launch-prefix",
    "required",
]
_TEST_ATTRS = [*_NODE_ATTRS, "test-name", "time-limit", "retry"]
_ATTRS = {
    "param": ("name", "value", "type", "textfile", "binfile", "command"),
    "rosparam": ("command", "ns", "file", "param", "subst_value"),
    "arg": ("name", "value", "default", "doc"),
    "machine": (
        "name",
        "address",
        "env-loader",
        "ssh-port",
        "user",
        "password",
        "default",
        "timeout",
    ),
    "remap": ("from", "to"),
    "env": ("name", "value"),
    "include": ("file", "ns", "clear_params", "pass_all_args"),
    "group": ("ns", "clear_params"),
    "node": tuple(_NODE_ATTRS),
    "test": tuple(_TEST_ATTRS),
}
_MACHINE_DEFAULTS = {"true": (True, True), "false": (False, True), "never": (False, False)}
_TEST_TIME_LIMIT = 60.0
#: An attribute's number: ``float`` or ``int``, as the attribute takes it.
_Number = TypeVar("_Number", float, int)
#: roslaunch's guess for a machine without ``env-loader`` (only compared, never run).
_ENV_LOADER = "/opt/ros/noetic/env.sh"


class _AbortError(Exception):
    """Unwinds the reading at the first error; carries the `LaunchError`."""

    def __init__(self, error: LaunchError) -> None:
        super().__init__(str(error))
        self.error = error


def resolve_launch_arguments(
    argv: Sequence[str], package_index: PackageIndex
) -> tuple[list[str], dict[str, str]]:
    """Split roslaunch's positional arguments into launch files and ``name:=value`` args.

    ``PKG FILE`` names a file found anywhere in package ``PKG`` (as ``roslaunch`` and
    ``roslib.packages.find_resource`` look, hidden directories skipped); otherwise the first
    word is a path (or ``-``). The ``name:=value`` arguments may stand anywhere.

    Raises:
        LaunchError: roslaunch's ``[F] is neither a launch file in package [P] nor is [P] a
            launch file name``, ``[F] is not a launch file name`` or ``multiple files
            named [F] in package [P]…``.
    """
    words = [a for a in argv if ":=" not in a]
    cli_args = load_mappings(argv)
    if not words:
        return [], cli_args
    if len(words) >= 2:
        found = _find_in_package(words[0], words[1], package_index)
        if len(found) > 1:
            listing = "".join(f"\n- {path}" for path in found)
            raise LaunchError(
                "",
                0,
                "",
                f"multiple files named [{words[1]}] in package [{words[0]}]:{listing}\n"
                "Please specify full path instead",
            )
        if found:
            return [found[0], *words[2:]], cli_args
    if words[0] == "-" or Path(words[0]).is_file():
        return words, cli_args
    if len(words) >= 2:
        message = (
            f"[{words[1]}] is neither a launch file in package [{words[0]}] nor is "
            f"[{words[0]}] a launch file name"
        )
    else:
        message = f"[{words[0]}] is not a launch file name"
    raise LaunchError("", 0, "", message)


def load_mappings(argv: Sequence[str]) -> dict[str, str]:
    """The ``name:=value`` arguments of a command line (rosgraph's ``load_mappings``).

    ``_param:=value`` private-parameter arguments are left out; ``__ns:=`` and the like stay.
    """
    from rosx.names.remap_args import is_legal_remap  # noqa: PLC0415

    mappings: dict[str, str] = {}
    for arg in argv:
        if not is_legal_remap(arg) or arg.count(":=") != 1:
            continue
        source, target = (side.strip() for side in arg.split(":="))
        if source and target and not (len(source) > 1 and source[0] == "_" and source[1] != "_"):
            mappings[source] = target
    return mappings


def _find_in_package(package: str, name: str, package_index: PackageIndex) -> list[str]:
    from rosx.packages.index import PackageNotFoundError  # noqa: PLC0415

    try:
        root = package_index.find(package)
    except PackageNotFoundError:
        return []
    found: list[str] = []
    for directory, subdirs, files in os.walk(root, followlinks=True):
        subdirs[:] = sorted(d for d in subdirs if not d.startswith("."))
        if name in files:
            path = os.path.normpath(Path(directory, name).absolute())
            if path not in found:
                found.append(path)
    return found


def load_launch(
    targets: Sequence[str],
    cli_args: Mapping[str, str] | None = None,
    environ: Mapping[str, str] | None = None,
    package_index: PackageIndex | None = None,
    *,
    with_core: bool = True,
    core_params: Mapping[str, Any] | None = None,
    args_only: bool = False,
    anonymous: Callable[[str], str] | None = None,
    run: CommandRunner | None = None,
    argv: Sequence[str] = (),
) -> LaunchPlan:
    """Read launch files into one plan.

    Args:
        targets: The launch files, in order (as `resolve_launch_arguments` gives them).
        cli_args: ``name:=value`` from the command line, for ``<arg>``.
        environ: For ``$(env)``, ``$(optenv)``, ``ROS_NAMESPACE`` and ``ROS_MASTER_URI``
            (default: ``os.environ``).
        package_index: For ``$(find)`` (default: built from ``environ``).
        with_core: Read roscore's part first, as every roslaunch except ``--dump-params``
            does: its parameters (``core_params``), and ``/rosout``'s name taken.
        core_params: The parameters roscore sets from ``roscore.xml`` (name -> value); None
            for rosx's core's ``/rosversion`` and ``/rosdistro`` (`roscore_params`). The
            printing options, which do not show them, pass ``{}`` and skip importing the core.
        args_only: Read ``<arg>`` tags only (``--ros-args``).
        anonymous: Makes ``$(anon id)`` names (default: rosgraph's ``anonymous_name``).
        run: Runs ``<param command=…>`` commands (default: a subprocess).
        argv: The command line, searched for ``__ns:=`` (the namespace of everything).

    Raises:
        LaunchError: Anything wrong in any file; nothing of the plan is returned.
    """
    from rosx.names.anonymous import anonymous_name  # noqa: PLC0415
    from rosx.names.script import ros_namespace  # noqa: PLC0415

    environ = os.environ if environ is None else environ
    if package_index is None:
        from rosx.packages.index import PackageIndex  # noqa: PLC0415

        package_index = PackageIndex.from_environ(environ)
    world = substitution.World(environ, package_index, anonymous or anonymous_name)
    plan = LaunchPlan()
    plan.master = MasterSettings(environ.get("ROS_MASTER_URI") or plan.master.uri)
    reader = _Reader(plan, world, run or run_command, args_only)
    if with_core:
        reader.add_core(roscore_params() if core_params is None else core_params)
    try:
        namespace = ros_namespace(environ, argv)
    except ValueError as error:
        raise LaunchError("", 0, "", str(error)) from None
    for target in targets:
        try:
            reader.load_file(target, namespace, dict(cli_args or {}))
        except _AbortError as abort:
            raise abort.error from None
    return plan


def roscore_params() -> dict[str, Any]:
    """What roslaunch's ``roscore.xml`` sets: ``/rosversion`` and ``/rosdistro``, as rosx's core."""
    from rosx.core.params import ROSDISTRO, ROSVERSION  # noqa: PLC0415

    return {"/rosversion": ROSVERSION, "/rosdistro": ROSDISTRO}


class _Reader:
    """Reads launch files into one plan (roslaunch's ``XmlLoader`` + ``ROSLaunchConfig``)."""

    def __init__(
        self, plan: LaunchPlan, world: substitution.World, run: CommandRunner, args_only: bool
    ) -> None:
        self.plan = plan
        self.world = world
        self.run = run
        self.args_only = args_only
        self.node_names: list[str] = []
        self.including: list[str] = []  # the chain of files being read, outermost first

    # -- errors ---------------------------------------------------------------------------

    def fail(self, context: LoadContext, element: Element | None, message: str) -> _AbortError:
        if element is None:
            return _AbortError(LaunchError(context.filename, 0, "", message))
        return _AbortError(LaunchError(context.filename, element.line, element.tag, message))

    def warn(self, context: LoadContext, element: Element, message: str) -> None:
        self.plan.warnings.append(
            str(LaunchError(context.filename, element.line, element.tag, message))
        )

    def source(self, context: LoadContext, element: Element) -> Source:
        return Source(context.filename, element.line)

    # -- attributes -----------------------------------------------------------------------

    def resolve(self, context: LoadContext, element: Element, text: str) -> str:
        """``text`` with substitution args resolved in ``context``; errors name the tag."""
        if "$" not in text:
            return text
        context.subst.filename = context.filename
        try:
            return substitution.resolve(text, context.subst, self.world)
        except substitution.MissingArgError as missing:
            if element.tag == "arg":
                raise self.fail(context, element, f"arg '{missing.name}' is not defined") from None
            raise self.fail(
                context, element, f"requires the '{missing.name}' arg to be set"
            ) from None
        except substitution.MissingPackageError as missing:
            raise self.fail(context, element, f"Resource not found: {missing.name}") from None
        except substitution.SubstitutionError as error:
            raise self.fail(context, element, str(error)) from None

    def optional(self, context: LoadContext, element: Element, name: str) -> str | None:
        text = element.attrs.get(name)
        return None if text is None else self.resolve(context, element, text)

    def required(self, context: LoadContext, element: Element, name: str) -> str:
        text = element.attrs.get(name)
        if text is None:
            raise self.fail(
                context, element, f"<{element.tag}> tag is missing required attribute: '{name}'"
            )
        return self.resolve(context, element, text)

    def boolean(
        self, context: LoadContext, element: Element, value: str | None, label: str
    ) -> bool:
        if value is None:
            return False
        if value.lower() in ("true", "false"):
            return value.lower() == "true"
        if not value:
            raise self.fail(context, element, f"bool value for {label} must be non-empty")
        raise self.fail(context, element, f"invalid bool value for {label}: {value}")

    def check_attrs(self, context: LoadContext, element: Element) -> None:
        allowed = _ATTRS[element.tag]
        for name in element.attrs:
            if name not in allowed and name not in ("if", "unless"):
                self.warn(context, element, f"unknown <{element.tag}> attribute '{name}'")

    def enabled(self, context: LoadContext, element: Element) -> bool:
        """Whether the tag's ``if``/``unless`` let it be read."""
        if_value = self.optional(context, element, "if")
        unless_value = self.optional(context, element, "unless")
        if if_value is not None and unless_value is not None:
            raise self.fail(context, element, "cannot set both 'if' and 'unless' on the same tag")
        try:
            if if_value is not None:
                return bool(convert_value(if_value, "bool"))
            if unless_value is not None:
                return not convert_value(unless_value, "bool")
        except ValueConversionError as error:
            raise self.fail(context, element, str(error)) from None
        return True

    # -- files ----------------------------------------------------------------------------

    def add_core(self, params: Mapping[str, Any]) -> None:
        source = Source("roscore.xml")
        for name, value in params.items():
            self.plan.params[name] = Param(name, value, source)
        self.node_names.append("/rosout")

    def parse(self, context: LoadContext, element: Element | None, filename: str) -> Element:
        try:
            data = Path(filename).read_bytes()
        except OSError as error:
            message = f"Invalid roslaunch XML syntax: [Errno {error.errno}] {error.strerror}: "
            raise self.fail(context, element, message + repr(filename)) from None
        try:
            return parse_launch(data)
        except XmlSyntaxError as error:
            raise _AbortError(LaunchError(filename, error.line, "", str(error))) from None

    def load_file(self, filename: str, namespace: str, cli_args: dict[str, str]) -> None:
        context = LoadContext(namespace, filename)
        context.subst.args = cli_args
        self.including = [os.path.normpath(Path(filename).absolute())]
        launch = self.parse(context, None, filename)
        self.plan.files.append(filename)
        self.launch_tag(context, launch)
        if any(e.tag == "master" for e in _descendants(launch)):
            self.plan.warnings.append(f"{filename}: ignoring defunct <master /> tag")
        self.recurse(context, launch.children, None)
        self.plan.arg_docs = dict(context.subst.arg_doc)

    def launch_tag(self, context: LoadContext, launch: Element) -> None:
        deprecated = launch.attrs.get("deprecated")
        if deprecated:
            self.warn(context, launch, f"DEPRECATED: {deprecated}")

    # -- tags -----------------------------------------------------------------------------

    def recurse(
        self, context: LoadContext, elements: list[Element], machine: Machine | None
    ) -> Machine | None:
        """Read ``elements`` in ``context``; returns the default machine after them."""
        for element in elements:
            tag = element.tag
            if tag == "arg":
                self.arg_tag(context, element)
            elif self.args_only or tag == "master":
                continue
            elif tag == "group":
                if self.enabled(context, element):
                    self.check_attrs(context, element)
                    child, _ = self.ns_and_clear_params(context, element)
                    child.params = list(child.params)
                    machine = self.recurse(child, element.children, machine)
            elif tag in ("node", "test"):
                self.node_tag(context, element, machine)
            elif tag == "param":
                self.param_tag(context, element)
            elif tag == "remap":
                remap = self.remap_tag(context, element)
                if remap is not None:
                    self.add_remap(context, element, remap)
            elif tag == "machine":
                found = self.machine_tag(context, element)
                if found is not None:
                    if found.default == "true":
                        machine = found
                    self.add_machine(context, element, found)
            elif tag == "rosparam":
                self.rosparam_tag(context, element)
            elif tag == "include":
                machine = self.include_tag(context, element, machine)
            elif tag == "env":
                self.env_tag(context, element)
            else:
                self.warn(context, element, f"unrecognized tag {tag}")
        return machine

    def ns_and_clear_params(
        self,
        context: LoadContext,
        element: Element,
        *,
        node_name: str | None = None,
        include_file: str | None = None,
    ) -> tuple[LoadContext, bool]:
        """The scope of a tag with ``ns`` and ``clear_params``, and whether it clears."""
        ns: str | None = None
        if "ns" in element.attrs:
            ns = self.resolve(context, element, element.attrs["ns"])
            if not ns:
                raise self.fail(
                    context, element, f"<{element.tag}> tag has an empty 'ns' attribute"
                )
        try:
            if include_file is not None:
                child = context.include_child(ns, include_file)
            else:
                child = context.child(ns)
        except ValueError as error:
            raise self.fail(context, element, str(error)) from None
        clear_text = self.resolve(context, element, element.attrs.get("clear_params", ""))
        clear = bool(clear_text) and self.boolean(context, element, clear_text, "clear_params")
        if clear:
            if element.tag in ("node", "test"):
                if not node_name:
                    raise self.fail(
                        context,
                        element,
                        f"<{element.tag}> tag must have a 'name' attribute to use "
                        "'clear_params' attribute",
                    )
                self.plan.clear_params.append(make_global_ns(ns_join(child.ns, node_name)))
            else:
                if not ns:
                    raise self.fail(
                        context,
                        element,
                        "'ns' attribute must be set in order to use 'clear_params'",
                    )
                self.plan.clear_params.append(child.ns)
        return child, clear

    def arg_tag(self, context: LoadContext, element: Element) -> None:
        if not self.enabled(context, element):
            return
        self.check_attrs(context, element)
        name = self.required(context, element, "name")
        value = self.optional(context, element, "value")
        default_text = element.attrs.get("default")
        scope = context.subst if context.include_subst is None else context.include_subst
        default = default_text
        if default_text is not None and not (name in scope.args and "$" in default_text):
            default = self.resolve(context, element, default_text)
        doc = self.optional(context, element, "doc")
        if value is not None and default is not None:
            raise self.fail(
                context, element, "<arg> tag must have one and only one of value/default."
            )
        try:
            context.add_arg(name, value=value, default=default, doc=doc)
        except ContextError as error:
            raise self.fail(context, element, str(error)) from None

    def param_tag(self, context: LoadContext, element: Element, *, local: bool = False) -> None:
        if not self.enabled(context, element):
            return
        self.check_attrs(context, element)
        type_ = (element.attrs.get("type") or "auto").lower().strip()
        given = {
            k: self.optional(context, element, k)
            for k in ("value", "textfile", "binfile", "command")
        }
        if sum(v is not None for v in given.values()) != 1:
            raise self.fail(
                context,
                element,
                "<param> tag must have one and only one of value/textfile/binfile.",
            )
        if "name" not in element.attrs:
            raise self.fail(context, element, "<param> tag is missing required attribute: 'name'.")
        name = self.resolve(context, element, element.attrs["name"].strip())
        try:
            value = self.param_value(name, type_, given)
        except ValueConversionError as error:
            raise self.fail(context, element, f"Invalid <param> tag: {error}.") from None
        if is_private(name) or local:
            context.add_param(LocalParam(canonicalize(name), value, self.source(context, element)))
        else:
            self.add_param(context, element, ns_join(context.ns, name), value)

    def param_value(self, name: str, type_: str, given: dict[str, str | None]) -> Any:
        value, textfile, binfile, command = given.values()
        if value is not None:
            return convert_value(value.strip(), type_)
        if textfile is not None:
            return text_value(textfile, type_)
        if binfile is not None:
            return binary_value(binfile)
        assert command is not None
        return command_value(name, command, type_, self.run)

    def add_param(
        self,
        context: LoadContext,
        element: Element,
        name: str,
        value: Any,
        source: Source | None = None,
    ) -> None:
        key = canonicalize(name)
        for parent in _namespaces_of(key):
            if parent in self.plan.params:
                self.warn(
                    context,
                    element,
                    f"parameter [{key}] conflicts with parent parameter [{parent}]",
                )
        self.plan.params[key] = Param(key, value, source or self.source(context, element))

    def rosparam_tag(self, context: LoadContext, element: Element) -> None:
        if not self.enabled(context, element):
            return
        self.check_attrs(context, element)
        command, ns, file, param, subst = (
            self.optional(context, element, a) for a in _ATTRS["rosparam"]
        )
        substitute = self.boolean(context, element, subst, "subst_value")
        param = ns_join(ns or "", param or "")
        command = command or "load"
        if command not in ("load", "dump", "delete"):
            raise self.fail(context, element, "command must be 'load', 'dump', or 'delete'")
        if file is not None:
            if command == "load" and not Path(file).is_file():
                raise self.fail(context, element, f"file does not exist [{file}]")
            if command == "delete":
                raise self.fail(
                    context, element, "'file' attribute is invalid with 'delete' command."
                )
        full = ns_join(context.ns, param) if param else context.ns
        source = self.source(context, element)
        if command != "load":
            step = RosparamCommand(command, full, file or "", source)  # type: ignore[arg-type]
            self.plan.rosparam_commands.append(step)
            return
        text = element.text
        if file:
            try:
                text = Path(file).read_text(encoding="utf-8")
            except (OSError, UnicodeDecodeError) as error:
                raise self.fail(context, element, f"cannot read [{file}]: {error}") from None
        if substitute:
            text = self.resolve(context, element, text)
        try:
            data = load_yaml(text)
        except ValueConversionError as error:
            where = f"file {file} contains invalid YAML" if file else "invalid YAML"
            raise self.fail(context, element, f"{where}: {error}") from None
        if data is None:
            data = {}
        if not param and not isinstance(data, dict):
            raise self.fail(
                context, element, "'param' attribute must be set for non-dictionary values"
            )
        if full == "/" and not isinstance(data, dict):
            raise self.fail(
                context, element, "Cannot load non-dictionary types into global namespace '/'"
            )
        try:
            for name, value in flatten(full, data):
                self.add_param(context, element, name, value)
        except ValueConversionError as error:
            raise self.fail(context, element, str(error)) from None

    def remap_tag(self, context: LoadContext, element: Element) -> tuple[str, str] | None:
        if not self.enabled(context, element):
            return None
        self.check_attrs(context, element)
        if "from" not in element.attrs or "to" not in element.attrs:
            raise self.fail(context, element, "<remap> tag is missing required from/to attributes")
        return (
            self.resolve(context, element, element.attrs["from"]),
            self.resolve(context, element, element.attrs["to"]),
        )

    def add_remap(self, context: LoadContext, element: Element, remap: tuple[str, str]) -> None:
        try:
            context.add_remap(*remap)
        except ContextError as error:
            raise self.fail(context, element, f"Invalid <remap> tag: {error}.") from None

    def env_tag(self, context: LoadContext, element: Element) -> None:
        if not self.enabled(context, element):
            return
        self.check_attrs(context, element)
        if "name" not in element.attrs or "value" not in element.attrs:
            raise self.fail(context, element, "<env> tag is missing required name/value attributes")
        name = self.resolve(context, element, element.attrs["name"])
        value = self.resolve(context, element, element.attrs["value"])
        if not name:
            raise self.fail(
                context, element, "Invalid <env> tag: 'name' attribute must be non-empty."
            )
        context.env.append((name, value))

    def machine_tag(self, context: LoadContext, element: Element) -> Machine | None:
        if not self.enabled(context, element):
            return None
        context = context.child(None)
        if any(
            self.optional(context, element, a)
            for a in ("ros-root", "ros-package-path", "ros-ip", "ros-hostname")
        ):
            raise self.fail(
                context,
                element,
                "<machine>: ros-* attributes are not supported "
                "since ROS Fuerte. Please use env-loader instead",
            )
        self.check_attrs(context, element)
        name = self.required(context, element, "name")
        address = self.required(context, element, "address")
        env_loader, port, user, password, default, timeout = (
            self.optional(context, element, a) for a in _ATTRS["machine"][2:]
        )
        try:
            ssh_port = int(port or "22")
        except ValueError as error:
            raise self.fail(context, element, str(error)) from None
        default = (default or "false").lower()
        if default not in _MACHINE_DEFAULTS:
            raise self.fail(context, element, f"Invalid value for 'attribute': {default}")
        for child in element.children:
            if child.tag == "env":
                raise self.fail(
                    context,
                    child,
                    "<machine>: <env> tag is not supported since ROS "
                    "Fuerte. Please use env-loader instead",
                )
            self.warn(context, child, f"unrecognized '{child.tag}' tag in <machine> tag")
        seconds = 10.0
        if timeout == "":
            raise self.fail(context, element, "'timeout' cannot be empty")
        if timeout is not None:
            try:
                seconds = float(timeout)
            except ValueError:
                raise self.fail(context, element, f"'timeout' be a number: [{timeout}]") from None
            if seconds <= 0.0:
                raise self.fail(context, element, f"'timeout' be a positive number: [{timeout}]")
        return Machine(
            name,
            address,
            env_loader or _ENV_LOADER,
            ssh_port,
            user or None,
            password,
            seconds,
            default,
            self.source(context, element),
        )

    def add_machine(self, context: LoadContext, element: Element, machine: Machine) -> None:
        known = self.plan.machines.get(machine.name)
        if known is None:
            self.plan.machines[machine.name] = machine
        elif _machine_key(known) != _machine_key(machine):
            raise self.fail(
                context,
                element,
                f"Machine [{machine.name}] already added and does not match duplicate entry",
            )

    def include_tag(
        self, context: LoadContext, element: Element, machine: Machine | None
    ) -> Machine | None:
        if not self.enabled(context, element):
            return machine
        self.check_attrs(context, element)
        filename = self.required(context, element, "file")
        pass_all = False
        if "pass_all_args" in element.attrs:
            text = self.resolve(context, element, element.attrs["pass_all_args"])
            pass_all = self.boolean(context, element, text, "pass_all_args")
        child, _ = self.ns_and_clear_params(context, element, include_file=filename)
        if pass_all:
            for name, value in context.subst.args.items():
                child.add_arg(name, value=value)
            child.pass_all_args = True
        child.filename = context.filename
        for inner in element.children:
            if inner.tag == "env":
                self.env_tag(child, inner)
            elif inner.tag == "arg":
                self.arg_tag(child, inner)
            else:
                self.warn(child, inner, f"unrecognized '{inner.tag}' tag in <include> tag")
        child.filename = filename
        try:
            child.start_include()
        except ContextError as error:
            raise self.fail(context, element, str(error)) from None
        launch = self.parse(context, element, filename)
        path = os.path.normpath(Path(filename).absolute())
        if path in self.including:
            chain = " -> ".join([*self.including, path])
            raise self.fail(context, element, f"the file includes itself: {chain}")
        self.plan.files.append(filename)
        self.launch_tag(child, launch)
        self.including.append(path)
        machine = self.recurse(child, launch.children, machine)
        self.including.pop()
        if not pass_all and child.unused_args():
            unused = ", ".join(child.unused_args())
            raise self.fail(context, element, f"unused args [{unused}] for include of [{filename}]")
        return machine

    def node_tag(self, context: LoadContext, element: Element, machine: Machine | None) -> None:
        if not self.enabled(context, element):
            return
        is_test = element.tag == "test"
        self.check_attrs(context, element)
        test_name, time_limit, retry = "", _TEST_TIME_LIMIT, 0
        if is_test:
            name = self.optional(context, element, "name") or ""
            test_name, time_limit, retry = self.test_attrs(context, element)
            name = name or test_name
        else:
            name = self.required(context, element, "name")
        if not is_legal_name(name):
            self.warn(
                context,
                element,
                f"WARN: illegal <node> name '{name}'. "
                "http://ros.org/wiki/Names This will likely cause "
                "problems with other ROS tools.",
            )
        child, cleared = self.ns_and_clear_params(context, element, node_name=name)
        try:
            private = child.child(name)
        except ValueError as error:
            raise self.fail(context, element, str(error)) from None
        private.params = []
        package = self.required(context, element, "pkg")
        type_ = self.required(context, element, "type")
        attrs = {
            a: self.optional(context, element, a)
            for a in (
                "machine",
                "args",
                "output",
                "respawn",
                "respawn_delay",
                "cwd",
                "launch-prefix",
                "required",
            )
        }
        machine_name = attrs["machine"] or (machine.name if machine else None)
        required = self.boolean(context, element, attrs["required"], "required")
        respawn = self.boolean(context, element, attrs["respawn"], "respawn")
        respawn_delay = self.seconds(context, element, attrs["respawn_delay"], "respawn_delay")
        remaps, env = self.node_children(context, element, private)
        output, cwd = attrs["output"], attrs["cwd"]
        if cwd == "ros_home":
            cwd = "ROS_HOME"
        problem = _node_problem(
            name,
            package,
            type_,
            "log" if is_test else output,
            cwd,
            respawn and not is_test,
            required and not is_test,
        )
        if problem:
            raise self.fail(context, element, f"Invalid <{element.tag}> tag: {problem}.")
        fields: dict[str, Any] = {
            "package": package,
            "type": type_,
            "name": name,
            "namespace": _node_namespace(child.ns),
            "args": attrs["args"] or "",
            "remappings": tuple(remaps.remap_args()),
            "env": tuple(env.env),
            "cwd": cwd,
            "launch_prefix": attrs["launch-prefix"] or None,
            "machine": machine_name or None,
            "source": self.source(context, element),
        }
        if is_test:
            test = Test(
                output="log",
                clear_params=cleared,
                test_name=test_name,
                time_limit=time_limit,
                retry=retry,
                **fields,
            )
            self.plan.tests.append(test)
            return
        node = Node(
            respawn=respawn,
            respawn_delay=respawn_delay,
            required=required,
            output=output,
            clear_params=cleared,
            **fields,
        )
        if name:
            resolved = ns_join(node.namespace, name)
            if resolved in self.node_names:
                raise self.fail(
                    context,
                    element,
                    f"roslaunch file contains multiple nodes named [{resolved}]. Please check all "
                    "<node> 'name' attributes to make sure they are unique. Also check that "
                    "$(anon id) use different ids.",
                )
            self.node_names.append(resolved)
        self.plan.nodes.append(node)

    def node_children(
        self, context: LoadContext, element: Element, private: LoadContext
    ) -> tuple[LoadContext, LoadContext]:
        """Read a node's tags; its private params go to the plan. Returns (remaps, env)."""
        remaps = context.child("")
        env = context.child("")
        for inner in element.children:
            if inner.tag == "remap":
                remap = self.remap_tag(context, inner)
                if remap is not None:
                    self.add_remap(remaps, inner, remap)
            elif inner.tag == "param":
                self.param_tag(private, inner, local=True)
            elif inner.tag == "rosparam":
                self.rosparam_tag(private, inner)
            elif inner.tag == "env":
                self.env_tag(env, inner)
            else:
                self.warn(
                    context,
                    inner,
                    f"WARN: unrecognized '{inner.tag}' child tag in the parent tag element",
                )
        for local in [*context.params, *private.params]:
            key = local.key[1:] if is_private(local.key) else local.key
            self.add_param(context, element, private.ns + key, local.value, local.source)
        return remaps, env

    def test_attrs(self, context: LoadContext, element: Element) -> tuple[str, float, int]:
        for attr in ("respawn", "respawn_delay", "output"):
            if attr in element.attrs:
                raise self.fail(context, element, f"<test> tags cannot have '{attr}' attribute")
        test_name = self.required(context, element, "test-name")
        limit_text = self.resolve(context, element, element.attrs.get("time-limit", ""))
        retry_text = self.resolve(context, element, element.attrs.get("retry", ""))
        time_limit, retry = _TEST_TIME_LIMIT, 0
        if limit_text:
            time_limit = self.number(context, element, float, "time-limit", limit_text)
            if time_limit <= 0.0:
                raise self.fail(context, element, "'time-limit' must be a positive number")
        if retry_text:
            retry = self.number(context, element, int, "retry", retry_text)
        return test_name, time_limit, retry

    def number(
        self,
        context: LoadContext,
        element: Element,
        convert: Callable[[str], _Number],
        attr: str,
        text: str,
    ) -> _Number:
        try:
            return convert(text)
        except ValueError:
            raise self.fail(context, element, f"'{attr}' must be a number: [{text}]") from None

    def seconds(
        self, context: LoadContext, element: Element, value: str | None, label: str
    ) -> float:
        if value is None:
            return 0.0
        if not value:
            raise self.fail(context, element, f"bool value for {label} must be non-empty")
        try:
            return float(value)
        except ValueError:
            raise self.fail(context, element, f"invalid float value for {label}: {value}") from None


def _node_problem(
    name: str,
    package: str,
    type_: str,
    output: str | None,
    cwd: str | None,
    respawn: bool,
    required: bool,
) -> str | None:
    if respawn and required:
        return "respawn and required cannot both be set to true"
    if "/" in name:
        return "node name cannot contain a namespace"
    if not package.strip():
        return "package must be non-empty"
    if not type_.strip():
        return "type must be non-empty"
    if output not in ("log", "screen", None):
        return "output must be one of 'log', 'screen'"
    if cwd not in ("ROS_HOME", "node", None):
        return "cwd must be one of 'ROS_HOME', 'node'"
    return None


def _node_namespace(ns: str) -> str:
    namespace = make_global_ns(ns or "/")
    while "//" in namespace:
        namespace = namespace.replace("//", "/")
    return namespace


def _namespaces_of(name: str) -> list[str]:
    parts = [p for p in name.split("/") if p]
    return ["/"] + ["/" + "/".join(parts[:i]) for i in range(1, len(parts))]


def _machine_key(machine: Machine) -> tuple[object, ...]:
    return (
        machine.address,
        machine.env_loader,
        machine.ssh_port,
        machine.user or "",
        machine.password or "",
        machine.timeout,
        machine.default != "never",
    )


def _descendants(element: Element) -> Iterator[Element]:
    for child in element.children:
        yield child
        yield from _descendants(child)


__all__ = ["load_launch", "load_mappings", "resolve_launch_arguments", "roscore_params"]
