"""``tf_conversions`` for scripts that rosx runs: its ``transformations``, which are tf's
(``tf.transformations``, `rosx.tf.transformations`).

The tf2 tutorials for Python compute a turtle's quaternion with
``tf_conversions.transformations.quaternion_from_euler``. ROS 1's package also has
``posemath``: conversions to and from PyKDL's ``Frame``. rosx has no PyKDL, so those names
say so, and what does the same arithmetic, when a script asks for them. A Python that cannot
import rosx gets the next ``tf_conversions`` on its path instead.
"""

from __future__ import annotations

from typing import Any

try:
    import rosx.tf  # noqa: F401 - whether this Python has rosx
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("tf_conversions")
else:
    from tf import transformations  # type: ignore[import-not-found]

    #: What rosx says of ``posemath`` and its conversions (all of them make or take PyKDL frames).
    WITHOUT_PYKDL = (
        "works on PyKDL frames, which rosx does not provide; tf.transformations (also "
        "tf_conversions.transformations) does the same arithmetic on 4x4 matrices, and "
        "tf2_geometry_msgs transforms points and poses"
    )
    _POSEMATH = frozenset(
        ("fromTf", "toTf", "fromMsg", "toMsg", "fromMatrix", "toMatrix", "fromCameraParams")
    )

    def __getattr__(name: str) -> Any:
        if name in _POSEMATH:
            raise AttributeError(f"tf_conversions.{name} {WITHOUT_PYKDL}")
        raise AttributeError(f"module 'tf_conversions' has no attribute '{name}'")

    __all__ = ["transformations"]
