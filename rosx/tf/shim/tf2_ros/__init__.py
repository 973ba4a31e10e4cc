"""``tf2_ros`` for scripts that rosx runs: ROS 1's tf2 Python API, served by `rosx.tf`.

Like ``rospy`` (in the client layer's shim directory), this directory is on ``sys.path`` only
for the scripts rosx runs. A Python that cannot import rosx (say, a ROS 1 installation's own)
gets the next ``tf2_ros`` on its path instead.
"""

from __future__ import annotations

try:
    from rosx.client.modules import install as _install
    from rosx.tf.broadcaster import StaticTransformBroadcaster, TransformBroadcaster
    from rosx.tf.buffer import DEFAULT_CAN_TRANSFORM_POLLING_SCALE, Buffer
    from rosx.tf.exceptions import (
        ConnectivityException,
        ExtrapolationException,
        InvalidArgumentException,
        LookupException,
        TimeoutException,
        TransformException,
    )
    from rosx.tf.interface import (
        BufferInterface,
        ConvertRegistration,
        NotImplementedException,
        Stamped,
        TransformRegistration,
        TypeException,
        convert,
    )
    from rosx.tf.listener import TransformListener
    from rosx.tf.pycore import BufferCore
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("tf2_ros")
else:
    _install()

    class BufferClient(BufferInterface):
        """tf2_ros's action-based buffer; rosx's scripts use a `Buffer` of their own."""

        def __init__(self, ns: str, check_frequency: object = None, timeout_padding: object = None):
            raise NotImplementedError(
                "tf2_ros.BufferClient needs tf2's buffer_server, which rosx does not provide; "
                "use tf2_ros.Buffer() with a tf2_ros.TransformListener"
            )

    __all__ = [
        "DEFAULT_CAN_TRANSFORM_POLLING_SCALE",
        "Buffer",
        "BufferClient",
        "BufferCore",
        "BufferInterface",
        "ConnectivityException",
        "ConvertRegistration",
        "ExtrapolationException",
        "InvalidArgumentException",
        "LookupException",
        "NotImplementedException",
        "Stamped",
        "StaticTransformBroadcaster",
        "TimeoutException",
        "TransformBroadcaster",
        "TransformException",
        "TransformListener",
        "TransformRegistration",
        "TypeException",
        "convert",
    ]
