"""Studies: task templates instantiated over the object library (the object-shape study), run as sweeps."""
