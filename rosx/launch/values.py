"""Parameter values as roslaunch computes them from ``<param>`` and ``<rosparam>``.

* `convert_value`: ``<param type=…>``'s conversions. ``auto`` (the default) makes a float of
  text holding a ``.``, an int of text without ``_`` that Python reads as one, a bool of
  ``true``/``false`` in any case, and a string of anything else; ``str``/``string``, ``int``,
  ``double``, ``bool``/``boolean`` (``true``, ``1``, ``false``, ``0``) and ``yaml``.
* `text_value`, `binary_value`, `command_value`: ``textfile``, ``binfile``, ``command``.
* `load_yaml`: the YAML of a ``<rosparam>`` (rosparam's rules, `rosx.msg.text.yamlparams`), and
  `flatten`, which unrolls dictionaries into one parameter per leaf as roslaunch does.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.names.resolution import ns_join

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator

    #: Runs a command line; returns its exit code and standard output.
    CommandRunner = Callable[[list[str]], tuple[int, str]]


class ValueConversionError(ValueError):
    """A value that cannot be computed; ``str()`` says why (roslaunch's words)."""


def convert_value(value: str, type_: str) -> Any:
    """``value`` converted to ``type_``: ``auto``, ``str``, ``int``, ``double``, ``bool``, ``yaml``.

    Raises:
        ValueConversionError: ``value`` is not of that type, or the type is unknown.
    """
    kind = type_.lower()
    if kind == "auto":
        try:
            if "." in value:
                return float(value)
            if "_" not in value:
                return int(value)
        except ValueError:
            pass
        if value.lower() in ("true", "false"):
            return value.lower() == "true"
        return value
    if kind in ("str", "string"):
        return value
    try:
        if kind == "int":
            return int(value)
        if kind == "double":
            return float(value)
    except ValueError as error:
        raise ValueConversionError(str(error)) from None
    if kind in ("bool", "boolean"):
        text = value.lower().strip()
        if text in ("true", "1"):
            return True
        if text in ("false", "0"):
            return False
        raise ValueConversionError(f"{text} is not a '{kind}' type")
    if kind == "yaml":
        return load_yaml(value, rosparam=False)
    raise ValueConversionError(f"Unknown type '{kind}'")


def text_value(path: str, type_: str) -> Any:
    """``textfile``: the file's text, converted to ``type_``."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        raise ValueConversionError(f"cannot read textfile [{path}]: {_reason(error)}") from None
    return convert_value(text, type_)


def binary_value(path: str) -> bytes:
    """``binfile``: the file's bytes (a binary parameter)."""
    try:
        return Path(path).read_bytes()
    except OSError as error:
        raise ValueConversionError(f"cannot read binfile [{path}]: {_reason(error)}") from None


def command_value(name: str, command: str, type_: str, run: CommandRunner | None) -> Any:
    """``command``: the standard output of the command line (run by ``run``), converted to
    ``type_``; without ``run`` (a plan read for a look only) the parameter is refused."""
    import shlex  # noqa: PLC0415 - shlex is not needed at start-up

    try:
        argv = shlex.split(command)
    except ValueError as error:
        raise ValueConversionError(f"Cannot load command parameter [{name}]: {error}") from None
    if not argv:
        raise ValueConversionError(f"Cannot load command parameter [{name}]: the command is empty")
    if run is None:
        raise ValueConversionError(
            f"Cannot load command parameter [{name}]: commands are not run here [{argv}]"
        )
    try:
        code, output = run(argv)
    except FileNotFoundError:
        raise ValueConversionError(
            f"Cannot load command parameter [{name}]: no such command [{argv}]"
        ) from None
    except OSError as error:
        raise ValueConversionError(
            f"Cannot load command parameter [{name}]: {_reason(error)} [{argv}]"
        ) from None
    if code != 0:
        raise ValueConversionError(
            f"Cannot load command parameter [{name}]: command [{argv}] returned with code [{code}]"
        )
    return convert_value(output, type_)


def load_yaml(text: str, *, rosparam: bool = True) -> Any:
    """One YAML document, as ``yaml.safe_load`` reads it.

    With ``rosparam`` (for ``<rosparam>``), rosparam's additions too: ``!degrees``/``deg()``,
    ``!radians``/``rad()``. Without (for ``<param type="yaml">``), plain YAML, as roslaunch
    reads it when it has not loaded rosparam: ``deg(180)`` stays a string.

    Raises:
        ValueConversionError: The text is not YAML (PyYAML's description of the problem).
    """
    from rosx.msg.text.yamlload import load  # noqa: PLC0415 - the text forms load on first use
    from rosx.msg.text.yamlparams import load_value  # noqa: PLC0415 - the text forms load on first use

    try:
        return load_value(text) if rosparam else load(text)
    except ValueError as error:
        raise ValueConversionError(_one_line(str(error))) from None


def _one_line(description: str) -> str:
    # PyYAML's description quotes the offending lines with a caret below; the words and the
    # positions say it on one line.
    words = [
        line.strip()
        for line in description.splitlines()
        if line.strip() and not line.startswith("    ") and line.strip() != "^"
    ]
    return " ".join(words).replace('in "<unicode string>", ', "at ").rstrip(":")


def flatten(name: str, value: Any) -> Iterator[tuple[str, Any]]:
    """``(name, value)`` pairs of the parameters a ``<rosparam>`` value sets.

    Dictionaries are unrolled (an empty one sets nothing); keys join ``name`` as ROS names do
    (a global or ``~`` key stands on its own).
    """
    if isinstance(value, dict):
        for key, item in value.items():
            if not isinstance(key, str):
                raise ValueConversionError(
                    f"YAML dictionaries must have string keys. Invalid dictionary is: {value}"
                )
            yield from flatten(ns_join(name, key), item)
    else:
        yield name, value


def _reason(error: OSError | UnicodeDecodeError) -> str:
    if isinstance(error, OSError) and error.strerror:
        return error.strerror
    return str(error)


__all__ = [
    "ValueConversionError",
    "binary_value",
    "command_value",
    "convert_value",
    "flatten",
    "load_yaml",
    "text_value",
]
