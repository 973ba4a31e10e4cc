"""``tf2_py`` for scripts that rosx runs: tf2's core (``BufferCore``) and its exceptions."""

from __future__ import annotations

try:
    from rosx.tf.exceptions import (
        ConnectivityException,
        ExtrapolationException,
        InvalidArgumentException,
        LookupException,
        TimeoutException,
        TransformException,
    )
    from rosx.tf.pycore import BufferCore
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("tf2_py")
else:
    __all__ = [
        "BufferCore",
        "ConnectivityException",
        "ExtrapolationException",
        "InvalidArgumentException",
        "LookupException",
        "TimeoutException",
        "TransformException",
    ]
