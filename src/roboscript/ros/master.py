"""The ROS master, asked directly before a node starts: rospy retries an absent master for ever ("Will keep trying"),
and a run should end with an error that names the address instead."""

from __future__ import annotations

import http.client
import os
import time
import xmlrpc.client
from xml.parsers.expat import ExpatError

from roboscript.drivers.base import DriverError

MASTER_TIMEOUT = 1.5  # seconds for the ROS master to answer before a run gives up on it


class _TimedTransport(xmlrpc.client.Transport):
    def __init__(self, timeout: float):
        super().__init__()
        self._timeout = timeout

    def make_connection(self, host):
        connection = super().make_connection(host)
        connection.timeout = self._timeout
        return connection


def check_master(uri: str | None = None, timeout: float = MASTER_TIMEOUT) -> None:
    """Raises :class:`DriverError` unless the ROS master at ``uri`` (default ``ROS_MASTER_URI``) answers within
    ``timeout`` seconds. rospy itself retries an absent master for ever ("Will keep trying")."""
    uri = uri or os.environ.get("ROS_MASTER_URI")
    if not uri:
        raise DriverError("ROS_MASTER_URI is not set: start a master (rosmaster --core -p 11311) and export its URI")
    started = time.monotonic()
    try:
        proxy = xmlrpc.client.ServerProxy(uri, transport=_TimedTransport(timeout))
        reply = proxy.getPid("/roboscript_probe")
    except (OSError, xmlrpc.client.Error, http.client.HTTPException, ExpatError, ValueError) as error:
        raise DriverError(
            f"no ROS master answers at {uri} ({type(error).__name__}: {error}, after "
            f"{time.monotonic() - started:.1f} s): start one (rosmaster --core -p PORT, or `roboscript ros-sim`), "
            "or name the running one with --master URI"
        ) from None
    if not (isinstance(reply, list | tuple) and len(reply) == 3 and reply[0] == 1):
        raise DriverError(f"{uri} answered, but not as a ROS master does (getPid returned {str(reply)[:100]})")
