"""`GraphOptions`: rqt_graph's controls, with its defaults, and its name filters.

Defaults are rqt_graph's (``ros_graph.py`` ``restore_settings``): *Nodes only*, filters ``/``,
namespace groups 2 deep, actions/tf/images grouped, dead sinks, leaf topics, debug, unreachable
nodes and dynamic_reconfigure topics hidden, tf shown.

A filter is a comma list; an entry starting with ``-`` excludes. An entry made only of letters,
digits, ``_`` and ``/`` matches a name exactly; any other entry is a regular expression matched
at the start of the name. No inclusion (or only ``/``) includes everything.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from enum import Enum


class Mode(str, Enum):
    """rqt_graph's graph types."""

    NODES = "nodes"  # Nodes only: node → node edges labelled by topic
    ACTIVE = "active"  # Nodes/Topics (active): connections the nodes report
    ALL = "all"  # Nodes/Topics (all): every registration the master holds

    @property
    def caption(self) -> str:
        """The graph-mode combo box's label, as rqt_graph words it."""
        return {
            Mode.NODES: "Nodes only",
            Mode.ACTIVE: "Nodes/Topics (active)",
            Mode.ALL: "Nodes/Topics (all)",
        }[self]


#: Names that rqt_graph's "Hide: Debug" hides (a node or topic containing one of them).
QUIET_NAMES = (
    "/diag_agg",
    "/runtime_logger",
    "/pr2_dashboard",
    "/rviz",
    "/rosout",
    "/cpu_monitor",
    "/monitor",
    "/hd_monitor",
    "/rxloggerlevel",
    "/clock",
    "/rqt",
    "/statistics",
)
#: Topics whose node → node edges "Hide: Debug" hides.
QUIET_EDGE_TOPICS = ("/time", "/clock", "/rosout", "/statistics")

_PLAIN_NAME = re.compile(r"^[a-zA-Z0-9_/]+$")


def is_quiet(name: str) -> bool:
    """Whether "Hide: Debug" hides the node or topic ``name``."""
    return any(q in name for q in QUIET_NAMES) or name.rsplit("/", 1)[-1].startswith("_")


@dataclass(frozen=True)
class NameFilter:
    """A parsed filter: inclusions and exclusions."""

    includes: tuple[str, ...]
    excludes: tuple[str, ...]

    @staticmethod
    def parse(text: str) -> NameFilter:
        """Parse ``"/a,-/b.*"``; a bad regular expression raises `ValueError`."""
        includes: list[str] = []
        excludes: list[str] = []
        for raw in text.split(","):
            entry = raw.strip()
            if entry.startswith("-"):
                excludes.append(entry[1:])
            else:
                includes.append(entry)
        if includes in ([], ["/"], [""]):
            includes = [".*"]
        for pattern in (*includes, *excludes):
            if not _PLAIN_NAME.match(pattern):
                try:
                    re.compile(pattern)
                except re.error as error:
                    raise ValueError(f"bad filter {pattern!r}: {error}") from None
        return NameFilter(tuple(includes), tuple(excludes))

    def accepts(self, name: str) -> bool:
        """Whether ``name`` matches an include pattern and no exclude pattern."""
        return _matches_any(name, self.includes) and not _matches_any(name, self.excludes)


def _matches_any(name: str, patterns: tuple[str, ...]) -> bool:
    name = name.strip()
    for pattern in patterns:
        if name == pattern:
            return True
        if not _PLAIN_NAME.match(pattern) and re.match(pattern, name):
            return True
    return False


@dataclass(frozen=True)
class GraphOptions:
    """Every control of rqt_graph's tool bar that changes what is drawn."""

    mode: Mode = Mode.NODES
    namespace_filter: str = "/"
    topic_filter: str = "/"
    group_depth: int = 2
    group_actions: bool = True
    group_tf: bool = True
    group_images: bool = True
    hide_dead_sinks: bool = True
    hide_leaf_topics: bool = True
    hide_debug: bool = True
    hide_tf: bool = False
    hide_unreachable: bool = True
    hide_params: bool = True
