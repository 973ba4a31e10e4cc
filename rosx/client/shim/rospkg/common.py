"""``rospkg.common`` for scripts that rosx runs (see the ``rospkg`` package)."""

from rosx.client.rospkg import ResourceNotFound

__all__ = ["ResourceNotFound"]
