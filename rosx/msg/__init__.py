"""The message system: layer 2 of rosx, split by job as rosbags splits ``typesys`` from ``serde``.

Here, type definitions and the type store:

- `spec`, `parser`: ``.msg``/``.srv`` text parsed into specs.
- `store`: every type rosx knows (package path, the packages shipped with rosx, rosbags' Noetic
  types via `standard`), found lazily by name; packages come from `rosx.packages.index`.
- `md5`, `describe`: md5 sums, full definitions and ``rosmsg show``'s text of a type.

Subpackages, each importing only what is listed before it:

- `rosx.msg.codec`: generated rospy-style classes and the ROS 1 wire codec (plus `Time` and
  `Duration`).
- `rosx.msg.text`: the text forms: ``rostopic echo`` (plain, CSV, field paths), the YAML
  emulation read and written by rostopic, rosservice and rosparam, and rosparam's rules.

The one import the other way is `rosx.msg.codec.message`'s ``str()`` of a message, which loads
`rosx.msg.text.echo` on first use (a message prints as ``rostopic echo`` shows it).
Importing this package imports nothing; modules load on first use.
"""
