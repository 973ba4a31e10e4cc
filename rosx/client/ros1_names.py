"""The names rospy's, genpy's and rosgraph's classes go by, for the scripts that rosx runs.

A traceback prints an exception's class as ``module.qualname``, and ``type(x)`` and ``repr``
of a class do too. A student searching for ``rospy.exceptions.ROSInitException`` finds rospy's
documentation and answers; ``rosx.client.exceptions.ROSInitException`` finds nothing. So the
shims (``rospy``, ``genpy``, ``roslib``, ``rospkg``, ``rosgraph``: what scripts import) give
rosx's classes the module paths of ROS 1's (`ROS1_MODULES`) when a script imports them; each
of those paths is a module the shims serve, holding the class under that name. rosx's own
tools, which import no shim, keep the names of rosx's modules. Message classes need nothing
here: they are built as ``<package>.msg._<Type>.<Type>``, as genpy generates them.
"""

from __future__ import annotations

import importlib

#: rosx's class (``module:name``) → the module that rospy, genpy or rosgraph define it in, and
#: its name there.
ROS1_MODULES: dict[str, tuple[str, str]] = {
    **{
        f"rosx.client.exceptions:{name}": ("rospy.exceptions", name)
        for name in (
            "ROSException",
            "ROSSerializationException",
            "ROSInitException",
            "ROSInterruptException",
            "ROSTimeMovedBackwardsException",
            "ROSInternalException",
            "TransportException",
            "TransportTerminated",
            "TransportInitError",
        )
    },
    "rosx.node.errors:ServiceError": ("rospy.service", "ServiceException"),
    "rosx.client.anymsg:AnyMsg": ("rospy.msg", "AnyMsg"),
    "rosx.client.masterproxy:MasterProxy": ("rospy.msproxy", "MasterProxy"),
    "rosx.client.timing:Time": ("rospy.rostime", "Time"),
    "rosx.client.timing:Duration": ("rospy.rostime", "Duration"),
    "rosx.client.timing:Rate": ("rospy.timer", "Rate"),
    "rosx.client.timing:Timer": ("rospy.timer", "Timer"),
    "rosx.client.timing:TimerEvent": ("rospy.timer", "TimerEvent"),
    "rosx.client.topics:Publisher": ("rospy.topics", "Publisher"),
    "rosx.client.topics:Subscriber": ("rospy.topics", "Subscriber"),
    "rosx.client.topics:SubscribeListener": ("rospy.topics", "SubscribeListener"),
    "rosx.client.services:Service": ("rospy.impl.tcpros_service", "Service"),
    "rosx.client.services:ServiceProxy": ("rospy.impl.tcpros_service", "ServiceProxy"),
    "rosx.msg.codec.message:Message": ("genpy.message", "Message"),
    "rosx.msg.codec.message:MessageException": ("genpy.message", "MessageException"),
    "rosx.msg.codec.message:SerializationError": ("genpy.message", "SerializationError"),
    "rosx.msg.codec.message:DeserializationError": ("genpy.message", "DeserializationError"),
    "rosx.msg.codec.rostime:TVal": ("genpy.rostime", "TVal"),
    "rosx.msg.codec.rostime:Time": ("genpy.rostime", "Time"),
    "rosx.msg.codec.rostime:Duration": ("genpy.rostime", "Duration"),
    **{
        f"rosx.client.roslib:{name}": ("roslib.packages", name)
        for name in ("ROSPkgException", "InvalidROSPkgException", "MultipleNodesException")
    },
    "rosx.client.rospkg:ResourceNotFound": ("rospkg.common", "ResourceNotFound"),
    "rosx.client.rospkg:RosPack": ("rospkg.rospack", "RosPack"),
    **{
        f"rosx.client.rosgraph:{name}": ("rosgraph.masterapi", name)
        for name in ("Master", "MasterException", "MasterFailure", "MasterError")
    },
}


def use_ros1_names(*homes: str) -> None:
    """Give the classes of `ROS1_MODULES` their ROS 1 module path and name: those defined in
    the modules ``homes`` (``rosx.client.rosgraph``…), every one when none is given. A shim
    names only the modules it loads anyway, so that ``import rosgraph`` stays light."""
    for source, (module, name) in ROS1_MODULES.items():
        home, _, attribute = source.partition(":")
        if homes and home not in homes:
            continue
        cls = getattr(importlib.import_module(home), attribute)
        cls.__module__ = module
        cls.__name__ = cls.__qualname__ = name


__all__ = ["ROS1_MODULES", "use_ros1_names"]
