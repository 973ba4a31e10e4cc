"""rosx rqt_graph's refresh on a large graph: fetch, build, lay out and draw.

An in-process master (`rosx.master.server.MasterThread`) holds N nodes (default 200) and T
topics (default 500): each topic has one publisher and two subscribers, picked at random
(seeded). Node URIs name closed ports, so the nodes' bus info is not asked (``--no-bus-info``'s
path). Prints, per mode, the wall time of each step of a refresh: *first* (nothing cached),
*relaid* (the layering cached, the drawing made again: what a refresh costs when only a
vertex's looks changed), *same* (`draw`'s cache: the graph did not change), then the peak
memory of a first refresh (under tracemalloc, which slows it).

    python bench/bench_rqt_graph.py [--nodes 200] [--topics 500]
"""

from __future__ import annotations

import argparse
import random
import time
import tracemalloc

from rosx.graph import layout, text
from rosx.graph.builder import build
from rosx.graph.fetch import fetch_state
from rosx.graph.layout import layered
from rosx.graph.options import GraphOptions, Mode
from rosx.graph.text import draw, render, with_label_vertices
from rosx.master.server import MasterThread
from rosx.transport.client import XmlRpcClient


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


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--nodes", type=int, default=200)
    parser.add_argument("--topics", type=int, default=500)
    args = parser.parse_args()
    master = MasterThread()
    uri = master.start()
    try:
        populate(uri, args.nodes, args.topics)
        for mode in (Mode.NODES, Mode.ALL):
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
                if refresh == "relaid":
                    draw(graph)  # fills draw's cache for the next refresh
        clear_caches()
        for mode in (Mode.NODES, Mode.ALL):
            tracemalloc.start()
            draw(build(fetch_state(uri, "/bench", bus_info=False), GraphOptions(mode=mode)))
            _, peak = tracemalloc.get_traced_memory()
            tracemalloc.stop()
            print(f"{mode.caption:19} peak memory of a refresh: {peak / 2**20:.1f} MiB")
    finally:
        master.close()


if __name__ == "__main__":
    main()
