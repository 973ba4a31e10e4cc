#!/usr/bin/env python3
"""tf2_tools' echo.py: prints the transform between two frames at a rate, with options for
the lookup time (-t), an offset from now (-o), a count (-l), the cache length (-c) and the
precision (-p, or ~precision)."""

import argparse
import math
import sys

import rospy
import tf2_py as tf2
import tf2_ros

from rosx.tf.transformations import euler_from_quaternion


def positive_float(x: str) -> float:
    value = float(x)
    if value <= 0.0:
        raise argparse.ArgumentTypeError(f"{value} must be > 0.0")
    return value


def positive_int(x: str) -> int:
    value = int(x)
    if value <= 0:
        raise argparse.ArgumentTypeError(f"{value} must be > 0")
    return value


class Echo:
    def __init__(self, args: argparse.Namespace) -> None:
        cache = None if args.cache_time is None else rospy.Duration.from_sec(args.cache_time)
        self.buffer = tf2_ros.Buffer(cache_time=cache)
        self.listener = tf2_ros.TransformListener(self.buffer)
        self.args = args
        self.count = 0
        self.timer = rospy.Timer(rospy.Duration.from_sec(1.0 / args.rate), self.lookup)

    def lookup(self, _event: object) -> None:
        args = self.args
        self.count += 1
        if args.limit and self.count > args.limit:
            rospy.signal_shutdown("tf echo finished")
            return
        now = rospy.Time.now()
        if args.time:
            when = rospy.Time.from_sec(args.time)
        elif args.offset:
            when = now + rospy.Duration.from_sec(args.offset)
        else:
            when = rospy.Time()
        try:
            t = self.buffer.lookup_transform(args.source_frame, args.target_frame, when)
        except tf2.LookupException as error:
            rospy.logerr(f"At time {when.to_sec()}, (current time {now.to_sec()}) {error}")
            return
        except tf2.ExtrapolationException as error:
            rospy.logerr(f"(current time {now.to_sec()}) {error}")
            return
        p = args.precision
        v = t.transform.translation
        q = t.transform.rotation
        angles = euler_from_quaternion((q.x, q.y, q.z, q.w))
        print(
            f"At time {t.header.stamp.to_sec()}, (current time {now.to_sec()})\n"
            f"- Translation: [{v.x:.{p}f}, {v.y:.{p}f}, {v.z:.{p}f}]\n"
            f"- Rotation: in Quaternion [{q.x:.{p}f}, {q.y:.{p}f}, {q.z:.{p}f}, {q.w:.{p}f}]\n"
            "            in RPY (radian) "
            f"[{angles[0]:.{p}f}, {angles[1]:.{p}f}, {angles[2]:.{p}f}]\n"
            "            in RPY (degree) "
            f"[{math.degrees(angles[0]):.{p}f}, {math.degrees(angles[1]):.{p}f}, "
            f"{math.degrees(angles[2]):.{p}f}]",
            flush=True,
        )


if __name__ == "__main__":
    rospy.init_node("echo")
    precision = 3
    if rospy.has_param("~precision"):
        precision = rospy.get_param("~precision")
        rospy.loginfo("Precision default value was overriden, new value: %d", precision)
    parser = argparse.ArgumentParser()
    parser.add_argument("source_frame")
    parser.add_argument("target_frame")
    parser.add_argument(
        "-r", "--rate", help="update rate, must be > 0.0", default=1.0, type=positive_float
    )
    parser.add_argument(
        "-c", "--cache_time", help="length of tf buffer cache in seconds", type=positive_float
    )
    parser.add_argument(
        "-o",
        "--offset",
        help="offset the lookup from current time, ignored if using -t",
        type=float,
    )
    parser.add_argument("-t", "--time", help="fixed time to do the lookup", type=float)
    parser.add_argument("-l", "--limit", help="lookup fixed number of times", type=positive_int)
    parser.add_argument(
        "-p", "--precision", help="output precision", default=precision, type=positive_int
    )
    echo = Echo(parser.parse_args(rospy.myargv(argv=sys.argv)[1:]))
    rospy.spin()
