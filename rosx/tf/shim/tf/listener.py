"""``tf.listener``: ``Transformer``, ``TransformerROS``, ``TransformListener``."""

from rosx.tf.tf1 import (  # noqa: F401
    Transformer,
    TransformerROS,
    TransformListener,
    strip_leading_slash,
)
