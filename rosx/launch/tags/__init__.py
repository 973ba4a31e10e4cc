"""The attributes each launch-file tag takes (roslaunch's ``xmlloader.py`` lists), and the
modules that read the tags by family: `scope` (arg, group, include, remap, env), `params`
(param, rosparam), `node` (node, test) and `machine`. `rosx.launch.reader` dispatches to them.
"""

from __future__ import annotations

NODE_ATTRS = [
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
TEST_ATTRS = [*NODE_ATTRS, "test-name", "time-limit", "retry"]
ATTRS = {
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
    "node": tuple(NODE_ATTRS),
    "test": tuple(TEST_ATTRS),
}

__all__ = ["ATTRS", "NODE_ATTRS", "TEST_ATTRS"]
