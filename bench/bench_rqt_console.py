"""rosx rqt_console with 100 000 entries: adding them, applying a filter, memory, the screen.

Entries are made up as turtlesim and a few other nodes log them (seeded): five severities,
eight nodes, messages of 30-90 characters, four topics each. Printed:

* *ingest*: `Log.add` of the 100 000 entries in batches of 1 000 (what the screen does ten
  times a second), no rule in force;
* *filter*: `Log.set_rules` re-checking every entry, for one rule of each kind the screen
  offers (a severity, a node regex, a text regex, a topic regex) and for three rules at once;
* *memory*: what the 100 000 entries and the shown rows hold (tracemalloc's peak while they
  are built, and what stays allocated after);
* *screen*: the app (`make_console_app`) headless at 120x40 holding them: time from a rule
  added to the screen idle again (rows drawn), and ``end`` / ``home`` keys until handled;
* *DataTable*: textual's own ``DataTable`` given the same rows (``add_rows``), for 10 000 and
  100 000 entries, to show why the table draws only what is on screen. ``--no-datatable`` skips
  it.

rqt_console itself (Qt) is not installable here; its freezes past 20 000 entries are reported
in rqt_common_plugins#132.

    python bench/bench_rqt_console.py [--entries 100000] [--no-datatable]
"""

from __future__ import annotations

import argparse
import asyncio
import gc
import random
import time
import tracemalloc
from typing import Any

from rosx_commands.rqt_console.app import make_console_app
from rosx_commands.rqt_console.model import Entry, Kind, Log, Rule, Rules
from rosx_commands.rqt_console.source import Inbox

NODES = [f"/node_{i}" for i in range(6)] + ["/turtlesim", "/teleop_turtle"]
TOPICS = ("/rosout", "/turtle1/pose", "/turtle1/color_sensor", "/turtle1/cmd_vel")
WORDS = [
    "turtle",
    "wall",
    "pose",
    "velocity",
    "spawn",
    "clamp",
    "reset",
    "pen",
    "colour",
    "service",
    "timer",
    "frame",
]


def entries(count: int, seed: int = 1) -> list[Entry]:
    rng = random.Random(seed)
    made = []
    for i in range(count):
        words = rng.choices(WORDS, k=rng.randint(4, 12))
        made.append(
            Entry(
                1_700_000_000 + i / 1000,
                rng.choice((1, 2, 2, 2, 4, 8, 16)),
                rng.choice(NODES),
                f"{' '.join(words)} #{i}",
                TOPICS,
                f"file_{i % 50}.py:function:{i % 400}",
            )
        )
    return made


def timed(action: Any, repeat: int = 5) -> float:
    """The median wall time of ``action()`` over ``repeat`` runs, in seconds."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        action()
        times.append(time.perf_counter() - start)
    return sorted(times)[len(times) // 2]


def model(count: int) -> None:
    made = entries(count)
    log = Log(count)

    def ingest() -> None:
        log.clear()
        for start in range(0, count, 1000):
            log.add(made[start : start + 1000])

    print(f"ingest {count} entries in batches of 1000: {timed(ingest) * 1e3:.0f} ms")
    for text in (
        "severity:warn+",
        "node:^/turtlesim$",
        "text:wall.*clamp",
        "topic:cmd_vel",
    ):
        rules = Rules().with_rule(Rule.parse(Kind.INCLUDE, text))
        seconds = timed(lambda rules=rules: log.set_rules(rules))
        print(f"filter include {text:20} {seconds * 1e3:6.1f} ms, {log.shown_count} shown")
    rules = (
        Rules()
        .with_rule(Rule.parse(Kind.INCLUDE, "severity:info+"))
        .with_rule(Rule.parse(Kind.EXCLUDE, "node:_[0-3]$"))
        .with_rule(Rule.parse(Kind.EXCLUDE, "text:reset|pen"))
    )
    seconds = timed(lambda: log.set_rules(rules))
    print(f"filter three rules               {seconds * 1e3:6.1f} ms, {log.shown_count} shown")


def memory(count: int) -> None:
    gc.collect()
    tracemalloc.start()
    made = entries(count)
    log = Log(count)
    log.add(made)
    del made
    current, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    print(f"memory, {count} entries kept and shown: {current / 2**20:.1f} MiB held,")
    print(f"  peak {peak / 2**20:.1f} MiB while made ({current / count:.0f} bytes an entry)")
    del log


class Fixed:
    def __init__(self, made: list[Entry]) -> None:
        self.inbox = Inbox(len(made))
        for entry in made:
            self.inbox.put(entry)

    def start(self) -> str:
        return "bench"

    def close(self) -> None:
        pass


async def screen(count: int) -> None:
    app = make_console_app(Fixed(entries(count)), limit=count, period=None)
    async with app.run_test(size=(120, 40)) as pilot:
        start = time.perf_counter()
        app.pane.ingest()
        await pilot.pause()
        await app.animator.wait_until_complete()
        print(f"screen: {count} entries in and drawn: {(time.perf_counter() - start) * 1e3:.0f} ms")
        for text in ("severity:warn+", "text:wall.*clamp", "node:/turtlesim"):
            start = time.perf_counter()
            app.pane.add_rule(Rule.parse(Kind.INCLUDE, text))
            await pilot.pause()
            shown = app.pane.entries.shown_count
            print(
                f"screen: rule {text:18} to rows drawn: "
                f"{(time.perf_counter() - start) * 1e3:5.0f} ms, {shown} shown"
            )
            app.pane.action_clear_rules()
            await pilot.pause()
        for key in ("home", "end", "pagedown"):
            start = time.perf_counter()
            await pilot.press(key)
            print(
                f"screen: {key:8} round trip (pilot's own waits included): "
                f"{(time.perf_counter() - start) * 1e3:.0f} ms"
            )


async def datatable(count: int) -> None:
    from textual.app import App
    from textual.widgets import DataTable

    class TableApp(App[None]):
        def compose(self) -> Any:
            yield DataTable()

    rows = [
        (str(e.stamp), e.severity, e.node, e.message, ", ".join(e.topics), e.location)
        for e in entries(count)
    ]
    app = TableApp()
    async with app.run_test(size=(120, 40)) as pilot:
        table = app.query_one(DataTable)
        table.add_columns("Time", "Severity", "Node", "Message", "Topics", "Location")
        start = time.perf_counter()
        table.add_rows(rows)
        await pilot.pause()
        filled = time.perf_counter() - start
        start = time.perf_counter()
        table.clear()
        table.add_rows(rows[::5])
        await pilot.pause()
        refilled = time.perf_counter() - start
        print(
            f"DataTable: {count} rows added and drawn {filled * 1e3:.0f} ms; "
            f"cleared and refilled with a fifth {refilled * 1e3:.0f} ms"
        )


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--entries", type=int, default=100_000)
    parser.add_argument("--no-datatable", action="store_true")
    args = parser.parse_args()
    model(args.entries)
    memory(args.entries)
    asyncio.run(screen(args.entries))
    if not args.no_datatable:
        for count in (10_000, args.entries):
            asyncio.run(datatable(count))


if __name__ == "__main__":
    main()
