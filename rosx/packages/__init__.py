"""The package index: layer 1b of rosx, below the message system.

- `crawl`: ``ROS_PACKAGE_PATH`` crawled as rospack crawls it, and the package directories
  shipped with rosx (``noetic/share/``: Noetic's core packages, the standard messages, the
  tutorials' packages; and turtlesim's).
- `manifest`: ``package.xml``, read and checked as catkin does.
- `index`: rospack's view of the packages (find, list, depends): the one package index, used by
  the type store (`rosx.msg.store`, for ``msg/`` and ``srv/`` folders), ``rospack``, ``rosrun``,
  ``roscd`` and catkin_make.
- `cache`: the index's crawl kept under ``ROS_HOME``, never stale; `kept`: that file read and
  checked with ``os`` alone, and `bundled`: rosx's own packages found so, for what must answer
  at once (a shell's <TAB>, ``rospack list`` and ``find``).

Finding packages is pure filesystem work, needed by the message layer (a package's types) and by
the workspace layer (rospack, rosrun, roscd), so it lives below both; creating and building
packages stays in `rosx.workspace`. The index does not know which packages the message layer
provides without a directory (``std_msgs``…); a caller that needs it passes that test in
(``PackageIndex(..., provides=...)``). This package imports nothing of rosx.
"""
