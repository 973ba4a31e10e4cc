"""``tf.transformations``: rosx's (`rosx.tf.transformations`), the same functions as ROS 1's."""

from rosx.tf.transformations import *  # noqa: F403
from rosx.tf.transformations import _AXES2TUPLE, _EPS, _NEXT_AXIS, _TUPLE2AXES  # noqa: F401
