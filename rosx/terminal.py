"""Whether a stream is a terminal: what decides colour, bold text and full-screen views.

A stream without ``isatty`` (a test's `io.StringIO` has one; a bare writer may not) and a
closed stream are not terminals. The one home of this question for the tools, roslaunch's
console, roscpp-style consoles and the terminal UIs.
"""

from __future__ import annotations


def is_terminal(stream: object) -> bool:
    """Whether ``stream`` is a terminal (a closed stream, or one without ``isatty``, is not)."""
    isatty = getattr(stream, "isatty", None)
    try:
        return bool(isatty and isatty())
    except ValueError:  # a closed stream
        return False


__all__ = ["is_terminal"]
