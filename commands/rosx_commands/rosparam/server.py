"""The Parameter Server as ROS 1's rosparam uses it: names, values, and the texts it prints.

Setting a dictionary *updates* a namespace: each leaf is set on its own (``rosparam set /a
'{b: 1}'`` leaves ``/a/c`` alone, and an empty dictionary sets nothing), as rosparam does.
Values are checked before the first one is sent, so a value the server cannot hold changes
nothing. The master's refusals (`rosx.master.client.MasterError`) are printed as ROS 1 prints
them, ``ERROR: <its status message>``, by the CLI's error mapping.
"""

from __future__ import annotations

import os

from rosx.msg.text.yamlparams import ParamValueError, check_value
from rosx.names.resolution import ns_join
from rosx.names.script import ros_namespace, script_resolve_name
from rosx_commands.context import CommandError, Environment

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

NAME = "rosparam"


class ParamServer:
    """One rosparam run's view of the Parameter Server."""

    def __init__(self, env: Environment) -> None:
        self.env = env
        self.namespace = ros_namespace(env.environ)
        caller_id = ns_join(self.namespace, f"{NAME}-{os.getpid()}")
        self.master = env.master(caller_id)

    def resolve(self, name: str | None) -> str:
        """A parameter name typed by the user, resolved as rosparam does."""
        return script_resolve_name(NAME, name or "", self.namespace)

    def get(self, name: str) -> Any:
        """The value (or namespace, as a dict) of ``name``; `MasterError` when it is not set."""
        return self.master.call("getParam", name)

    def names(self) -> list[str]:
        """Every parameter's full name (``getParamNames``)."""
        return [str(name) for name in self.master.call("getParamNames")]

    def delete(self, name: str) -> None:
        """Delete ``name`` (``deleteParam``); `MasterError` when it is not set."""
        self.master.call("deleteParam", name)

    def replace_root(self) -> None:
        """Empty the whole server (the root cannot be deleted, only set to ``{}``)."""
        self.master.call("setParam", "/", {})

    def set_raw(self, name: str, value: Any, *, verbose: bool = False) -> None:
        """Set ``name`` to ``value``; a dict sets each of its leaves (rosparam's update)."""
        try:
            check_value(value, name)
        except ParamValueError as error:
            raise CommandError(f"ERROR: {error}") from None
        for key, leaf in _leaves(name, value):
            self.master.call("setParam", key, leaf)
            if verbose:
                self.env.out(f"set parameter [{key}] to [{py_str(leaf)}]")

    def print_params(self, params: Any, namespace: str) -> None:
        """``name=value`` for every leaf under ``namespace`` (rosparam's verbose listing)."""
        if type(params) is dict:
            for key, value in params.items():
                if type(value) is dict:
                    self.print_params(value, ns_join(namespace, key))
                else:
                    self.env.out(f"{ns_join(namespace, key)}={py_str(value)}")
        else:
            self.env.out(py_str(params))


def _leaves(name: str, value: Any) -> list[tuple[str, Any]]:
    if type(value) is not dict:
        return [(name, value)]
    leaves: list[tuple[str, Any]] = []
    for key, item in value.items():
        leaves += _leaves(ns_join(name, key), item)
    return leaves


def py_str(value: object) -> str:
    """``str(value)`` as rosparam prints it; binary values show their bytes as Latin-1 text."""
    if isinstance(value, bytes):
        return value.decode("latin-1")
    return str(value)
