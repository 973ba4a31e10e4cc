#!/usr/bin/env python3
"""rospy_tutorials' listener_subscribe_notify: a talker told of each subscriber that comes and
goes (rospy's ``SubscribeListener``). Node ``talker_callback`` (anonymous), topic ``chatter``.

It greets a new subscriber twice: on the topic, to everyone, and on that subscriber's
connection alone; when the last one leaves it says so.
"""

import contextlib
from collections.abc import Callable

import rospy
from std_msgs.msg import String


class ChatterListener(rospy.SubscribeListener):
    def peer_subscribe(
        self,
        topic_name: str,
        topic_publish: Callable[[String], None],
        peer_publish: Callable[[String], None],
    ) -> None:
        print(f"a peer subscribed to topic [{topic_name}]")
        to_all = "Hey everyone, we have a new friend!"
        print(to_all)
        topic_publish(String(to_all))
        to_peer = "greetings. welcome to topic " + topic_name
        print(to_peer)
        peer_publish(String(to_peer))

    def peer_unsubscribe(self, topic_name: str, num_peers: int) -> None:
        print(f"a peer unsubscribed from topic [{topic_name}]")
        if num_peers == 0:
            print("I have no friends")


def talk() -> None:
    chatter = rospy.Publisher(
        "chatter", String, subscriber_listener=ChatterListener(), queue_size=10
    )
    rospy.init_node("talker_callback", anonymous=True)
    count = 0
    while not rospy.is_shutdown():
        text = f"hello world {count}"
        print(text)
        chatter.publish(String(text))
        count += 1
        rospy.sleep(0.1)


if __name__ == "__main__":
    with contextlib.suppress(rospy.ROSInterruptException):
        talk()
