"""Catkin-style workspaces and packages: layer 7 of rosx.

- `manifest`: ``package.xml``, read and checked as catkin does.
- `create`: ``catkin_create_pkg`` (with catkin_pkg's ``templates/``).
- `build`, `types`, `errors`: ``catkin_make``: packages found, types built, ``devel/`` written.
- `shell`: the shell functions (``roscd``, ``rosls``, ROS 1's command names) and setup files.
- `index`: ``rospack``'s view of the packages: find, list, depends.
- `executables`: how ``rosrun`` finds a package's executable.
- `locate`: where ``roscd`` goes.

This package imports `rosx.msg` (for the type store and the package crawl), nothing above it.
"""
