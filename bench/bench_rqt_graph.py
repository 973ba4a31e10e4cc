"""rosx rqt_graph's refresh on a large graph: fetch, build, lay out and draw.

An in-process master (`rosx.master.server.MasterThread`) holds N nodes (default 200) and T
topics (default 500): each topic has one publisher and two subscribers, picked at random
(seeded). Node URIs name closed ports, so the nodes' bus info is not asked (``--no-bus-info``'s
path). Prints, per mode, the wall time of each step of a refresh: *first* (nothing cached),
*relaid* (the layering cached, the drawing made again: what a refresh costs when only a
vertex's looks changed), *same* (`draw`'s cache: the graph did not change), then the peak
memory of a first refresh (under tracemalloc, which slows it).

Then two more sections:

*Side by side with rqt_graph's layout engine.* ROS 1's rqt_graph is a Qt GUI (not installable
here), but on a refresh it writes the graph as DOT and lays it out with Graphviz ``dot``
(through pydot, format xdot). For each mode, rosx's DOT of the same graph, in rqt_graph's shape
(`rosx.graph.dot.dot`, namespace clusters as rqt_graph groups them), is piped to
``dot -Txdot``; if that fails, the graph without clusters is tried too. Each run is stopped
(killed) after ``--dot-timeout`` seconds. Printed: graphviz's wall time (process start
included, as pydot starts it; pydot's parsing of the xdot and Qt's scene are not counted),
rosx's layout+draw of a first refresh, and the ratio rosx / graphviz. Skipped when ``dot`` is
not on PATH.

*Does the live view freeze during a refresh?* The textual app (`make_graph_app`) is driven
headless (160x50) on a source that hands it the graph fetched once, with rosx's caches
cleared, so its refresh on mount is a first one, run on a worker thread. Meanwhile a task on
the app's event loop sleeps 10 ms at a time and records the gaps between its wake-ups (a
gap well over 10 ms is a stall: the UI could not react), and ``down`` is sent every 50 ms,
each timed until the widget it goes to has handled it (`key_handled`). Printed: when the app
was ready and when the drawing was shown (``app.drawing.boxes`` non-empty); the median and
worst wake-up gap in between, split into the gap in which the worker handed the drawing to
the UI thread and the worst of the others (the worker thread holding the GIL); the keys'
handling times; the time and worst gap from then until the app is idle (the drawing painted);
then, with the graph view ``#graph`` focused, ten ``right`` keys that scroll it, timed until
handled and, separately, as ``await pilot.press`` round trips (which add pilot's own waits
for the screen and for the process to go idle: 40 ms at least).

    python bench/bench_rqt_graph.py [--nodes 200] [--topics 500] [--dot-timeout 60]
"""

from __future__ import annotations

import argparse
import asyncio
import random
import shutil
import statistics
import subprocess
import sys
import time
import tracemalloc
from dataclasses import dataclass, field
from typing import Any

from rosx.graph import layout, text
from rosx.graph.builder import build
from rosx.graph.dot import dot
from rosx.graph.fetch import fetch_state
from rosx.graph.layout import layered
from rosx.graph.options import GraphOptions, Mode
from rosx.graph.state import GraphState
from rosx.graph.text import draw, render, with_label_vertices
from rosx.graph.view import Vertex, ViewGraph
from rosx.master.server import MasterThread
from rosx.transport.client import XmlRpcClient

MODES = (Mode.NODES, Mode.ALL)
#: The live view's probe: the sleep between two wake-ups of the watching task, in seconds.
TICK = 0.010
#: The live view's probe: the pause between two key presses during the refresh, in seconds.
PRESS_EVERY = 0.050
SCROLL_PRESSES = 10


def populate(uri: str, nodes: int, topics: int) -> None:
    rng = random.Random(7)
    names = [f"/ns{i % 10}/node{i}" for i in range(nodes)]
    with XmlRpcClient() as client:
        for t in range(topics):
            topic = f"/ns{t % 10}/topic{t}"
            pub, *subs = rng.sample(range(nodes), 3)
            api = f"http://127.0.0.2:{1 + pub}/"
            client.call(uri, "registerPublisher", names[pub], topic, "std_msgs/String", api)
            for sub in subs:
                api = f"http://127.0.0.2:{1 + sub}/"
                client.call(uri, "registerSubscriber", names[sub], topic, "std_msgs/String", api)


def clear_caches() -> None:
    layout._cache.clear()
    text._cache.clear()


def ms(seconds: float) -> str:
    return f"{1000 * seconds:7.1f} ms"


# -- rosx's refresh, step by step ------------------------------------------------------------


def bench_refresh(uri: str) -> dict[Mode, tuple[ViewGraph, float]]:
    """The step table; returns each mode's graph and its first refresh's layout+draw time."""
    firsts: dict[Mode, tuple[ViewGraph, float]] = {}
    for mode in MODES:
        for refresh in ("first", "relaid", "same"):
            t0 = time.perf_counter()
            state = fetch_state(uri, "/bench", bus_info=False)
            t1 = time.perf_counter()
            graph = build(state, GraphOptions(mode=mode))
            t2 = time.perf_counter()
            if refresh == "same":
                t3 = t2
                drawing = draw(graph)
            else:
                split = with_label_vertices(graph)
                layering = layered(split)
                t3 = time.perf_counter()
                drawing = render(split, layering)
            t4 = time.perf_counter()
            print(
                f"{mode.caption:19} {refresh:6} {len(graph.vertices):4} vertices"
                f" {len(graph.edges):5} edges | fetch {1000 * (t1 - t0):5.1f} ms"
                f"  build {1000 * (t2 - t1):5.1f} ms  layout {1000 * (t3 - t2):6.1f} ms"
                f"  draw {1000 * (t4 - t3):5.1f} ms | total {1000 * (t4 - t0):6.1f} ms |"
                f" {max(map(len, drawing.lines))}x{len(drawing.lines)} chars"
            )
            if refresh == "first":
                firsts[mode] = (graph, t4 - t2)
            if refresh == "relaid":
                draw(graph)  # fills draw's cache for the next refresh
    return firsts


def bench_memory(uri: str) -> None:
    clear_caches()
    for mode in MODES:
        tracemalloc.start()
        draw(build(fetch_state(uri, "/bench", bus_info=False), GraphOptions(mode=mode)))
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        print(f"{mode.caption:19} peak memory of a refresh: {peak / 2**20:.1f} MiB")


# -- side by side with rqt_graph's layout engine ---------------------------------------------


@dataclass
class DotRun:
    seconds: float
    timed_out: bool = False
    error: str | None = None  # the first line graphviz wrote to stderr, when it failed
    output_bytes: int = 0


def run_dot(exe: str, source: str, timeout: float) -> DotRun:
    """``dot -Txdot`` on ``source``: its wall time; killed after ``timeout`` seconds."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(
        [exe, "-Txdot"],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    try:
        try:
            out, err = proc.communicate(source.encode(), timeout=timeout)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
            return DotRun(time.perf_counter() - t0, timed_out=True)
        seconds = time.perf_counter() - t0
        if proc.returncode != 0:
            lines = [line for line in err.decode(errors="replace").splitlines() if line.strip()]
            first = lines[0] if lines else f"exit status {proc.returncode}"
            return DotRun(seconds, error=first)
        return DotRun(seconds, output_bytes=len(out))
    finally:
        if proc.poll() is None:  # an error or ^C while waiting: never leave dot running
            proc.kill()
            proc.wait()


def bench_graphviz(firsts: dict[Mode, tuple[ViewGraph, float]], timeout: float) -> None:
    print()
    exe = shutil.which("dot")
    if exe is None:
        print(
            "== Side by side with rqt_graph's layout engine: skipped (graphviz `dot` not on PATH)"
        )
        return
    version = subprocess.run(
        [exe, "-V"], capture_output=True, text=True, timeout=30, check=False
    ).stderr.strip()
    print(f"== Side by side with rqt_graph's layout engine: {exe} -Txdot ({version})")
    print(
        "   rosx: layout+draw of a first refresh (step table above); graphviz: wall time of"
        f" `dot -Txdot` on the same graph's DOT; stopped after {timeout:g} s"
    )
    for mode in MODES:
        graph, rosx_seconds = firsts[mode]
        for grouped in (True, False):
            source = dot(graph, grouped=grouped)
            run = run_dot(exe, source, timeout)
            shape = "namespace clusters" if grouped else "no clusters"
            line = (
                f"{mode.caption:19} {shape:18} ({source.count(chr(10)):5} DOT lines)"
                f" | rosx {ms(rosx_seconds)} | graphviz "
            )
            if run.timed_out:
                line += f"> {timeout:g} s (stopped) | rosx/graphviz < {rosx_seconds / timeout:.3f}"
            elif run.error is not None:
                line += f"{ms(run.seconds)} | graphviz failed: {run.error}"
            else:
                line += (
                    f"{ms(run.seconds)} | rosx/graphviz {rosx_seconds / run.seconds:6.2f}"
                    f" | xdot {run.output_bytes / 1024:.0f} KiB"
                )
            print(line)
            if run.error is None:
                break  # rqt_graph's graph laid out (or given up on): no need for the fallback


# -- does the live view freeze during a refresh? ---------------------------------------------


class FixedSource:
    """The live view's `GraphSource`: one graph, fetched up front; no network afterwards."""

    def __init__(self, state: GraphState) -> None:
        self.state = state

    def snapshot(self) -> GraphState:
        return self.state

    def describe(self, vertex: Vertex) -> str:
        return f"{vertex.kind}: {vertex.label}"

    def rate(self, topic: str) -> str:
        return "average rate: 10.000 Hz"

    def close(self) -> None:
        pass


@dataclass
class LoopWatch:
    """Wakes every `TICK` on the app's event loop; records each wake-up and the gap before it."""

    app: Any
    wakes: list[tuple[float, float]] = field(default_factory=list)
    shown_at: float | None = None

    async def run(self) -> None:
        last = time.perf_counter()
        while True:
            await asyncio.sleep(TICK)
            now = time.perf_counter()
            self.wakes.append((now, now - last))
            last = now
            if self.shown_at is None and self.app.drawing.boxes:
                self.shown_at = now

    def gaps(self, start: float, end: float) -> list[float]:
        """Gaps of the wake-ups in ``(start, end]``."""
        return [gap for at, gap in self.wakes if start < at <= end]


def spread(values: list[float]) -> str:
    if not values:
        return "none"
    return f"n={len(values):3}  median {ms(statistics.median(values))}  worst {ms(max(values))}"


async def key_handled(app: Any, key: str) -> float:
    """Seconds from posting ``key`` to the app until the widget it goes to has handled it.

    The app handles the key (its bindings, else it forwards the key to the focused widget's
    queue) before the callback queued behind it; that callback queues a second one behind the
    forwarded key on the focused widget: when the second runs, the key has been handled.
    `pilot.press` is not used for this: it also waits for the process's CPU time to stop
    advancing, up to 1 s, which never happens while the refresh's thread works.
    """
    from textual import events

    done: asyncio.Future[float] = asyncio.get_running_loop().create_future()

    def finish() -> None:
        if not done.done():
            done.set_result(time.perf_counter())

    t0 = time.perf_counter()
    app.post_message(events.Key(key, None))
    app.call_later(lambda: (app.focused or app.screen).call_later(finish))
    while not done.done():
        await asyncio.wait({done}, timeout=0.5)
        if not app.is_running:  # the app failed (run_test will raise its error)
            return float("nan")
    return done.result() - t0


async def drive_live_view(state: GraphState, mode: Mode) -> None:
    from rosx_commands.rqt_graph.app import make_graph_app

    clear_caches()  # the app's refresh on mount is a first one
    app = make_graph_app(FixedSource(state), GraphOptions(mode=mode), period=None)
    watch = LoopWatch(app)
    t0 = time.perf_counter()
    watcher = asyncio.create_task(watch.run())
    keys: list[float] = []
    try:
        async with app.run_test(size=(160, 50)) as pilot:
            ready = time.perf_counter()
            while not app.drawing.boxes and time.perf_counter() - t0 < 600:
                keys.append(await key_handled(app, "down"))
                await asyncio.sleep(PRESS_EVERY)
            await app.workers.wait_for_complete()
            await pilot.pause()
            settled = time.perf_counter()
            shown = watch.shown_at or settled
            view = app.query_one("#graph")
            view.focus()
            await pilot.pause()
            x0 = view.scroll_x
            handled = [await key_handled(app, "right") for _ in range(SCROLL_PRESSES)]
            await pilot.pause()
            x1 = view.scroll_x
            presses = []
            for _ in range(SCROLL_PRESSES):
                p0 = time.perf_counter()
                await pilot.press("right")
                presses.append(time.perf_counter() - p0)
            x2 = view.scroll_x
            boxes = len(app.drawing.boxes)
    finally:
        watcher.cancel()
    during = watch.gaps(ready, shown)
    after = watch.gaps(shown, settled)
    print(f"{mode.caption}: {boxes} boxes")
    print(
        f"  app ready (first screen) after  {ms(ready - t0)}  (startup worst gap"
        f" {ms(max(watch.gaps(t0, ready), default=0.0))})"
    )
    print(f"  drawing shown after             {ms(shown - t0)}")
    print(f"  loop wake-up gaps, ready..shown {spread(during)}  (nominal {TICK * 1000:g} ms)")
    if watch.shown_at is not None and watch.shown_at > ready:
        # the wake-up that first saw the drawing: its gap holds the hand-over on the UI thread
        handover = watch.gaps(watch.shown_at - 1e-9, watch.shown_at)
        others = watch.gaps(ready, watch.shown_at - 1e-9)
        print(
            f"    of which the hand-over gap    {ms(handover[0])}; worst other gap"
            f" {ms(max(others, default=0.0))}"
        )
    print(f"  'down' handled, meanwhile       {spread(keys)}")
    print(
        f"  shown..settled (painted)        {ms(settled - shown)}, worst gap"
        f" {ms(max(after, default=0.0))}"
    )
    print(
        f"  'right' on #graph: handled      {spread(handled)}"
        f"  (scroll_x {x0:g} -> {x1:g} -> {x2:g})"
    )
    print(f"  'right' on #graph: pilot.press  {spread(presses)}")


def bench_live_view(uri: str) -> None:
    print()
    print(
        "== Does the live view freeze during a refresh? (textual headless 160x50, first refresh"
        f" on a worker thread, GIL switch interval {sys.getswitchinterval() * 1000:g} ms)"
    )
    state = fetch_state(uri, "/bench", bus_info=False)
    for mode in MODES:
        asyncio.run(drive_live_view(state, mode))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--nodes", type=int, default=200)
    parser.add_argument("--topics", type=int, default=500)
    parser.add_argument("--dot-timeout", type=float, default=60.0, metavar="S")
    args = parser.parse_args()
    master = MasterThread()
    uri = master.start()
    try:
        populate(uri, args.nodes, args.topics)
        firsts = bench_refresh(uri)
        bench_memory(uri)
        bench_graphviz(firsts, args.dot_timeout)
        bench_live_view(uri)
    finally:
        master.close()


if __name__ == "__main__":
    main()
