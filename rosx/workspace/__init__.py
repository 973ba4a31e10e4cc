"""Catkin-style workspaces and packages: layer 7 of rosx.

- `create`: ``catkin_create_pkg`` (with catkin_pkg's ``templates/``).
- `build`, `types`, `errors`: ``catkin_make``: packages found, types built, ``devel/`` written.
- `shell`: what ``rosx shell-init`` prints (``roscd``, ``rosls``, ROS 1's command names) and
  the setup files.
- `path_commands`: ROS 1's command names as small programs on ``PATH``, for ``rosx shell-init``.
- `executables`: how ``rosrun`` finds a package's executable.
- `locate`: where ``roscd`` goes.

Finding packages (``ROS_PACKAGE_PATH``, ``package.xml``, rospack's find/list/depends) is the
package index, `rosx.packages`, below the message layer so that the type store uses it too.

This package imports `rosx.packages` and `rosx.msg` (for the type store), nothing above them.
"""
