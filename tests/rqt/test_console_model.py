"""rqt_console's entries and rules: what is shown, highlighted, folded and kept."""

from __future__ import annotations

import pytest

from rosx_commands.rqt_console.model import (
    Entry,
    Kind,
    Log,
    Rule,
    RuleError,
    Rules,
    details,
    location,
)


def entry(message: str, level: int = 2, node: str = "/talker", **extra: object) -> Entry:
    return Entry(1000.5, level, node, message, **extra)  # type: ignore[arg-type]


def test_a_bare_pattern_is_a_regex_on_the_text() -> None:
    rule = Rule.parse(Kind.EXCLUDE, "hit the .*wall")
    assert (rule.subject, rule.pattern) == ("text", "hit the .*wall")
    assert rule.matches(entry("Oh no! I hit the wall! (Clamping from [x=11.1, y=5.5])"))
    assert not rule.matches(entry("Spawning turtle [turtle1]"))


@pytest.mark.parametrize(
    ("text", "levels"),
    [
        ("severity:warn", {4}),
        ("severity:warn+", {4, 8, 16}),
        ("level:-info", {1, 2}),
        ("severity: Error, FATAL", {8, 16}),
    ],
)
def test_severity_rules_name_levels_or_bounds(text: str, levels: set[int]) -> None:
    assert Rule.parse(Kind.INCLUDE, text).levels == levels


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            "severity:loud",
            "unknown severity 'loud': use debug, info, warn, error, fatal, NAME+ or -NAME",
        ),
        ("node:(", "bad regular expression '(': missing ), unterminated subpattern at position 0"),
        ("colour:red", "unknown field 'colour': use one of severity, node, text, topic, location"),
        ("node:", "empty node pattern"),
    ],
)
def test_bad_rules_say_what_is_wrong(text: str, message: str) -> None:
    with pytest.raises(RuleError) as caught:
        Rule.parse(Kind.INCLUDE, text)
    assert str(caught.value) == message


def test_includes_any_of_them_then_excludes_win() -> None:
    rules = (
        Rules()
        .with_rule(Rule.parse(Kind.INCLUDE, "node:^/turtlesim$"))
        .with_rule(Rule.parse(Kind.INCLUDE, "severity:error+"))
        .with_rule(Rule.parse(Kind.EXCLUDE, "text:ignore me"))
        .with_rule(Rule.parse(Kind.HIGHLIGHT, "topic:cmd_vel"))
    )
    assert rules.shows(entry("a", node="/turtlesim"))
    assert rules.shows(entry("b", level=8))
    assert not rules.shows(entry("c"))
    assert not rules.shows(entry("ignore me", node="/turtlesim"))
    assert rules.highlights(entry("d", topics=("/turtle1/cmd_vel",)))
    assert not rules.highlights(entry("d", topics=("/turtle1/pose",)))
    assert [str(r) for r in rules.rules] == [
        "include node:^/turtlesim$",
        "include severity:error+",
        "exclude text:ignore me",
        "highlight topic:cmd_vel",
    ]
    assert rules.without(Kind.INCLUDE).of(Kind.INCLUDE) == ()
    assert rules.without().rules == ()


def test_a_node_appearing_later_is_held_by_an_include_rule() -> None:
    log = Log()
    log.set_rules(Rules().with_rule(Rule.parse(Kind.INCLUDE, "node:/turtlesim")))
    log.add([entry("late", node="/newcomer"), entry("mine", node="/turtlesim")])
    assert [log.shown(i).message for i in range(log.shown_count)] == ["mine"]


def test_a_repeated_record_folds_into_the_row_before() -> None:
    log = Log()
    added = log.add([entry("same"), entry("same"), entry("same", level=4), entry("same")])
    assert added == 3 and len(log) == 3 and log.received == 4
    assert log.shown(0).count == 2
    assert "Severity: Info (2 times)" in details(log.shown(0))


def test_rules_apply_to_the_entries_kept_and_to_those_that_come() -> None:
    log = Log()
    log.add(entry(f"m{i}", level=(1, 2, 4, 8, 16)[i % 5]) for i in range(100))
    log.set_rules(Rules().with_rule(Rule.parse(Kind.EXCLUDE, "severity:-info")))
    assert log.shown_count == 60
    log.add([entry("debug", level=1), entry("warn", level=4)])
    assert log.shown_count == 61 and log.shown(60).message == "warn"
    assert [e.message for e in log.rows(58, 61)] == ["m98", "m99", "warn"]


def test_the_oldest_entries_go_beyond_the_limit() -> None:
    log = Log(limit=100)
    log.set_rules(Rules().with_rule(Rule.parse(Kind.EXCLUDE, "text:odd")))
    log.add(entry("odd" if i % 2 else f"even {i}") for i in range(250))
    assert len(log) <= 100 and log.dropped == 250 - len(log)
    shown = [log.shown(i).message for i in range(log.shown_count)]
    assert shown[-1] == "even 248" and all(m.startswith("even") for m in shown)
    assert len(shown) == len(log) // 2


def test_clear_forgets_entries_but_keeps_rules() -> None:
    log = Log()
    rules = Rules().with_rule(Rule.parse(Kind.EXCLUDE, "x"))
    log.set_rules(rules)
    log.add([entry("a"), entry("b")])
    log.clear()
    assert (len(log), log.shown_count, log.rules) == (0, 0, rules)
    log.add([entry("c"), entry("x")])
    assert [e.message for e in log.rows(0, 5)] == ["c"]


def test_location_is_file_function_line() -> None:
    assert location("turtle_frame.cpp", "updateTurtles", 213) == (
        "turtle_frame.cpp:updateTurtles:213"
    )
    assert location("", "", 0) == ""
