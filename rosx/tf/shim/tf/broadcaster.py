"""``tf.broadcaster``: ``TransformBroadcaster``."""

from rosx.tf.tf1 import TransformBroadcaster  # noqa: F401
