"""franky-sim, the libfranka simulator, as the peer a Franka driver is tested against and as a twin of a lab's arm."""
