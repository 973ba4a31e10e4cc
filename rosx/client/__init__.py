"""The rospy-compatible client API: what ``import rospy`` gives a script run by rosx.

Layer 6 of rosx. A ROS 1 Python script written for rospy (``rospy.init_node``,
``rospy.Publisher``, ``rospy.Subscriber``, ``rospy.Rate``, ``rospy.is_shutdown``,
``rospy.loginfo``, ``rospy.get_param``, ``rospy.Service``…) runs unchanged on it, and speaks
ROS 1's protocols, so it works with rosx's tools and with ROS 1's alike. Modules, one concept each:

- `state`: the process's one node, its command line, its shutdown sequence.
- `lifecycle`: ``init_node``, ``spin``, ``on_shutdown``, ``signal_shutdown``, names.
- `names`: ``rospy.names`` (the node's names, the remappings); `masterproxy`: ``MasterProxy``,
  ``get_master``; `rosgraph`: the part of ``rosgraph`` scripts import (``Master``, ``names``).
- `topics`: ``Publisher``, ``Subscriber``, ``wait_for_message``; `anymsg`: ``AnyMsg``.
- `services`: ``Service``, ``ServiceProxy``, ``wait_for_service``.
- `params`: the Parameter Server functions. `logs`: ``loginfo`` and friends.
- `timing`: ``Time``, ``Duration``, ``sleep``, ``Rate``, ``Timer``.
- `exceptions`: rospy's exceptions.
- `modules` and `script`: how scripts import ``rospy`` and ``<package>.msg``, and run.
- `roslib` and `rospkg`: what older scripts call of ``roslib`` (``load_manifest``, packages,
  message classes, names) and of ``rospkg`` (``RosPack``); `ros1_names`: the module paths
  rospy's and genpy's classes print, which the shims give rosx's.

Names load on first use (as in `rosx.names`), so a tool that needs one module of this package
(``rosx rosrun`` needs `script`) does not load the whole API.

This package imports `rosx.node`, `rosx.msg` and `rosx.names`, nothing above them.
"""

from __future__ import annotations

from typing import Any

from rosx._lazy import lazy_names

_HOMES = {
    "AnyMsg": "rosx.client.anymsg",
    "DEBUG": "rosx.client.lifecycle",
    "Duration": "rosx.client.timing",
    "ERROR": "rosx.client.lifecycle",
    "FATAL": "rosx.client.lifecycle",
    "INFO": "rosx.client.lifecycle",
    "MasterProxy": "rosx.client.masterproxy",
    "Message": "rosx.msg.codec.message",
    "Publisher": "rosx.client.topics",
    "ROSException": "rosx.client.exceptions",
    "ROSInitException": "rosx.client.exceptions",
    "ROSInternalException": "rosx.client.exceptions",
    "ROSInterruptException": "rosx.client.exceptions",
    "ROSSerializationException": "rosx.client.exceptions",
    "ROSTimeMovedBackwardsException": "rosx.client.exceptions",
    "Rate": "rosx.client.timing",
    "Service": "rosx.client.services",
    "ServiceException": "rosx.client.exceptions",
    "ServiceProxy": "rosx.client.services",
    "SubscribeListener": "rosx.client.topics",
    "Subscriber": "rosx.client.topics",
    "Time": "rosx.client.timing",
    "Timer": "rosx.client.timing",
    "TimerEvent": "rosx.client.timing",
    "TransportException": "rosx.client.exceptions",
    "TransportInitError": "rosx.client.exceptions",
    "TransportTerminated": "rosx.client.exceptions",
    "WARN": "rosx.client.lifecycle",
    "delete_param": "rosx.client.params",
    "get_caller_id": "rosx.client.lifecycle",
    "get_master": "rosx.client.masterproxy",
    "get_name": "rosx.client.lifecycle",
    "get_namespace": "rosx.client.lifecycle",
    "get_node_uri": "rosx.client.lifecycle",
    "get_param": "rosx.client.params",
    "get_param_cached": "rosx.client.params",
    "get_param_names": "rosx.client.params",
    "get_published_topics": "rosx.client.lifecycle",
    "get_ros_root": "rosx.client.lifecycle",
    "get_rostime": "rosx.client.timing",
    "get_time": "rosx.client.timing",
    "has_param": "rosx.client.params",
    "init_node": "rosx.client.lifecycle",
    "is_shutdown": "rosx.client.lifecycle",
    "logdebug": "rosx.client.logs",
    "logdebug_once": "rosx.client.logs",
    "logdebug_throttle": "rosx.client.logs",
    "logdebug_throttle_identical": "rosx.client.logs",
    "logerr": "rosx.client.logs",
    "logerr_once": "rosx.client.logs",
    "logerr_throttle": "rosx.client.logs",
    "logerr_throttle_identical": "rosx.client.logs",
    "logerror": "rosx.client.logs",
    "logfatal": "rosx.client.logs",
    "logfatal_once": "rosx.client.logs",
    "logfatal_throttle": "rosx.client.logs",
    "logfatal_throttle_identical": "rosx.client.logs",
    "loginfo": "rosx.client.logs",
    "loginfo_once": "rosx.client.logs",
    "loginfo_throttle": "rosx.client.logs",
    "loginfo_throttle_identical": "rosx.client.logs",
    "logout": "rosx.client.logs",
    "logwarn": "rosx.client.logs",
    "logwarn_once": "rosx.client.logs",
    "logwarn_throttle": "rosx.client.logs",
    "logwarn_throttle_identical": "rosx.client.logs",
    "myargv": "rosx.client.lifecycle",
    "on_shutdown": "rosx.client.lifecycle",
    "parse_rosrpc_uri": "rosx.wire.rosrpc",
    "remap_name": "rosx.client.names",
    "resolve_name": "rosx.client.lifecycle",
    "search_param": "rosx.client.params",
    "set_param": "rosx.client.params",
    "signal_shutdown": "rosx.client.lifecycle",
    "sleep": "rosx.client.timing",
    "spin": "rosx.client.lifecycle",
    "wait_for_message": "rosx.client.topics",
    "wait_for_service": "rosx.client.services",
}


_load = lazy_names(__name__, _HOMES)


def __getattr__(name: str) -> Any:
    # std_msgs/Header needs the standard type store, loaded only when a script asks for it.
    if name == "Header":
        from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

        return get_message_class("std_msgs/Header")
    return _load(name)


__all__ = [
    "DEBUG",
    "ERROR",
    "FATAL",
    "INFO",
    "WARN",
    "AnyMsg",
    "Duration",
    "Header",
    "MasterProxy",
    "Message",
    "Publisher",
    "ROSException",
    "ROSInitException",
    "ROSInternalException",
    "ROSInterruptException",
    "ROSSerializationException",
    "ROSTimeMovedBackwardsException",
    "Rate",
    "Service",
    "ServiceException",
    "ServiceProxy",
    "SubscribeListener",
    "Subscriber",
    "Time",
    "Timer",
    "TimerEvent",
    "TransportException",
    "TransportInitError",
    "TransportTerminated",
    "delete_param",
    "get_caller_id",
    "get_master",
    "get_name",
    "get_namespace",
    "get_node_uri",
    "get_param",
    "get_param_cached",
    "get_param_names",
    "get_published_topics",
    "get_ros_root",
    "get_rostime",
    "get_time",
    "has_param",
    "init_node",
    "is_shutdown",
    "logdebug",
    "logdebug_once",
    "logdebug_throttle",
    "logdebug_throttle_identical",
    "logerr",
    "logerr_once",
    "logerr_throttle",
    "logerr_throttle_identical",
    "logerror",
    "logfatal",
    "logfatal_once",
    "logfatal_throttle",
    "logfatal_throttle_identical",
    "loginfo",
    "loginfo_once",
    "loginfo_throttle",
    "loginfo_throttle_identical",
    "logout",
    "logwarn",
    "logwarn_once",
    "logwarn_throttle",
    "logwarn_throttle_identical",
    "myargv",
    "on_shutdown",
    "parse_rosrpc_uri",
    "remap_name",
    "resolve_name",
    "search_param",
    "set_param",
    "signal_shutdown",
    "sleep",
    "spin",
    "wait_for_message",
    "wait_for_service",
]
