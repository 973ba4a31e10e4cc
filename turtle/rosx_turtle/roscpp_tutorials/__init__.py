"""roscpp_tutorials' nodes, in Python, as their C++ originals behave on the ROS graph.

- `chatter`: ``talker`` (``hello world <n>`` on ``chatter`` at 10 Hz) and ``listener``
  (``I heard: [<text>]``);
- `add_two_ints`: ``add_two_ints_server`` (service ``add_two_ints``, roscpp_tutorials/TwoInts)
  and ``add_two_ints_client X Y``.

Each prints roscpp's console lines (`rosx_turtle.console`) and takes roscpp's remapping
arguments (`rosx_turtle.roscpp`); ``rosrun roscpp_tutorials <name>`` runs them
(from their files in rosx's ``lib/roscpp_tutorials``).
"""
