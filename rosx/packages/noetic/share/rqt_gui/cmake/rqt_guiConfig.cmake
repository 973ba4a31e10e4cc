# rqt_gui's CMake configuration, where catkin installs it (share/rqt_gui/cmake/rqt_guiConfig.cmake).
# The rqt_gui package here is rosx's: rosx compiles no C++ and ships no headers, libraries or
# CMake macros, so a CMake project that finds this file stops with the message below instead of
# configuring against nothing. Build such projects against a ROS 1 installation.
message(FATAL_ERROR
  "rqt_gui in ${CMAKE_CURRENT_LIST_DIR} is rosx's, which has no C++ headers, libraries or "
  "CMake macros to build against: use a ROS 1 installation for CMake projects")
