"""3D reconstruction: the views fused, matched across and cut into instances, and what a look shows of free space."""
