"""Launch files the tests start, as the ROS tutorials write them."""

from __future__ import annotations

#: The turtlemimic file of the tutorial "Using rqt_console and roslaunch".
TURTLEMIMIC = """\
<launch>

  <group ns="turtlesim1">
    <node pkg="turtlesim" name="sim" type="turtlesim_node"/>
  </group>

  <group ns="turtlesim2">
    <node pkg="turtlesim" name="sim" type="turtlesim_node"/>
  </group>

  <node pkg="turtlesim" name="mimic" type="mimic">
    <remap from="input" to="turtlesim1/turtle1"/>
    <remap from="output" to="turtlesim2/turtle1"/>
  </node>

</launch>
"""
