"""What rosx reads of a package's ``CMakeLists.txt``: its install rules and its C++ targets.

rosx runs no CMake. ``catkin_make install`` still needs to know what a package installs, and
``catkin_make`` what it would compile, so this reads the few commands that say it:
``catkin_install_python(PROGRAMS … DESTINATION …)``, ``install(PROGRAMS|FILES|DIRECTORY …
DESTINATION …)`` (with catkin's ``${CATKIN_PACKAGE_*_DESTINATION}`` variables), and
``add_executable``/``add_library`` (C++ targets). Comments and quoting are handled; other
variables and generator expressions are not evaluated: a rule using them is skipped.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import NamedTuple

_COMMAND = re.compile(r"(?im)^[ \t]*([a-z_][a-z0-9_]*)[ \t]*\(([^)]*)\)")
_ARGUMENT = re.compile(r'"((?:[^"\\]|\\.)*)"|([^\s"]+)')
_KINDS = ("PROGRAMS", "FILES", "DIRECTORY", "TARGETS")
_KEYWORDS = {
    "DESTINATION",
    "PERMISSIONS",
    "CONFIGURATIONS",
    "COMPONENT",
    "RENAME",
    "OPTIONAL",
    "USE_SOURCE_PERMISSIONS",
    "FILES_MATCHING",
    "PATTERN",
    "REGEX",
    "EXCLUDE",
    "ARCHIVE",
    "LIBRARY",
    "RUNTIME",
}


class InstallRule(NamedTuple):
    """Copy ``sources`` (``PROGRAMS``, ``FILES`` or ``DIRECTORY``) to ``destination``, a path
    relative to the install space."""

    kind: str
    sources: tuple[str, ...]
    destination: str


def _strip_comments(text: str) -> str:
    lines = []
    for line in text.splitlines():
        quoted = False
        end = len(line)
        for index, char in enumerate(line):
            if char == '"':
                quoted = not quoted
            elif char == "#" and not quoted:
                end = index
                break
        lines.append(line[:end])
    return "\n".join(lines)


def _commands(text: str) -> list[tuple[str, list[str]]]:
    found = []
    for match in _COMMAND.finditer(_strip_comments(text)):
        words = [q if q is not None and q != "" else p for q, p in _ARGUMENT.findall(match[2])]
        found.append((match[1].lower(), words))
    return found


def destinations(package: str) -> dict[str, str]:
    """catkin's destination variables for ``package``, relative to the install space."""
    return {
        "CATKIN_PACKAGE_BIN_DESTINATION": f"lib/{package}",
        "CATKIN_PACKAGE_LIB_DESTINATION": "lib",
        "CATKIN_PACKAGE_SHARE_DESTINATION": f"share/{package}",
        "CATKIN_PACKAGE_PYTHON_DESTINATION": f"lib/python3/dist-packages/{package}",
        "CATKIN_PACKAGE_INCLUDE_DESTINATION": f"include/{package}",
        "CATKIN_PACKAGE_ETC_DESTINATION": f"etc/{package}",
        "CATKIN_GLOBAL_BIN_DESTINATION": "bin",
        "CATKIN_GLOBAL_LIB_DESTINATION": "lib",
        "CATKIN_GLOBAL_SHARE_DESTINATION": "share",
        "CATKIN_GLOBAL_INCLUDE_DESTINATION": "include",
        "CATKIN_GLOBAL_ETC_DESTINATION": "etc",
        "CATKIN_GLOBAL_PYTHON_DESTINATION": "lib/python3/dist-packages",
        "PROJECT_NAME": package,
    }


def _expand(word: str, variables: dict[str, str]) -> str | None:
    expanded = re.sub(r"\$\{(\w+)\}", lambda m: variables.get(m[1], "\0"), word)
    return None if "\0" in expanded or "$" in expanded else expanded


def _rule(kind: str, words: list[str], variables: dict[str, str]) -> InstallRule | None:
    if "DESTINATION" not in words:
        return None
    at = words.index("DESTINATION")
    if at + 1 >= len(words):
        return None
    destination = _expand(words[at + 1], variables)
    sources: list[str] = []
    for word in words:
        if word in _KEYWORDS:
            break
        expanded = _expand(word, variables)
        if expanded is None:
            return None
        sources.append(expanded)
    if destination is None or not sources:
        return None
    return InstallRule(kind, tuple(sources), destination.strip("/"))


def install_rules(package: str, cmakelists: Path) -> list[InstallRule]:
    """The install rules of ``cmakelists`` that rosx can follow, in order."""
    try:
        text = cmakelists.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return []
    variables = destinations(package)
    rules: list[InstallRule] = []
    for name, words in _commands(text):
        if name == "catkin_install_python" and words[:1] == ["PROGRAMS"]:
            rule = _rule("PROGRAMS", words[1:], variables)
        elif name == "install" and words[:1] and words[0] in _KINDS[:3]:
            rule = _rule(words[0], words[1:], variables)
        else:
            continue
        if rule is not None:
            rules.append(rule)
    return rules


def cpp_targets(cmakelists: Path) -> list[str]:
    """The C++ executables and libraries ``cmakelists`` builds (``add_executable``,
    ``add_library``), by name."""
    try:
        text = cmakelists.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return []
    project = next((words[0] for name, words in _commands(text) if name == "project" and words), "")
    targets = []
    for name, words in _commands(text):
        if name in ("add_executable", "add_library") and words:
            targets.append(words[0].replace("${PROJECT_NAME}", project))
    return targets


__all__ = ["InstallRule", "cpp_targets", "destinations", "install_rules"]
