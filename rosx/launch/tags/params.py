"""The parameter tags of a launch file: ``<param>`` and ``<rosparam>``.

``<param>`` takes its value from ``value`` (typed as roslaunch types it), ``textfile``,
``binfile`` or ``command``; a private one (``~name``, or inside a ``<node>``) waits in the
context for the node it belongs to. ``<rosparam>`` loads YAML (inline or a ``file``, with
``subst_value``) into the plan's parameters, or records a ``dump``/``delete`` step.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.launch.context import LocalParam
from rosx.launch.model import RosparamCommand
from rosx.launch.tags import ATTRS
from rosx.launch.values import (
    ValueConversionError,
    binary_value,
    command_value,
    convert_value,
    flatten,
    load_yaml,
    text_value,
)
from rosx.names.resolution import canonicalize, ns_join
from rosx.names.validation import is_private

if TYPE_CHECKING:
    from rosx.launch.context import LoadContext
    from rosx.launch.reader import Reader
    from rosx.launch.xmldoc import Element


def param_tag(
    reader: Reader, context: LoadContext, element: Element, *, local: bool = False
) -> None:
    """Read a ``<param>`` tag into the plan (value, textfile, binfile or command)."""
    if not reader.enabled(context, element):
        return
    reader.check_attrs(context, element)
    type_ = (element.attrs.get("type") or "auto").lower().strip()
    given = {
        k: reader.optional(context, element, k) for k in ("value", "textfile", "binfile", "command")
    }
    if sum(v is not None for v in given.values()) != 1:
        raise reader.fail(
            context,
            element,
            "<param> tag must have one and only one of value/textfile/binfile.",
        )
    if "name" not in element.attrs:
        raise reader.fail(context, element, "<param> tag is missing required attribute: 'name'.")
    name = reader.resolve(context, element, element.attrs["name"].strip())
    try:
        value = param_value(reader, name, type_, given)
    except ValueConversionError as error:
        raise reader.fail(context, element, f"Invalid <param> tag: {error}.") from None
    if is_private(name) or local:
        context.add_param(LocalParam(canonicalize(name), value, reader.source(context, element)))
    else:
        reader.add_param(context, element, ns_join(context.ns, name), value)


def param_value(reader: Reader, name: str, type_: str, given: dict[str, str | None]) -> Any:
    """The value of a ``<param>`` from whichever of value, textfile, binfile or command it gives."""
    value, textfile, binfile, command = given.values()
    if value is not None:
        return convert_value(value.strip(), type_)
    if textfile is not None:
        return text_value(textfile, type_)
    if binfile is not None:
        return binary_value(binfile)
    assert command is not None
    return command_value(name, command, type_, reader.run)


def rosparam_tag(reader: Reader, context: LoadContext, element: Element) -> None:
    """Read a ``<rosparam>`` tag: load YAML into the plan, or record a dump or delete."""
    if not reader.enabled(context, element):
        return
    reader.check_attrs(context, element)
    command, ns, file, param, subst = (
        reader.optional(context, element, a) for a in ATTRS["rosparam"]
    )
    substitute = reader.boolean(context, element, subst, "subst_value")
    param = ns_join(ns or "", param or "")
    command = command or "load"
    if command not in ("load", "dump", "delete"):
        raise reader.fail(context, element, "command must be 'load', 'dump', or 'delete'")
    if file is not None:
        if command == "load" and not Path(file).is_file():
            raise reader.fail(context, element, f"file does not exist [{file}]")
        if command == "delete":
            raise reader.fail(
                context, element, "'file' attribute is invalid with 'delete' command."
            )
    full = ns_join(context.ns, param) if param else context.ns
    source = reader.source(context, element)
    if command != "load":
        step = RosparamCommand(command, full, file or "", source)  # type: ignore[arg-type]
        reader.plan.rosparam_commands.append(step)
        return
    text = element.text
    if file:
        try:
            text = Path(file).read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as error:
            raise reader.fail(context, element, f"cannot read [{file}]: {error}") from None
    if substitute:
        text = reader.resolve(context, element, text)
    try:
        data = load_yaml(text)
    except ValueConversionError as error:
        where = f"file {file} contains invalid YAML" if file else "invalid YAML"
        raise reader.fail(context, element, f"{where}: {error}") from None
    if data is None:
        data = {}
    if not param and not isinstance(data, dict):
        raise reader.fail(
            context, element, "'param' attribute must be set for non-dictionary values"
        )
    if full == "/" and not isinstance(data, dict):
        raise reader.fail(
            context, element, "Cannot load non-dictionary types into global namespace '/'"
        )
    try:
        for name, value in flatten(full, data):
            reader.add_param(context, element, name, value)
    except ValueConversionError as error:
        raise reader.fail(context, element, str(error)) from None


__all__ = ["param_tag", "param_value", "rosparam_tag"]
