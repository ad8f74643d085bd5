"""ros-sim: a simulated world served as a ROS robot, through the interfaces a real arm's ROS drivers offer."""
