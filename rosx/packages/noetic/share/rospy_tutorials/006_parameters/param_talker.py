#!/usr/bin/env python3
"""rospy_tutorials' param_talker (rospy/Tutorials/Parameters): node ``param_talker`` reads a
global, a relative, a private and a defaulted parameter and a dictionary of gains, logging
each; sets, deletes and searches parameters; then publishes its ``utterance`` on the topic
its ``~topic_name`` names, once a second. ``param_talker.launch`` sets them all."""

import contextlib

import rospy
from std_msgs.msg import String


def talk() -> None:
    rospy.init_node("param_talker")

    global_example = rospy.get_param("/global_example")
    rospy.loginfo("%s is %s", rospy.resolve_name("/global_example"), global_example)
    utterance = rospy.get_param("utterance")
    rospy.loginfo("%s is %s", rospy.resolve_name("utterance"), utterance)
    topic_name = rospy.get_param("~topic_name")
    rospy.loginfo("%s is %s", rospy.resolve_name("~topic_name"), topic_name)
    default_param = rospy.get_param("default_param", "default_value")
    rospy.loginfo("%s is %s", rospy.resolve_name("default_param"), default_param)
    gains = rospy.get_param("gains")
    rospy.loginfo("gains are %s, %s, %s", gains["P"], gains["I"], gains["D"])

    rospy.loginfo("setting parameters...")
    rospy.set_param("list_of_floats", [1.0, 2.0, 3.0, 4.0])
    rospy.set_param("bool_True", True)
    rospy.set_param("~private_bar", 1 + 2)
    rospy.set_param("to_delete", "baz")
    rospy.loginfo("...parameters have been set")

    if rospy.has_param("to_delete"):
        rospy.delete_param("to_delete")
        rospy.loginfo(f"deleted {rospy.resolve_name('to_delete')} parameter")
    else:
        rospy.loginfo(f"parameter {rospy.resolve_name('to_delete')} was already deleted")
    found = rospy.search_param("global_example")
    rospy.loginfo(f"found global_example parameter under key: {found}")

    chatter = rospy.Publisher(topic_name, String, queue_size=10)
    while not rospy.is_shutdown():
        chatter.publish(utterance)
        rospy.loginfo(utterance)
        rospy.sleep(1)


if __name__ == "__main__":
    with contextlib.suppress(rospy.ROSInterruptException):
        talk()
