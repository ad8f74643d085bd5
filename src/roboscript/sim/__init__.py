"""MuJoCo simulation: worlds, objects, furniture, cameras, control and ground truth."""
