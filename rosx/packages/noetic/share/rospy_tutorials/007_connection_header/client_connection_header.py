#!/usr/bin/env python3
"""rospy_tutorials' client_connection_header: calls ``add_two_ints`` with ``cookies: peanut
butter`` in its connection header and prints the server's header. Usage: ``[x y]`` (two
random numbers without them)."""

import random
import sys

import rospy
from rospy_tutorials.srv import AddTwoInts


def add(x: int, y: int) -> int | None:
    rospy.wait_for_service("add_two_ints")
    try:
        metadata = {"cookies": "peanut butter"}
        add_two_ints = rospy.ServiceProxy("add_two_ints", AddTwoInts, headers=metadata)
        print(f"Requesting {x}+{y} with cookies={metadata['cookies']}")
        response = add_two_ints(x, y)
        print("Server's connection headers were", response._connection_header)
        return int(response.sum)
    except rospy.ServiceException as exc:
        print(f"Service call failed: {exc}")
        return None


def usage() -> str:
    return f"{sys.argv[0]} [x y]"


if __name__ == "__main__":
    if len(sys.argv) == 1:
        x, y = random.randint(-50000, 50000), random.randint(-50000, 50000)
    elif len(sys.argv) == 3:
        try:
            x, y = int(sys.argv[1]), int(sys.argv[2])
        except ValueError:
            print(usage())
            sys.exit(1)
    else:
        print(usage())
        sys.exit(1)
    print(f"{x} + {y} = {add(x, y)}")
