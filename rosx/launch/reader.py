"""The reading of launch files into a `LaunchPlan`, as roslaunch's ``XmlLoader`` reads them.

Tags are read depth-first in document order; ``<include>``d files are read where they are
included; the last setting of a parameter wins. `Reader` holds what every tag needs (the
plan, substitution, attribute checks, errors) and dispatches each tag to its family's module
in `rosx.launch.tags`; unknown tags and attributes are warnings (`LaunchPlan.warnings`), as
roslaunch's "config errors". Every error is a `LaunchError` naming the file, the line and the
tag, raised through `AbortError` at the first one.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

from rosx.launch import substitution
from rosx.launch.context import LoadContext
from rosx.launch.errors import LaunchError, ResourceNotFoundError
from rosx.launch.model import CORE_SOURCE, LaunchPlan, Machine, Param, Source
from rosx.launch.tags import ATTRS
from rosx.launch.tags.machine import add_machine, machine_tag
from rosx.launch.tags.node import node_tag
from rosx.launch.tags.params import param_tag, rosparam_tag
from rosx.launch.tags.scope import add_remap, arg_tag, env_tag, group_tag, include_tag, remap_tag
from rosx.launch.values import ValueConversionError, convert_value
from rosx.launch.xmldoc import Element, XmlSyntaxError, parse_launch
from rosx.names.resolution import canonicalize, make_global_ns, ns_join

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator, Mapping

    from rosx.launch.values import CommandRunner


#: An attribute's number: ``float`` or ``int``, as the attribute takes it.
_Number = TypeVar("_Number", float, int)


class AbortError(Exception):
    """Unwinds the reading at the first error; carries the `LaunchError`."""

    def __init__(self, error: LaunchError) -> None:
        super().__init__(str(error))
        self.error = error


class Reader:
    """Reads launch files into one plan (roslaunch's ``XmlLoader`` + ``ROSLaunchConfig``)."""

    def __init__(
        self,
        plan: LaunchPlan,
        world: substitution.World,
        run: CommandRunner | None,
        args_only: bool,
    ) -> None:
        self.plan = plan
        self.world = world
        self.run = run
        self.args_only = args_only
        self.node_names: list[str] = []
        self.including: list[str] = []  # the chain of files being read, outermost first

    # -- errors ---------------------------------------------------------------------------

    def fail(self, context: LoadContext, element: Element | None, message: str) -> AbortError:
        """``list_children``: always empty; rosx starts no remote roslaunch children."""
        if element is None:
            return AbortError(LaunchError(context.filename, 0, "", message))
        return AbortError(LaunchError(context.filename, element.line, element.tag, message))

    def warn(self, context: LoadContext, element: Element, message: str) -> None:
        """Add a roslaunch-style warning about ``element`` to the plan; reading goes on."""
        self.plan.warnings.append(
            str(LaunchError(context.filename, element.line, element.tag, message))
        )

    def source(self, context: LoadContext, element: Element) -> Source:
        """Where ``element`` was read, for messages that point back at the file."""
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
            raise AbortError(
                ResourceNotFoundError(context.filename, element.line, element.tag, missing.name)
            ) from None
        except substitution.SubstitutionError as error:
            raise self.fail(context, element, str(error)) from None

    def optional(self, context: LoadContext, element: Element, name: str) -> str | None:
        """The attribute ``name`` with substitutions resolved, or None if it is absent."""
        text = element.attrs.get(name)
        return None if text is None else self.resolve(context, element, text)

    def required(self, context: LoadContext, element: Element, name: str) -> str:
        """The attribute ``name`` with substitutions resolved; roslaunch's "missing required
        attribute" error if it is absent."""
        text = element.attrs.get(name)
        if text is None:
            raise self.fail(
                context, element, f"<{element.tag}> tag is missing required attribute: '{name}'"
            )
        return self.resolve(context, element, text)

    def boolean(
        self, context: LoadContext, element: Element, value: str | None, label: str
    ) -> bool:
        """A ``true``/``false`` attribute (any case; absent is False); roslaunch's error
        otherwise."""
        if value is None:
            return False
        if value.lower() in ("true", "false"):
            return value.lower() == "true"
        if not value:
            raise self.fail(context, element, f"bool value for {label} must be non-empty")
        raise self.fail(context, element, f"invalid bool value for {label}: {value}")

    def check_attrs(self, context: LoadContext, element: Element) -> None:
        """Warn about attributes ``element``'s tag does not take, as roslaunch does; they are
        ignored."""
        allowed = ATTRS[element.tag]
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
        """Add what roscore's own launch provides: its parameters and the ``/rosout`` node."""
        source = Source(CORE_SOURCE)
        for name, value in params.items():
            self.plan.params[name] = Param(name, value, source)
        self.node_names.append("/rosout")

    def parse(self, context: LoadContext, element: Element | None, filename: str) -> Element:
        """``filename`` parsed into elements; an unreadable file or bad XML aborts with
        roslaunch's "Invalid roslaunch XML syntax" text."""
        try:
            data = Path(filename).read_bytes()
        except OSError as error:
            message = f"Invalid roslaunch XML syntax: [Errno {error.errno}] {error.strerror}: "
            raise self.fail(context, element, message + repr(filename)) from None
        try:
            return parse_launch(data)
        except XmlSyntaxError as error:
            raise AbortError(LaunchError(filename, error.line, "", str(error))) from None

    def load_file(self, filename: str, namespace: str, cli_args: dict[str, str]) -> None:
        """Read ``filename`` and everything it includes into the plan, in ``namespace``, with the
        command line's ``name:=value`` args."""
        context = LoadContext(namespace, filename)
        context.subst.args = cli_args
        self.including = [os.path.normpath(Path(filename).absolute())]
        launch = self.parse(context, None, filename)
        self.plan.files.append(filename)
        self.launch_tag(context, launch)
        if any(e.tag == "master" for e in descendants(launch)):
            self.plan.warnings.append(f"{filename}: ignoring defunct <master /> tag")
        self.recurse(context, launch.children, None)
        self.plan.arg_docs = dict(context.subst.arg_doc)

    def launch_tag(self, context: LoadContext, launch: Element) -> None:
        """Apply the ``<launch>`` tag itself: its ``deprecated`` message becomes a warning."""
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
                arg_tag(self, context, element)
            elif self.args_only or tag == "master":
                continue
            elif tag == "group":
                machine = group_tag(self, context, element, machine)
            elif tag in ("node", "test"):
                node_tag(self, context, element, machine)
            elif tag == "param":
                param_tag(self, context, element)
            elif tag == "remap":
                remap = remap_tag(self, context, element)
                if remap is not None:
                    add_remap(self, context, element, remap)
            elif tag == "machine":
                found = machine_tag(self, context, element)
                if found is not None:
                    if found.default == "true":
                        machine = found
                    add_machine(self, context, element, found)
            elif tag == "rosparam":
                rosparam_tag(self, context, element)
            elif tag == "include":
                machine = include_tag(self, context, element, machine)
            elif tag == "env":
                env_tag(self, context, element)
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

    def add_param(
        self,
        context: LoadContext,
        element: Element,
        name: str,
        value: Any,
        source: Source | None = None,
    ) -> None:
        """Add parameter ``name`` to the plan; a later value wins, and a name under or over an
        existing parameter is warned about as roslaunch warns."""
        key = canonicalize(name)
        for parent in _namespaces_of(key):
            if parent in self.plan.params:
                self.warn(
                    context,
                    element,
                    f"parameter [{key}] conflicts with parent parameter [{parent}]",
                )
        self.plan.params[key] = Param(key, value, source or self.source(context, element))

    def number(
        self,
        context: LoadContext,
        element: Element,
        convert: Callable[[str], _Number],
        attr: str,
        text: str,
    ) -> _Number:
        """``text`` converted by ``convert``; "must be a number" naming ``attr`` if it is not
        one."""
        try:
            return convert(text)
        except ValueError:
            raise self.fail(context, element, f"'{attr}' must be a number: [{text}]") from None

    def seconds(
        self, context: LoadContext, element: Element, value: str | None, label: str
    ) -> float:
        """A seconds attribute as a float (absent is 0.0); roslaunch's error if it is empty or
        not a number."""
        if value is None:
            return 0.0
        if not value:
            raise self.fail(context, element, f"bool value for {label} must be non-empty")
        try:
            return float(value)
        except ValueError:
            raise self.fail(context, element, f"invalid float value for {label}: {value}") from None


def _namespaces_of(name: str) -> list[str]:
    parts = [p for p in name.split("/") if p]
    return ["/"] + ["/" + "/".join(parts[:i]) for i in range(1, len(parts))]


def descendants(element: Element) -> Iterator[Element]:
    """Every element below ``element``, depth first, in document order."""
    for child in element.children:
        yield child
        yield from descendants(child)


__all__ = ["AbortError", "Reader", "descendants"]
