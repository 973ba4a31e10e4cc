"""The one error of the launch layer: what is wrong, in which file, on which line, in which tag.

ROS 1's roslaunch often says only what is wrong (ros_comm#70); every `LaunchError` also says
where, so that a user can go straight to the offending tag.
"""

from __future__ import annotations


class LaunchError(Exception):
    """A launch file cannot be loaded; nothing of it is started.

    ``str()`` is one line, ``FILE:LINE: <TAG>: MESSAGE``, without the parts that are unknown
    (a file that is not XML has no tag). An error about no file at all (a node name not found
    by ``--args``) is its message alone, as roslaunch prints it.

    Attributes:
        file: The launch file the error is in ("" when it is not about a file).
        line: The 1-based line of the tag (0 when unknown).
        tag: The tag's name, ``node``, ``param``… ("" when unknown).
        message: What is wrong, in ROS 1's words where it has them.
        status: The exit status roslaunch ends with for this error (1 unless said otherwise).
    """

    status: int = 1

    def __init__(self, file: str, line: int, tag: str, message: str) -> None:
        super().__init__(file, line, tag, message)
        self.file = file
        self.line = line
        self.tag = tag
        self.message = message

    def __str__(self) -> str:
        where = self.file
        if where and self.line:
            where = f"{where}:{self.line}"
        parts = [p for p in (where, f"<{self.tag}>" if self.tag else "") if p]
        if not parts:
            return self.message
        message = " ".join(self.message.split("\n")).strip()
        return ": ".join([*parts, message])


class ResourceNotFoundError(LaunchError):
    """A package not on the package path, named by ``$(find PACKAGE)`` or a node's ``pkg``;
    ``package`` names it. ``str()`` says ``Resource not found: PACKAGE``; roslaunch says it as
    rospkg's error, the package and the paths searched (`located`)."""

    def __init__(self, file: str, line: int, tag: str, package: str) -> None:
        super().__init__(file, line, tag, f"Resource not found: {package}")
        self.package = package

    def located(self) -> str:
        """``FILE:LINE: <TAG>: PACKAGE``: where, then the package alone (what rospkg names)."""
        return str(LaunchError(self.file, self.line, self.tag, self.package))


__all__ = ["LaunchError", "ResourceNotFoundError"]
