"""The core's errors as ROS 1's tools print them: the one place the CLI words them.

`rosx_commands.cli.run_command` hands every exception a sub-command lets through to
`command_error`; what it maps becomes one line on stderr (two for an unreachable master on a
terminal) and the tool's error status, anything else stays a bug and keeps its traceback.

- `rosx.master.client.MasterUnreachable`: ``ERROR: Unable to communicate with master!``
- `rosx.master.client.MasterError`: ``ERROR: <the master's status message>``
- `rosx.node.service_client.ServiceRefused`: ``ERROR: service [/x] responded with an error:
  b'<the server's text>'``, as rospy under Python 3 shows it
- any other `rosx.node.errors.ServiceError`: ``ERROR: <rospy's text>``
- `rosx.graph.describe.UnknownTopicError`: ``ERROR: Unknown topic /x``
- `rosx.graph.describe.NodeContactError`: ``ERROR: Communication with node[<uri>] failed!``

ROS 1's scripts and tests match the master's line exactly, so the hint on how to get a master
is added only when stderr is a terminal.
"""

from __future__ import annotations

import io
import sys

from rosx_commands.context import CommandError, Environment

#: ROS 1's words when the master does not answer.
UNREACHABLE = "ERROR: Unable to communicate with master!"


def unreachable(env: Environment, uri: str, status: int = 1) -> CommandError:
    """ROS 1's line for a master that does not answer; on a terminal, how to get one."""
    text = UNREACHABLE
    if env.stderr_isatty:
        text += (
            f"\nNo master answers at ROS_MASTER_URI={uri}: start one with `rosx roscore` "
            "(or `rosx sim`) in another terminal, or point ROS_MASTER_URI at a running one."
        )
    return CommandError(text, status)


def command_error(error: BaseException, env: Environment, status: int) -> CommandError | None:
    """The `CommandError` (text and ``status``) ``error`` stands for, or None if it is none of
    the core's errors."""
    # A class whose module was never imported cannot have raised: look only at loaded ones.
    loaded = sys.modules
    if "rosx.master.client" in loaded:
        from rosx.master.client import MasterError, MasterUnreachable  # noqa: PLC0415 - the master's code loads only to talk to one

        if isinstance(error, MasterUnreachable):
            return unreachable(env, error.uri, status)
        if isinstance(error, MasterError):
            # rosmaster's own texts for bad arguments already begin with "ERROR: ".
            text = error.status
            return CommandError(text if text.startswith("ERROR: ") else f"ERROR: {text}", status)
    if "rosx.node.service_client" in loaded:
        from rosx.node.service_client import ServiceRefused  # noqa: PLC0415 - the node runtime loads with the first node

        if isinstance(error, ServiceRefused):
            # rospy under Python 3 shows the server's text as bytes, and so does rosservice.
            return CommandError(
                f"ERROR: service [{error.service}] responded with an error: {error.payload!r}",
                status,
            )
    if "rosx.node.errors" in loaded:
        from rosx.node.errors import ServiceError  # noqa: PLC0415 - the node runtime loads with the first node

        if isinstance(error, ServiceError):
            return CommandError(f"ERROR: {error}", status)
    if "rosx.bag.errors" in loaded:
        from rosx.bag.errors import BagError  # noqa: PLC0415 - bag code loads only for bags

        if isinstance(error, BagError):  # a damaged chunk met while reading messages
            return CommandError(f"ERROR: {error}", status)
    if "rosx.graph.describe" in loaded:
        from rosx.graph.describe import NodeContactError, UnknownTopicError  # noqa: PLC0415 - graph code loads only when asked for

        if isinstance(error, UnknownTopicError | NodeContactError):
            return CommandError(f"ERROR: {error}", status)
    return None


def error_line(error: BaseException) -> str:
    """``error`` as one line for a terminal UI's status line: the core's errors in ROS 1's
    words (`command_error`), any other as its text."""
    quiet = Environment(stdout=io.StringIO(), stderr=io.StringIO(), environ={})
    mapped = command_error(error, quiet, 1)
    text = mapped.message if mapped else str(error)
    return text.splitlines()[0] if text.strip() else type(error).__name__
