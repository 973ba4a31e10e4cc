"""The exceptions of bag files, named and worded as ROS 1's rosbag names them.

Scripts written for ROS 1 catch ``rosbag.ROSBagException`` and its subclasses; the rosbag API
(`rosx.bag.api`) exports these classes under those names.
"""

from __future__ import annotations


class BagError(Exception):
    """Anything wrong with a bag file or its use (ROS 1's ``ROSBagException``)."""

    def __init__(self, value: str = "") -> None:
        super().__init__(value)
        self.value = value

    def __str__(self) -> str:
        return self.value


class BagFormatError(BagError):
    """The file's bytes are not a valid bag (ROS 1's ``ROSBagFormatException``)."""


class NotABagError(BagError):
    """The file does not begin with a bag's version line: it is empty, or not a bag at all."""


class BagUnindexedError(BagError):
    """The bag has no index: its recorder never closed it (``ROSBagUnindexedException``)."""

    def __init__(self, *args: object) -> None:
        super().__init__("Unindexed bag")


class BagEncryptNotSupportedError(BagError):
    """The bag is encrypted (``ROSBagEncryptNotSupportedException``); rosx cannot decrypt."""


__all__ = [
    "BagEncryptNotSupportedError",
    "BagError",
    "BagFormatError",
    "BagUnindexedError",
    "NotABagError",
]
