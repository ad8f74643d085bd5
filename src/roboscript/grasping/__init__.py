"""Grasping: where a parallel gripper can take an object (box grasps from its footprint, antipodal pairs from its
observed points) and which of those grasps the arm reaches. Grasping reads perception and asks the motion planner;
the tool API's grasp tools are a thin facade over it."""
