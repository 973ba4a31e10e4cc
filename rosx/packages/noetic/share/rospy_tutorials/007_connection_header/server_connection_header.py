#!/usr/bin/env python3
"""rospy_tutorials' server_connection_header: the ``add_two_ints`` service of node
``add_two_ints_server``, printing who called and the cookies their connection header offers."""

import rospy
from rospy_tutorials.srv import AddTwoInts, AddTwoIntsRequest, AddTwoIntsResponse


def add_two_ints(request: AddTwoIntsRequest) -> AddTwoIntsResponse:
    header = request._connection_header
    print(f"Request from {header['callerid']}")
    if "cookies" in header:
        print(f"Request gave me {header['cookies']} cookies")
    total = request.a + request.b
    print(f"Returning [{request.a} + {request.b} = {total}]")
    return AddTwoIntsResponse(total)


def serve() -> None:
    rospy.init_node("add_two_ints_server")
    rospy.Service("add_two_ints", AddTwoInts, add_two_ints)
    rospy.spin()


if __name__ == "__main__":
    serve()
