"""Generated message classes and the ROS 1 wire codec (rosbags' ``serde``).

- `classes`: message and service classes by type name, cached per type store.
- `message`: their base classes, as rospy scripts see them.
- `codegen`, `serializer`, `deserializer`, `source`: the generated ``__init__``, ``serialize``
  and ``deserialize``; `wiretypes`: built-in types as ``struct`` characters.
- `checks`: which field made serialisation fail, in genpy's words.
- `rostime`: ``time`` and ``duration`` values (`Time`, `Duration`).
- `introspect`: message values read generically (fields, plain Python values).

Imports `rosx.msg`'s definitions and store, not `rosx.msg.text` (but for a message's ``str()``).
"""
