"""Perception: the object store behind the tools (ground truth or RGB-D pipeline) and grasp detection."""
