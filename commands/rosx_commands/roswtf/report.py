"""roswtf's findings and how they are worded and printed.

A check returns nothing when all is well, else a value that completes its message as roswtf
completes it: a string is appended, a list becomes `` * item`` lines under the message, any
other true value leaves the message alone. `Findings.print` writes the summary roswtf writes,
with its ANSI bold ``WARNING`` and red ``ERROR`` (roswtf writes them whatever the terminal).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx_commands.context import Environment

WARNING = "\033[1mWARNING\033[0m"
ERROR = "\033[31m\033[1mERROR\033[0m"


def worded(message: str, found: object) -> str:
    """``message`` completed with what a check ``found``."""
    if isinstance(found, (list, tuple)):
        return message + "\n" + "\n".join(f" * {item}" for item in found) + "\n"
    if isinstance(found, str):
        return message + found
    return message


class Findings:
    """Warnings and errors found so far."""

    def __init__(self) -> None:
        self.warnings: list[str] = []
        self.errors: list[str] = []

    def check(self, level: str, message: str, found: object) -> None:
        """Record ``message`` at ``level`` (``warning``/``error``) if ``found`` is true."""
        if found:
            (self.warnings if level == "warning" else self.errors).append(worded(message, found))

    def run(self, rules: list[tuple[str, Callable[[], object], str]]) -> None:
        """Run ``(level, check, message)`` rules in order."""
        for level, check, message in rules:
            self.check(level, message, check())

    def clear(self) -> None:
        """Forget the warnings and errors found so far."""
        self.warnings.clear()
        self.errors.clear()

    def print(self, env: Environment) -> None:
        """roswtf's summary: ``No errors or warnings``, or the warnings then the errors."""
        if not self.warnings and not self.errors:
            env.out("No errors or warnings")
            return
        if self.warnings:
            env.out(
                f"Found {len(self.warnings)} warning(s).\nWarnings are things that may be just "
                "fine, but are sometimes at fault\n"
            )
            for text in self.warnings:
                env.out(f"{WARNING} {text}")
            env.out("")
        if self.errors:
            env.out(f"Found {len(self.errors)} error(s).\n")
            for text in self.errors:
                env.out(f"{ERROR} {text}")


__all__ = ["ERROR", "WARNING", "Findings", "worded"]
