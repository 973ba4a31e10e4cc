"""The scoping tags of a launch file: ``<arg>``, ``<group>``, ``<include>``, ``<remap>``, ``<env>``.

Each reads one tag into the `LoadContext` it opens or changes (args, namespace, remappings,
environment), as roslaunch's ``XmlLoader`` does; ``<include>`` reads the included file in
place, through the `Reader`. One deliberate difference from roslaunch: an ``<arg>``'s
``default`` is not resolved when the arg already has a value (ros_comm#422).
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

from rosx.launch.context import ContextError

if TYPE_CHECKING:
    from rosx.launch.context import LoadContext
    from rosx.launch.model import Machine
    from rosx.launch.reader import Reader
    from rosx.launch.xmldoc import Element


def arg_tag(reader: Reader, context: LoadContext, element: Element) -> None:
    """Read an ``<arg>`` tag: its value, default or the command line's, into the scope."""
    if not reader.enabled(context, element):
        return
    reader.check_attrs(context, element)
    name = reader.required(context, element, "name")
    value = reader.optional(context, element, "value")
    default_text = element.attrs.get("default")
    scope = context.subst if context.include_subst is None else context.include_subst
    default = default_text
    if default_text is not None and not (name in scope.args and "$" in default_text):
        default = reader.resolve(context, element, default_text)
    doc = reader.optional(context, element, "doc")
    if value is not None and default is not None:
        raise reader.fail(
            context, element, "<arg> tag must have one and only one of value/default."
        )
    try:
        context.add_arg(name, value=value, default=default, doc=doc)
    except ContextError as error:
        raise reader.fail(context, element, str(error)) from None


def group_tag(
    reader: Reader, context: LoadContext, element: Element, machine: Machine | None
) -> Machine | None:
    """Read a ``<group>``'s tags in its scope; returns the default machine after them."""
    if reader.enabled(context, element):
        reader.check_attrs(context, element)
        child, _ = reader.ns_and_clear_params(context, element)
        child.params = list(child.params)
        machine = reader.recurse(child, element.children, machine)
    return machine


def include_tag(
    reader: Reader, context: LoadContext, element: Element, machine: Machine | None
) -> Machine | None:
    """Read an ``<include>`` tag: the file, with its args and namespace, into the plan."""
    if not reader.enabled(context, element):
        return machine
    reader.check_attrs(context, element)
    filename = reader.required(context, element, "file")
    pass_all = False
    if "pass_all_args" in element.attrs:
        text = reader.resolve(context, element, element.attrs["pass_all_args"])
        pass_all = reader.boolean(context, element, text, "pass_all_args")
    child, _ = reader.ns_and_clear_params(context, element, include_file=filename)
    if pass_all:
        for name, value in context.subst.args.items():
            child.add_arg(name, value=value)
        child.pass_all_args = True
    child.filename = context.filename
    for inner in element.children:
        if inner.tag == "env":
            env_tag(reader, child, inner)
        elif inner.tag == "arg":
            arg_tag(reader, child, inner)
        else:
            reader.warn(child, inner, f"unrecognized '{inner.tag}' tag in <include> tag")
    child.filename = filename
    try:
        child.start_include()
    except ContextError as error:
        raise reader.fail(context, element, str(error)) from None
    launch = reader.parse(context, element, filename)
    path = os.path.normpath(Path(filename).absolute())
    if path in reader.including:
        chain = " -> ".join([*reader.including, path])
        raise reader.fail(context, element, f"the file includes itself: {chain}")
    reader.plan.files.append(filename)
    reader.launch_tag(child, launch)
    reader.including.append(path)
    machine = reader.recurse(child, launch.children, machine)
    reader.including.pop()
    if not pass_all and child.unused_args():
        unused = ", ".join(child.unused_args())
        raise reader.fail(context, element, f"unused args [{unused}] for include of [{filename}]")
    return machine


def remap_tag(reader: Reader, context: LoadContext, element: Element) -> tuple[str, str] | None:
    """Read a ``<remap>`` tag; its ``(from, to)``, or None when ``if``/``unless`` skip it."""
    if not reader.enabled(context, element):
        return None
    reader.check_attrs(context, element)
    if "from" not in element.attrs or "to" not in element.attrs:
        raise reader.fail(context, element, "<remap> tag is missing required from/to attributes")
    return (
        reader.resolve(context, element, element.attrs["from"]),
        reader.resolve(context, element, element.attrs["to"]),
    )


def add_remap(
    reader: Reader, context: LoadContext, element: Element, remap: tuple[str, str]
) -> None:
    """Add ``remap`` to the context, refusing names roslaunch refuses."""
    try:
        context.add_remap(*remap)
    except ContextError as error:
        raise reader.fail(context, element, f"Invalid <remap> tag: {error}.") from None


def env_tag(reader: Reader, context: LoadContext, element: Element) -> None:
    """Read an ``<env>`` tag into the context's environment."""
    if not reader.enabled(context, element):
        return
    reader.check_attrs(context, element)
    if "name" not in element.attrs or "value" not in element.attrs:
        raise reader.fail(context, element, "<env> tag is missing required name/value attributes")
    name = reader.resolve(context, element, element.attrs["name"])
    value = reader.resolve(context, element, element.attrs["value"])
    if not name:
        raise reader.fail(
            context, element, "Invalid <env> tag: 'name' attribute must be non-empty."
        )
    context.env.append((name, value))


__all__ = ["add_remap", "arg_tag", "env_tag", "group_tag", "include_tag", "remap_tag"]
