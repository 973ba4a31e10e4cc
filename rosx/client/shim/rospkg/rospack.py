"""``rospkg.rospack`` for scripts that rosx runs (see the ``rospkg`` package)."""

from rosx.client.rospkg import RosPack

__all__ = ["RosPack"]
