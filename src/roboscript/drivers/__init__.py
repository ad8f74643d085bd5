"""Drivers: the transports to a real robot and its cameras (ROS 1, libfranka, librealsense), behind one interface."""
