"""The libfranka backend: :class:`~roboscript.backends.driven.DriverBackend` over the franky driver, as a robot
configuration with ``driver: franky`` describes the arm (``robot_configs/fr3_franky.yaml`` is an example)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from roboscript.backends.driven import DriverBackend
from roboscript.drivers.base import CameraSource
from roboscript.drivers.franky import FrankyDriver
from roboscript.robot_config import RobotConfig, RobotConfigError, load_robot_config


def franky_backend(
    config: RobotConfig | str | Path,
    confirm: Callable[[str], bool] | None = None,
    cameras: CameraSource | None = None,
) -> DriverBackend:
    """The Franka arm ``config`` (a configuration, its file, or a packaged one's name) describes, through libfranka;
    ``cameras`` default to the configuration's RealSense cameras."""
    config = config if isinstance(config, RobotConfig) else load_robot_config(config)
    if config.franky is None:
        raise RobotConfigError(config.source or config.name, "driver", f"is {config.driver}, not franky")
    driver = FrankyDriver(config, cameras)
    try:
        return DriverBackend(driver, config, config.franky.base_pose, confirm)
    except BaseException:
        driver.close()
        raise
