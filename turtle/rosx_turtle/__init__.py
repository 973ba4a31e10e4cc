"""turtlesim for rosx; ``msg/`` and ``srv/`` hold the ``turtlesim`` package's types."""
