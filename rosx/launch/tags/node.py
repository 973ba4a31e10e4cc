"""The ``<node>`` and ``<test>`` tags: a `Node` (or `Test`, parsed but not run) with its
namespace, private parameters, remappings and environment, checked as roslaunch checks them
(respawn with required, names with a namespace, ``output``, ``cwd``, duplicate names).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.launch.model import Node, Test
from rosx.launch.tags.params import param_tag, rosparam_tag
from rosx.launch.tags.scope import add_remap, env_tag, remap_tag
from rosx.names.resolution import make_global_ns, ns_join
from rosx.names.validation import is_legal_name, is_private

if TYPE_CHECKING:
    from rosx.launch.context import LoadContext
    from rosx.launch.model import Machine
    from rosx.launch.reader import Reader
    from rosx.launch.xmldoc import Element

_TEST_TIME_LIMIT = 60.0


def node_tag(
    reader: Reader, context: LoadContext, element: Element, machine: Machine | None
) -> None:
    """Read a ``<node>`` or ``<test>`` tag and its children into the plan."""
    if not reader.enabled(context, element):
        return
    is_test = element.tag == "test"
    reader.check_attrs(context, element)
    test_name, time_limit, retry = "", _TEST_TIME_LIMIT, 0
    if is_test:
        name = reader.optional(context, element, "name") or ""
        test_name, time_limit, retry = test_attrs(reader, context, element)
        name = name or test_name
    else:
        name = reader.required(context, element, "name")
    if not is_legal_name(name):
        reader.warn(
            context,
            element,
            f"WARN: illegal <node> name '{name}'. "
            "http://ros.org/wiki/Names This will likely cause "
            "problems with other ROS tools.",
        )
    child, cleared = reader.ns_and_clear_params(context, element, node_name=name)
    try:
        private = child.child(name)
    except ValueError as error:
        raise reader.fail(context, element, str(error)) from None
    private.params = []
    package = reader.required(context, element, "pkg")
    type_ = reader.required(context, element, "type")
    attrs = {
        a: reader.optional(context, element, a)
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
    required = reader.boolean(context, element, attrs["required"], "required")
    respawn = reader.boolean(context, element, attrs["respawn"], "respawn")
    respawn_delay = reader.seconds(context, element, attrs["respawn_delay"], "respawn_delay")
    remaps, env = node_children(reader, context, element, private)
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
        raise reader.fail(context, element, f"Invalid <{element.tag}> tag: {problem}.")
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
        "source": reader.source(context, element),
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
        reader.plan.tests.append(test)
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
        if resolved in reader.node_names:
            raise reader.fail(
                context,
                element,
                f"roslaunch file contains multiple nodes named [{resolved}]. Please check all "
                "<node> 'name' attributes to make sure they are unique. Also check that "
                "$(anon id) use different ids.",
            )
        reader.node_names.append(resolved)
    reader.plan.nodes.append(node)


def node_children(
    reader: Reader, context: LoadContext, element: Element, private: LoadContext
) -> tuple[LoadContext, LoadContext]:
    """Read a node's tags; its private params go to the plan. Returns (remaps, env)."""
    remaps = context.child("")
    env = context.child("")
    for inner in element.children:
        if inner.tag == "remap":
            remap = remap_tag(reader, context, inner)
            if remap is not None:
                add_remap(reader, remaps, inner, remap)
        elif inner.tag == "param":
            param_tag(reader, private, inner, local=True)
        elif inner.tag == "rosparam":
            rosparam_tag(reader, private, inner)
        elif inner.tag == "env":
            env_tag(reader, env, inner)
        else:
            reader.warn(
                context,
                inner,
                f"WARN: unrecognized '{inner.tag}' child tag in the parent tag element",
            )
    for local in [*context.params, *private.params]:
        key = local.key[1:] if is_private(local.key) else local.key
        reader.add_param(context, element, private.ns + key, local.value, local.source)
    return remaps, env


def test_attrs(reader: Reader, context: LoadContext, element: Element) -> tuple[str, float, int]:
    """A ``<test>``'s name, time limit and retries; refuses a node's attributes it may not have."""
    for attr in ("respawn", "respawn_delay", "output"):
        if attr in element.attrs:
            raise reader.fail(context, element, f"<test> tags cannot have '{attr}' attribute")
    test_name = reader.required(context, element, "test-name")
    limit_text = reader.resolve(context, element, element.attrs.get("time-limit", ""))
    retry_text = reader.resolve(context, element, element.attrs.get("retry", ""))
    time_limit, retry = _TEST_TIME_LIMIT, 0
    if limit_text:
        time_limit = reader.number(context, element, float, "time-limit", limit_text)
        if time_limit <= 0.0:
            raise reader.fail(context, element, "'time-limit' must be a positive number")
    if retry_text:
        retry = reader.number(context, element, int, "retry", retry_text)
    return test_name, time_limit, retry


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


__all__ = ["node_children", "node_tag", "test_attrs"]
