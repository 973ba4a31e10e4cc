# rospy_tutorials's CMake configuration folder, as catkin installs it. rosx builds no C++ and reads
# no CMake files: this file only keeps the package's layout (what rosls shows) as on Noetic.
