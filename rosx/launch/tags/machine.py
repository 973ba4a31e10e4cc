"""The ``<machine>`` tag: parsed and checked as roslaunch does (ros-* attributes and ``<env>``
refused since Fuerte; ``timeout``, ``ssh-port`` and ``default`` validated); a machine added
twice must match. Running on another machine is refused later, by the runner.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx.launch.model import Machine
from rosx.launch.tags import ATTRS

if TYPE_CHECKING:
    from rosx.launch.context import LoadContext
    from rosx.launch.reader import Reader
    from rosx.launch.xmldoc import Element

_MACHINE_DEFAULTS = {"true": (True, True), "false": (False, True), "never": (False, False)}
#: roslaunch's guess for a machine without ``env-loader`` (only compared, never run).
_ENV_LOADER = "/opt/ros/noetic/env.sh"


def machine_tag(reader: Reader, context: LoadContext, element: Element) -> Machine | None:
    """Read a ``<machine>`` tag; the machine, or None when ``if``/``unless`` skip it."""
    if not reader.enabled(context, element):
        return None
    context = context.child(None)
    if any(
        reader.optional(context, element, a)
        for a in ("ros-root", "ros-package-path", "ros-ip", "ros-hostname")
    ):
        raise reader.fail(
            context,
            element,
            "<machine>: ros-* attributes are not supported "
            "since ROS Fuerte. Please use env-loader instead",
        )
    reader.check_attrs(context, element)
    name = reader.required(context, element, "name")
    address = reader.required(context, element, "address")
    env_loader, port, user, password, default, timeout = (
        reader.optional(context, element, a) for a in ATTRS["machine"][2:]
    )
    try:
        ssh_port = int(port or "22")
    except ValueError as error:
        raise reader.fail(context, element, str(error)) from None
    default = (default or "false").lower()
    if default not in _MACHINE_DEFAULTS:
        raise reader.fail(context, element, f"Invalid value for 'attribute': {default}")
    for child in element.children:
        if child.tag == "env":
            raise reader.fail(
                context,
                child,
                "<machine>: <env> tag is not supported since ROS "
                "Fuerte. Please use env-loader instead",
            )
        reader.warn(context, child, f"unrecognized '{child.tag}' tag in <machine> tag")
    seconds = 10.0
    if timeout == "":
        raise reader.fail(context, element, "'timeout' cannot be empty")
    if timeout is not None:
        try:
            seconds = float(timeout)
        except ValueError:
            raise reader.fail(context, element, f"'timeout' be a number: [{timeout}]") from None
        if seconds <= 0.0:
            raise reader.fail(context, element, f"'timeout' be a positive number: [{timeout}]")
    return Machine(
        name,
        address,
        env_loader or _ENV_LOADER,
        ssh_port,
        user or None,
        password,
        seconds,
        default,
        reader.source(context, element),
    )


def add_machine(reader: Reader, context: LoadContext, element: Element, machine: Machine) -> None:
    """Add ``machine`` to the plan; refuse another of its name that differs, as roslaunch does."""
    known = reader.plan.machines.get(machine.name)
    if known is None:
        reader.plan.machines[machine.name] = machine
    elif _machine_key(known) != _machine_key(machine):
        raise reader.fail(
            context,
            element,
            f"Machine [{machine.name}] already added and does not match duplicate entry",
        )


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


__all__ = ["add_machine", "machine_tag"]
