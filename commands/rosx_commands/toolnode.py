"""`ToolNode`: the node a terminal tool subscribes through, started on first use.

A tool such as rqt_plot or rqt_topic talks to the master only when the user asks for a topic,
so its node (``/<tool>_<pid>_<ms>``, anonymous as ROS 1's tools name theirs) and its type store
are made the first time they are needed, from whichever thread needs them, and the node is shut
down when the tool closes. A tool's live source derives from it.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from rosx.msg.store import TypeStore
    from rosx.node import Node
    from rosx_commands.context import Environment


class ToolNode:
    """``tool``'s node on the master of ``env`` and the message types ``env`` knows."""

    def __init__(self, env: Environment, tool: str) -> None:
        self.env = env
        self.tool = tool
        self._node: Node | None = None
        self._store: TypeStore | None = None
        self._node_lock = threading.Lock()

    def close(self) -> None:
        """Shut the node down (``<tool> closed``) if it was started."""
        if self._node is not None:
            self._node.shutdown(f"{self.tool} closed")
            self._node = None

    def _types(self) -> TypeStore:
        """The message types (standard ones and ``ROS_PACKAGE_PATH``'s), parsed on first use."""
        if self._store is None:
            from rosx.msg.store import TypeStore  # noqa: PLC0415 - parsed lazily

            self._store = TypeStore.from_environ(self.env.environ)
        return self._store

    def _started(self) -> Node:
        """The node, started by the first caller; may block on the master."""
        with self._node_lock:
            if self._node is None:
                from rosx.names.anonymous import anonymous_node_name  # noqa: PLC0415 - name rules load only when used
                from rosx.node import Node  # noqa: PLC0415 - only a live tool needs the runtime

                self._node = Node(
                    anonymous_node_name(self.tool),
                    master_uri=self.env.master_uri,
                    environ=self.env.environ,
                ).start()
            return self._node
