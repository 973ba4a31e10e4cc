"""Names typed with spaces for underscores, as a lab sheet printed them.

Printed sheets and slides lose underscores: ``rosrun turtlesim turtle teleop key``,
``rostopic info /turtle1/cmd vel``, ``rosmsg show geometry msgs/Twist``, ``catkin make``; a
name broken across a line comes back with a space in it (``roslaunch turtle sim
multisim.launch``). The shell then splits one name into several words. `joined` finds the
name the words make when joined with ``_`` (or with nothing), among the names that exist; the
tools print ROS 1's error first, then what the user most likely meant.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable, Container, Sequence


def joined(
    words: Sequence[str], known: Container[str] | Callable[[str], bool]
) -> tuple[str, int] | None:
    """The longest name that the first two or more ``words`` make joined by ``_``, or by
    nothing, and that is ``known``, with how many words it took; None when there is none.

    ``joined(["turtle", "teleop", "key", "x"], {"turtle_teleop_key"})`` is
    ``("turtle_teleop_key", 3)``; ``joined(["turtle", "sim", "x.launch"], {"turtlesim"})`` is
    ``("turtlesim", 2)``.
    """
    exists = known if callable(known) else known.__contains__
    for count in range(len(words), 1, -1):
        for name in ("_".join(words[:count]), "".join(words[:count])):
            if exists(name):
                return name, count
    return None


def rejoined(
    words: Sequence[str], known: Container[str] | Callable[[str], bool]
) -> list[str] | None:
    """``words`` with the first two or more joined by ``_`` into a ``known`` name (`joined`),
    the rest as they are; None when no such name exists."""
    found = joined(words, known)
    if found is None:
        return None
    name, count = found
    return [name, *words[count:]]


__all__ = ["joined", "rejoined"]
