#!/usr/bin/env python3
"""tf2_tools' view_frames.py: listens to tf for 5 seconds, asks its buffer's ~tf2_frames
service for the frames, and writes frames.gv and frames.pdf (with Graphviz) in the current
folder; without Graphviz it says so and prints the tree."""

import sys

import rospy
import tf2_ros
from tf2_msgs.srv import FrameGraph

from rosx_commands.tf_tools.frames import read_frames_yaml, render, tf2_dot

if __name__ == "__main__":
    rospy.init_node("view_frames")
    rospy.loginfo("Listening to tf data during 5 seconds...")
    rospy.sleep(0.00001)
    buffer = tf2_ros.Buffer()
    listener = tf2_ros.TransformListener(buffer)
    rospy.sleep(5.0)
    rospy.loginfo("Generating graph in frames.pdf file...")
    rospy.wait_for_service("~tf2_frames")
    frames = read_frames_yaml(rospy.ServiceProxy("~tf2_frames", FrameGraph)().frame_yaml)
    parents = {name: str(values["parent"]) for name, values in frames.items()}
    render(tf2_dot(frames, rospy.Time.now().to_sec()), parents, sys.stdout)
