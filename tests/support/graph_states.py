"""Synthetic graph states: Lab 1's turtlesim world, with and without bus info."""

from __future__ import annotations

from rosx.graph.state import BusLink, GraphState

PUBS = {
    "/turtle1/cmd_vel": ("/teleop_turtle",),
    "/turtle1/pose": ("/turtlesim",),
    "/turtle1/color_sensor": ("/turtlesim",),
    "/rosout": ("/turtlesim", "/teleop_turtle"),
    "/rosout_agg": ("/rosout",),
}
SUBS = {"/turtle1/cmd_vel": ("/turtlesim",), "/rosout": ("/rosout",)}
URIS = {
    "/teleop_turtle": "http://h:1/",
    "/turtlesim": "http://h:2/",
    "/rosout": "http://h:3/",
}


def lab1(*, teleop_connected: bool = True) -> GraphState:
    """Lab 1 with bus info; the teleop's connection to turtlesim is live or not."""
    cmd = (BusLink("/turtle1/cmd_vel", "/turtlesim", "o"),) if teleop_connected else ()
    cmd_in = (BusLink("/turtle1/cmd_vel", "http://h:1/", "i"),) if teleop_connected else ()
    return GraphState(
        PUBS,
        SUBS,
        {},
        {"/turtle1/cmd_vel": "geometry_msgs/Twist"},
        URIS,
        {
            "/teleop_turtle": (*cmd, BusLink("/rosout", "/rosout", "o")),
            "/turtlesim": (*cmd_in, BusLink("/rosout", "/rosout", "o")),
            "/rosout": (BusLink("/rosout", "http://h:1/", "i"),),
        },
    )
