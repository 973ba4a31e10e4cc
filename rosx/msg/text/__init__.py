"""The text forms of messages and parameters, as ROS 1's tools print and read them.

- `echo`, `echocsv`, `fieldpath`: ``rostopic echo`` (its YAML-like text, ``-p`` CSV, field paths).
- `yamlload`, `yamldump`, `yamlstr`: PyYAML's ``safe_load`` and ``dump`` emulated.
- `yamlargs`: message values from YAML arguments (``rostopic pub``, ``rosservice call``).
- `yamlparams`: rosparam's YAML rules (``!degrees``, ``rad(…)``, binary values).

Imports `rosx.msg`, `rosx.msg.codec` and `rosx.names`.
"""
