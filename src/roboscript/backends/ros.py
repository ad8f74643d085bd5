"""The ROS backend: :class:`~roboscript.backends.driven.DriverBackend` over the ROS 1 driver, as a robot
configuration file describes the robot (``robot_configs/`` holds examples for franka_ros and ur_robot_driver)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from roboscript.backends.driven import DriverBackend
from roboscript.robot_config import RobotConfig, RobotConfigError, load_robot_config

TF_CONNECT_TIMEOUT = 10.0  # seconds for the robot's base frame to appear in TF when the backend connects


def ros_backend(
    config: RobotConfig | str | Path,
    confirm: Callable[[str], bool] | None = None,
    node_name: str = "roboscript",
) -> DriverBackend:
    """The robot ``config`` (a configuration, its file, or a packaged one's name) over ROS 1; the ROS master is the
    one ``ROS_MASTER_URI`` names. Fails within the configuration's ``server_timeout`` if the robot's driver does
    not answer."""
    from roboscript.ros.driver import RosDriver

    config = config if isinstance(config, RobotConfig) else load_robot_config(config)
    if config.driver != "ros":
        raise RobotConfigError(config.source or config.name, "driver", f"is {config.driver}, not ros")
    driver = RosDriver(config, node_name)
    try:
        # TF's listener has only just started: it first connects to every publisher of /tf and /tf_static, which
        # takes seconds on a busy machine. A frame that is really missing is reported after this long.
        base = driver.frame_pose(config.base_frame, timeout=max(config.server_timeout, TF_CONNECT_TIMEOUT))
        return DriverBackend(driver, config, base, confirm)
    except BaseException:
        driver.close()
        raise
