"""ros-sim's cameras: each camera's RGB, depth, camera info and labelled segmentation image, rendered from a copy
of the simulation's state in a thread of their own, and the segmentation's labels on a latched topic."""

from __future__ import annotations

import json
import threading

import mujoco
import numpy as np

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.robot_config import RobotConfig
from roboscript.sim.cameras import Renderer, pinhole_intrinsics

OPTICAL_FRAME = "{camera}_color_optical_frame"


class CameraPublisher(threading.Thread):
    """Renders and publishes the cameras from a copy of the simulation's state, in a thread of its own (a renderer's
    GL context belongs to the thread that made it)."""

    def __init__(self, backend: MujocoBackend, config: RobotConfig, image_type, info_type, labels_topic, stop):
        import rospy
        from std_msgs.msg import String

        super().__init__(daemon=True, name="ros-sim cameras")
        self.backend, self.config, self._stop = backend, config, stop
        self._image, self._info = image_type, info_type
        model = backend.sim_world.model
        self._snapshot = mujoco.MjData(model)
        self._lock = threading.Lock()
        self._fresh = threading.Event()
        self._stamp = 0.0
        self._specs = {c.name: c for c in backend.sim_world.spec.cameras}
        self._publishers = {}
        for camera in (c for c in config.cameras if c.over_ros):
            if camera.name not in self._specs:
                continue  # the configuration names a camera this world lacks: it is simply not served
            self._publishers[camera.name] = (
                rospy.Publisher(camera.rgb, image_type, queue_size=2),
                rospy.Publisher(camera.depth, image_type, queue_size=2),
                rospy.Publisher(camera.info, info_type, queue_size=2),
                rospy.Publisher(camera.segmentation, image_type, queue_size=2) if camera.segmentation else None,
            )
        labels = json.dumps({str(k): v for k, v in backend.segmentation_labels().items()})
        self._labels = rospy.Publisher(config.segmentation_labels or labels_topic, String, queue_size=1, latch=True)
        self._labels.publish(String(data=labels))

    def _wanted(self) -> bool:
        return any(p.get_num_connections() for pubs in self._publishers.values() for p in pubs if p is not None)

    def offer(self, simulator, now: float) -> None:
        """Called on the simulation's thread: takes a copy of the state to render, if anyone listens."""
        if not self._publishers or self._fresh.is_set() or not self._wanted():
            return
        with self._lock:
            mujoco.mj_copyData(self._snapshot, simulator.model, simulator.data)
            self._stamp = now
        self._fresh.set()

    def run(self) -> None:
        import rospy

        world = self.backend.sim_world
        renderers: dict[tuple[int, int], Renderer] = {}
        while not self._stop.is_set() and not rospy.is_shutdown():
            if not self._fresh.wait(timeout=0.1):
                continue
            with self._lock:
                data = mujoco.MjData(world.model)
                mujoco.mj_copyData(data, world.model, self._snapshot)
                stamp = rospy.Time.from_sec(self._stamp)
            self._fresh.clear()
            for name, (rgb_pub, depth_pub, info_pub, seg_pub) in self._publishers.items():
                spec = self._specs[name]
                key = (spec.width, spec.height)
                if key not in renderers:
                    renderers[key] = Renderer(world.model, world.geom_entity, spec.width, spec.height)
                frame = renderers[key].capture(data, name, spec, segmentation=seg_pub is not None)
                frame_id = OPTICAL_FRAME.format(camera=name)
                rgb_pub.publish(self._picture(frame.rgb, "rgb8", 3, stamp, frame_id))
                depth_pub.publish(self._picture(frame.depth.astype(np.float32), "32FC1", 4, stamp, frame_id))
                if seg_pub is not None:
                    seg_pub.publish(self._picture(frame.segmentation.astype(np.int32), "32SC1", 4, stamp, frame_id))
                info_pub.publish(self._camera_info(spec, stamp, frame_id))
        for renderer in renderers.values():
            renderer.close()

    def _picture(self, array: np.ndarray, encoding: str, pixel_bytes: int, stamp, frame_id: str):
        image = self._image()
        image.header.stamp, image.header.frame_id = stamp, frame_id
        image.height, image.width = array.shape[:2]
        image.encoding, image.is_bigendian = encoding, 0
        image.step = image.width * pixel_bytes
        image.data = np.ascontiguousarray(array).tobytes()
        return image

    def _camera_info(self, spec, stamp, frame_id: str):
        info = self._info()
        info.header.stamp, info.header.frame_id = stamp, frame_id
        info.height, info.width = spec.height, spec.width
        k = pinhole_intrinsics(spec.fovy, spec.width, spec.height)
        info.distortion_model = "plumb_bob"
        info.D = [0.0] * 5
        info.K = [float(v) for v in k.flatten()]
        info.R = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
        info.P = [k[0, 0], 0.0, k[0, 2], 0.0, 0.0, k[1, 1], k[1, 2], 0.0, 0.0, 0.0, 1.0, 0.0]
        return info
