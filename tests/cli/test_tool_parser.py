"""`ToolParser` answers without optparse when no option is given, exactly as optparse would."""

from __future__ import annotations

import io

import pytest

from rosx_commands.cli import ToolParser
from rosx_commands.context import CommandError, Environment


def _parser() -> ToolParser:
    parser = ToolParser(Environment(stdout=io.StringIO(), environ={}), "rostool", "usage: %prog x")
    parser.add_option("-v", dest="verbose", default=False, action="store_true", help="verbose")
    parser.add_option("-p", "--plot", action="store_true", help="no dest, no default")
    parser.add_option("--sigint-timeout", type="float", default=15.0, help="derived dest")
    parser.add_option("-n", dest="count", default=None, help="count")
    parser.add_option("-w", "--window", dest="window", default=-1, help="window")
    parser.add_option("-c", help="a short flag alone")
    parser.add_option("--split", action="callback", callback=lambda *_: None, help="no dest")
    parser.add_option("-q", dest="window", action="store_const", const=0, help="shares a dest")
    return parser


@pytest.mark.parametrize("argv", [[], ["/"], ["/a", "b:=c", "1"]])
def test_words_alone_get_optparse_defaults(argv: list[str]) -> None:
    options, args = _parser().parse(argv)
    expected, expected_args = _parser().optparse().parse_args(argv)
    assert vars(options) == vars(expected)
    assert args == expected_args == argv


@pytest.mark.parametrize(
    ("argv", "attribute", "value"),
    [(["-v", "/x"], "verbose", True), (["--sigint-timeout", "2", "/x"], "sigint_timeout", 2.0)],
)
def test_options_go_through_optparse(argv: list[str], attribute: str, value: object) -> None:
    options, args = _parser().parse(argv)
    assert getattr(options, attribute) == value
    assert args == ["/x"]


def test_string_default_of_a_typed_option_is_converted_as_optparse_does() -> None:
    parser = ToolParser(Environment(environ={}), "rostool", "usage: %prog x")
    parser.add_option("--rate", dest="rate", type="float", default="2.5")
    options, _ = parser.parse(["/x"])
    assert options.rate == 2.5


def test_errors_are_optparse_usage_errors() -> None:
    parser = _parser()
    parser.description = "Described."
    with pytest.raises(CommandError) as raised:
        parser.error("too many arguments")
    assert raised.value.message == "Usage: rostool x\n\nrostool: error: too many arguments"
    assert raised.value.status == 2
