"""Recordings of trials (``--record FILE``): MCAP files of Foxglove messages a person can scrub through in 3D."""
