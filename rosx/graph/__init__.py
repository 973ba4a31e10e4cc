"""The ROS graph as the tools describe it and rqt_graph draws it.

`state` holds what the master and the nodes say (``getSystemState``, ``getBusInfo``), read by
`fetch`; `describe` says what ``rosnode info`` and ``rostopic info`` print of one node or topic
and summarises a state for ``rosx sim``'s panels; `builder` turns a state into a
`view.ViewGraph` under rqt_graph's modes, filters and hide rules (`options`); `layout` places
it left to right; `text` and `dot` draw it. Only `fetch` and `describe` talk to the network,
through `rosx.master.client`; nothing here imports a terminal UI.
"""
