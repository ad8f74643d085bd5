"""The ROS 1 edge: message types Debian does not package (more of the transport comes with the ROS backend)."""
