"""Package names loaded on first use (PEP 562), for the packages whose modules are many.

    __getattr__ = lazy_names(__name__, {"Node": "rosx.node.node"})

``from package import Node`` then imports `rosx.node.node` only when asked, so a tool that
needs one module of a package does not pay for the rest. Imports only importlib and sys, so
every layer may use it at no cost.
"""

from __future__ import annotations

import importlib
import sys

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable, Mapping
    from typing import Any


def lazy_names(package: str, homes: Mapping[str, str]) -> Callable[[str], Any]:
    """A module ``__getattr__`` for ``package``: each name of ``homes`` is imported from its
    module on first use and kept in the package."""

    def load(name: str) -> Any:
        home = homes.get(name)
        if home is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(home), name)
        setattr(sys.modules[package], name, value)
        return value

    return load
