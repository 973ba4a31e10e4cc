"""What a node does with its command line before it runs: private parameters (``_name:=value``).

ROS 1 (rospy's ``init_node``) sets each ``_name:=value`` argument as the node's private
parameter ``~name`` before the node's own code starts:

* the value is YAML, read as PyYAML's ``safe_load`` reads it (`rosx.msg.text.yamlload`): ``1`` is an
  int, ``1.0`` a float, ``true`` a bool, ``'1'`` and ``hello`` strings, ``[1, 2]`` a list,
  ``{a: 1}`` a dict (which replaces the namespace ``~name``);
* ``~name`` resolves against the node's name, after ``__name:=``/``__ns:=``, and then through
  the node's remappings, as every name the node uses;
* a later argument for the same name wins.

A value that is not YAML, or that the Parameter Server cannot hold (null, a date, an integer
beyond 32 bits), stops the start with `ParamArgsError` before any parameter is set.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.names.remap_args import RemapArgs
from rosx.names.resolution import resolve
from rosx.node.errors import NodeError

if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.master.client import MasterClient


class ParamArgsError(NodeError, ValueError):
    """A ``_name:=value`` argument that cannot be set; the text is rospy's, plus what is wrong."""


def load_private_params(raw: Mapping[str, str]) -> dict[str, Any]:
    """Each ``_name:=value``'s value read as YAML, by name without the underscore.

    Raises:
        ParamArgsError: a value is not YAML, or not something the Parameter Server stores.
    """
    from rosx.msg.text.yamlload import YAMLLoadError, load  # noqa: PLC0415 - ruamel loads lazily
    from rosx.msg.text.yamlparams import ParamValueError, check_value  # noqa: PLC0415 - the text forms load on first use

    values: dict[str, Any] = {}
    for name, text in raw.items():
        try:
            value = load(text)
            check_value(value, "~" + name)
        except (YAMLLoadError, ParamValueError) as error:
            raise ParamArgsError(f"invalid command-line parameters: {error}") from None
        values[name] = value
    return values


def private_param_keys(
    values: Mapping[str, Any],
    *,
    node_name: str,
    namespace: str = "/",
    remappings: Mapping[str, str] | None = None,
) -> dict[str, Any]:
    """``values`` keyed by the global names of ``~name``, for node ``node_name``."""
    return {
        resolve("~" + name, namespace, node_name, remappings, strict=False): value
        for name, value in values.items()
    }


def set_private_params(
    master: MasterClient,
    args: RemapArgs | Mapping[str, str],
    *,
    node_name: str,
    namespace: str = "/",
    remappings: Mapping[str, str] | None = None,
) -> dict[str, Any]:
    """Set the private parameters of a command line on the master; returns what was set.

    Args:
        master: The master, called as the node (its caller id).
        args: The parsed command line (`rosx.names.parse_remap_args`), or its ``params``.
        node_name: The node's name after ``__name:=`` (global, or relative to ``namespace``).
        namespace: The node's namespace after ``__ns:=``.
        remappings: The node's name remappings.

    Raises:
        ParamArgsError: a value cannot be set (nothing is set then).
        MasterError, MasterUnreachable: the master refused or cannot be reached.
    """
    raw = args.params if isinstance(args, RemapArgs) else args
    keyed = private_param_keys(
        load_private_params(raw), node_name=node_name, namespace=namespace, remappings=remappings
    )
    for key, value in keyed.items():
        master.call("setParam", key, value)
    return keyed


__all__ = ["ParamArgsError", "load_private_params", "private_param_keys", "set_private_params"]
