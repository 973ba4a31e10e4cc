"""``genpy.rostime`` for scripts that rosx runs (see the ``genpy`` package)."""

from rosx.msg.codec.rostime import Duration, Time, TVal

__all__ = ["Duration", "TVal", "Time"]
