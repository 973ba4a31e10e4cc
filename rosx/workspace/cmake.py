"""What rosx reads of a package's ``CMakeLists.txt``: install rules, C++ targets, type files.

rosx runs no CMake. ``catkin_make install`` still needs to know what a package installs, and
``catkin_make`` what it would compile and generate, so this reads the few commands that say it:
``catkin_install_python(PROGRAMS … DESTINATION …)``, ``install(PROGRAMS|FILES|DIRECTORY …
DESTINATION …)`` (with catkin's ``${CATKIN_PACKAGE_*_DESTINATION}`` variables),
``add_executable``/``add_library`` (C++ targets), ``add_message_files``,
``add_service_files``, ``add_action_files`` (`type_files`), and ``catkin_python_setup``
(`rosx.workspace.python_setup` carries it out). Comments and quoting are handled;
other variables and generator expressions are not evaluated: a rule using them is skipped.

Every other command is either one that cannot change what a Python workspace does (C++ build
settings, tests, control flow: `HARMLESS`) or one rosx does not carry out: `unsupported` lists
those with their line, so that catkin_make says so instead of ignoring them.
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


class Call(NamedTuple):
    """One command of a ``CMakeLists.txt``: its name (lower case), arguments and line."""

    name: str
    words: list[str]
    line: int


def calls(text: str) -> list[Call]:
    """The commands of the CMake ``text``, in order."""
    stripped = _strip_comments(text)
    found = []
    for match in _COMMAND.finditer(stripped):
        words = [q if q is not None and q != "" else p for q, p in _ARGUMENT.findall(match[2])]
        line = stripped.count("\n", 0, match.start(1)) + 1
        found.append(Call(match[1].lower(), words, line))
    return found


def _commands(text: str) -> list[tuple[str, list[str]]]:
    return [(call.name, call.words) for call in calls(text)]


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


#: Commands rosx reads (above) or whose effect needs nothing of rosx.
READ = frozenset(
    {
        "project",
        "catkin_install_python",
        "install",
        "add_executable",
        "add_library",
        "add_message_files",
        "add_service_files",
        "add_action_files",
        "generate_messages",
        "catkin_python_setup",
    }
)

#: Commands that cannot change what a workspace of Python nodes and types does: finding
#: dependencies and declaring the package, C++ compiling and linking (rosx compiles none),
#: tests (catkin_make builds none), variables, messages and control flow.
HARMLESS = frozenset(
    {
        "cmake_minimum_required", "cmake_policy", "find_package", "catkin_package",
        "catkin_metapackage", "catkin_destinations", "include_directories", "link_directories",
        "target_link_libraries", "add_dependencies", "target_include_directories",
        "target_compile_options", "target_compile_definitions", "target_compile_features",
        "set_target_properties", "set_property", "add_compile_options", "add_definitions",
        "set", "unset", "list", "string", "math", "option", "message", "include",
        "find_library", "find_path", "find_program", "pkg_check_modules",
        "if", "elseif", "else", "endif", "foreach", "endforeach", "while", "endwhile",
        "catkin_add_gtest", "catkin_add_nosetests", "catkin_add_executable_with_gtest",
        "add_rostest", "add_rostest_gtest", "catkin_download_test_data", "roslint_cpp",
        "roslint_python", "roslint_add_test", "roslaunch_add_file_check",
    }
)  # fmt: skip

#: Why some common commands are not carried out, and what it means for the user.
_REASONS = {
    "add_subdirectory": "rosx reads no CMakeLists.txt but the package's own: what {0}/ adds is "
    "not built",
    "generate_dynamic_reconfigure_options": "rosx generates no dynamic_reconfigure config modules",
}

#: The folder each kind of type file is read from; rosx's type store looks nowhere else.
TYPE_FOLDERS = {
    "add_message_files": "msg",
    "add_service_files": "srv",
    "add_action_files": "action",
}


def unsupported(text: str) -> list[tuple[Call, str]]:
    """The commands of ``text`` that rosx does not carry out, each with what that means."""
    found = []
    for call in calls(text):
        if call.name in READ or call.name in HARMLESS:
            continue
        reason = _REASONS.get(call.name, "rosx does not run this command")
        found.append((call, reason.format(*call.words, "", "")))
    return found


class TypeFiles(NamedTuple):
    """One ``add_message_files``/``add_service_files``/``add_action_files`` call: the folder,
    and the files it names (None: every file of the kind in the folder)."""

    call: Call
    directory: str
    files: list[str] | None


def type_files(text: str) -> list[TypeFiles]:
    """The type file declarations of ``text``, in order."""
    found = []
    for call in calls(text):
        if call.name not in TYPE_FOLDERS:
            continue
        directory = TYPE_FOLDERS[call.name]
        files: list[str] | None = None
        words = call.words
        for index, word in enumerate(words):
            if word == "DIRECTORY" and index + 1 < len(words):
                directory = words[index + 1]
            elif word == "FILES":
                files = []
                for name in words[index + 1 :]:
                    if name in ("DIRECTORY", "BASE_DIR", "NOINSTALL", "SKIP_CHECK"):
                        break
                    files.append(name)
        found.append(TypeFiles(call, directory, files))
    return found


__all__ = [
    "HARMLESS",
    "READ",
    "TYPE_FOLDERS",
    "Call",
    "InstallRule",
    "TypeFiles",
    "calls",
    "cpp_targets",
    "destinations",
    "install_rules",
    "type_files",
    "unsupported",
]
