# rospy_tutorials's CMake configuration, where catkin installs it (share/rospy_tutorials/cmake/rospy_tutorialsConfig.cmake).
# The rospy_tutorials package here is rosx's: rosx compiles no C++ and ships no headers, libraries or
# CMake macros, so a CMake project that finds this file stops with the message below instead of
# configuring against nothing. Build such projects against a ROS 1 installation.
message(FATAL_ERROR
  "rospy_tutorials in ${CMAKE_CURRENT_LIST_DIR} is rosx's, which has no C++ headers, libraries or "
  "CMake macros to build against: use a ROS 1 installation for CMake projects")
