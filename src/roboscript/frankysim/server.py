"""A franky-sim server for one FR3 (run as ``python -m roboscript.frankysim.server``): it serves libfranka's network
protocol on a free loopback address, prints ``serving HOST`` once it does, and runs its physics in real time until
its standard input closes or it is killed. In a world (``--world``), a line ``state`` on its standard input is
answered with a line ``state JSON``: the world's joint positions and velocities, for a mirror of it (cameras, checks)
on the other side. A line ``reflex`` trips a joint reflex during the running motion
(:mod:`roboscript.frankysim.reflexes`), as a collision would on an FR3."""

from __future__ import annotations

import argparse
import json
import sys

from roboscript.sim.world_catalog import load_world


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--base", type=float, nargs=3, default=None, help="the arm's base (without --world; a world stands its arm)"
    )
    parser.add_argument("--joints", type=float, nargs=7, default=None, help="where the arm starts (radians)")
    parser.add_argument(
        "--world", default=None, help="a world (packaged name or file): its scene, the arm where it stands"
    )
    parser.add_argument("--seed", type=int, default=None, help="with --world: lay it out as a trial of this seed does")
    args = parser.parse_args(argv)
    if args.world is not None and args.base is not None:
        parser.error("--base is for an arm alone: a world stands its arm where its file says")
    from franky_sim import DEFAULT_INITIAL_JOINT_POS
    from franky_sim.mujoco_simulator import MujocoSimulator

    from roboscript.frankysim.reflexes import ReflexingSimulationServer

    if args.world is not None:
        from roboscript.frankysim.world import WorldSimulator  # franky-sim's: the optional extra

        world = load_world(args.world)
        simulator = WorldSimulator(world if args.seed is None else world.randomized(args.seed))
    else:
        simulator = MujocoSimulator(enable_visualization=False)
    with simulator as sim:
        start = args.joints or (None if args.world else DEFAULT_INITIAL_JOINT_POS)  # a world's arm starts at home
        robot = sim.add_robot(initial_q=start, position=tuple(args.base or (0.0, 0.0, 0.0)))
        with ReflexingSimulationServer(sim) as server:
            server.run_async()
            print(f"serving {robot.hostname}", flush=True)
            for line in sys.stdin:  # until the launcher closes it
                if line.strip() == "state" and args.world is not None:
                    qpos, qvel = sim.state()
                    print("state " + json.dumps([qpos.tolist(), qvel.tolist()]), flush=True)
                elif line.strip() == "reflex":
                    server.trip_reflex()
    return 0


if __name__ == "__main__":
    sys.exit(main())
