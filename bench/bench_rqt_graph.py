"""rosx rqt_graph's refresh on a large graph: fetch, build, lay out and draw.

An in-process master (`rosx.master.server.MasterThread`) holds N nodes (default 200) and T
topics (default 500): each topic has one publisher and two subscribers, picked at random
(seeded). Node URIs name closed ports, so the nodes' bus info is not asked (``--no-bus-info``'s
path). Prints, per mode, the wall time of each step and the peak memory of one refresh.

    python bench/bench_rqt_graph.py [--nodes 200] [--topics 500]
"""

from __future__ import annotations

import argparse
import random
import time
import tracemalloc

from rosx.graph.builder import build
from rosx.graph.fetch import fetch_state
from rosx.graph.options import GraphOptions, Mode
from rosx.graph.text import draw
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
            tracemalloc.start()
            t0 = time.perf_counter()
            state = fetch_state(uri, "/bench", bus_info=False)
            t1 = time.perf_counter()
            graph = build(state, GraphOptions(mode=mode))
            t2 = time.perf_counter()
            drawing = draw(graph)
            t3 = time.perf_counter()
            _, peak = tracemalloc.get_traced_memory()
            tracemalloc.stop()
            print(
                f"{mode.caption:24} {len(graph.vertices):4} vertices {len(graph.edges):5} edges |"
                f" fetch {1000 * (t1 - t0):6.1f} ms  build {1000 * (t2 - t1):6.1f} ms"
                f"  layout+draw {1000 * (t3 - t2):7.1f} ms |"
                f" drawing {max(map(len, drawing.lines))}x{len(drawing.lines)} chars"
                f" | peak {peak / 2**20:.1f} MiB"
            )
    finally:
        master.close()


if __name__ == "__main__":
    main()
