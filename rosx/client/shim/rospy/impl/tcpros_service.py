"""``rospy.impl.tcpros_service`` for scripts that rosx runs (see the ``rospy`` package)."""

from rosx.client.services import (
    Service,
    ServiceProxy,
    wait_for_service,
)

__all__ = ["Service", "ServiceProxy", "wait_for_service"]
