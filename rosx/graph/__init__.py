"""The ROS graph as rqt_graph draws it: state, view model, filters, layout, text and DOT.

`state` holds what the master and the nodes say (``getSystemState``, ``getBusInfo``);
`builder` turns it into a `view.ViewGraph` under rqt_graph's modes, filters and hide rules
(`options`); `layout` places it left to right; `text` and `dot` draw it. Only `fetch` talks
to the network; nothing here imports a terminal UI.
"""
