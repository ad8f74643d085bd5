"""Ray across nodes: a sweep on a cluster of two Ray nodes lands its trials on both, and each ends as it does on the
process pool.

Ray will not make a cluster of two nodes on one machine's loopback (it replaces 127.0.0.1 with the machine's
interface address, or, told to keep it, refuses a second node), so each node gets a network of its own: two network
namespaces joined by a veth pair, the head and the sweep's driver in one, the second node in the other. Each node
has its own temp dir and one CPU, so the sweep's two actors (a CPU each) take a node each. The second node cannot
see the test's folder (an empty file system is mounted over it where that node runs): the suite and the records
travel, no file is shared. Namespaces need root; a machine without them fails the test rather than skipping it, so
that the cluster is never silently left untested.

The nodes are stopped by killing every process in their namespaces, never with ``ray stop``, which stops every Ray
process on the machine (another test's cluster too).
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest
import yaml

import roboscript
from helpers import sweep_outcomes
from roboscript.bench.results import read_records
from roboscript.study.sweep import LocalExecutor, run_sweep
from roboscript.study.sweep_file import load_sweep_file

PORT = 6379  # the head's GCS port: free, as the head's namespace holds nothing else
JOIN_TIMEOUT = 180.0  # seconds for both nodes to be up and in the cluster (about 10 on 2 idle cores)
STOP_TIMEOUT = 30.0  # seconds for a namespace's processes to end once killed

# Run in the head's namespace: prints the addresses of the cluster's live nodes once they are ``argv[2:]``, or after
# some 10 s without.
ALIVE_NODES = """
import json, sys, time, ray
ray.init(address=sys.argv[1], log_to_driver=False)
for _ in range(20):
    alive = sorted(n["NodeManagerAddress"] for n in ray.nodes() if n["Alive"])
    if alive == sorted(sys.argv[2:]):
        break
    time.sleep(0.5)
print(json.dumps(alive))
"""


@dataclass
class TwoNodes:
    """A Ray cluster of a head in namespace ``namespaces[0]`` and a second node in ``namespaces[1]``."""

    namespaces: tuple[str, str]
    ips: tuple[str, str]
    temp_dirs: tuple[Path, Path]
    env: dict[str, str]
    nodes: list[subprocess.Popen]

    @property
    def address(self) -> str:
        return f"{self.ips[0]}:{PORT}"

    def run_on_head(self, command: list[str], timeout: float) -> subprocess.CompletedProcess:
        """``command`` in the head's namespace, as the driver of a sweep runs there."""
        return subprocess.run(
            ["ip", "netns", "exec", self.namespaces[0], *command],
            env=self.env,
            capture_output=True,
            text=True,
            timeout=timeout,
        )


def _ip(*args: str) -> None:
    if shutil.which("ip") is None:
        pytest.fail("the two-node Ray test needs the `ip` command (iproute2: scripts/setup.sh installs it)")
    done = subprocess.run(["ip", *args], capture_output=True, text=True)
    if done.returncode != 0:
        pytest.fail(f"`ip {' '.join(args)}` failed ({done.stderr.strip()}): the two-node Ray test needs network "
                    "namespaces and veth pairs (root, or CAP_NET_ADMIN and CAP_SYS_ADMIN)")  # fmt: skip


def _pids(namespace: str) -> list[int]:
    if shutil.which("ip") is None:  # nothing was made
        return []
    done = subprocess.run(["ip", "netns", "pids", namespace], capture_output=True, text=True)
    return [int(p) for p in done.stdout.split()]


def _stop(namespace: str) -> list[int]:
    """Kills every process in ``namespace``; those still there after ``STOP_TIMEOUT`` seconds. SIGKILL at once:
    their files all lie in the temp dirs, removed next, and a Ray node given SIGTERM takes some 30 s to end."""
    deadline = time.monotonic() + STOP_TIMEOUT
    while (pids := _pids(namespace)) and time.monotonic() < deadline:
        for pid in pids:
            with contextlib.suppress(ProcessLookupError):  # ended since it was listed
                os.kill(pid, signal.SIGKILL)
        time.sleep(0.2)
    return pids


def _log(path: Path) -> str:
    return path.read_text()[-3000:] if path.is_file() else "(no log)"


@pytest.fixture
def two_nodes(tmp_path: Path) -> Iterator[TwoNodes]:
    pytest.importorskip("ray")
    if os.geteuid() != 0:
        pytest.fail("the two-node Ray test needs root: it builds network namespaces, a veth pair and a mount")
    tag = os.getpid()
    namespaces = (f"rs_ray_a{tag}", f"rs_ray_b{tag}")
    # A namespace's network is its own, so the subnet clashes with nothing; one per run (from the pid, as the
    # namespaces' names are) all the same, so that what one run left behind is not taken for another's.
    subnet = f"10.231.{tag % 250 + 1}"
    ips = (f"{subnet}.1", f"{subnet}.2")
    # Ray's unix sockets lie in its temp dir, and a socket's path is at most 107 characters: short folders.
    temp_dirs = tuple(Path(tempfile.mkdtemp(prefix=f"rs_ray{n}_", dir="/tmp")) for n in "AB")
    src = str(Path(roboscript.__file__).parents[1])  # the code under test, for the driver and every Ray worker
    env = {
        **os.environ,
        "PYTHONPATH": os.pathsep.join(p for p in (src, os.environ.get("PYTHONPATH")) if p),
        "RAY_AUTH_MODE": "disabled",
        "RAY_USAGE_STATS_ENABLED": "0",
    }
    ray = [sys.executable, "-m", "ray.scripts.scripts", "start", "--num-cpus", "1", "--object-store-memory",
           str(100 * 1024**2), "--disable-usage-stats", "--block"]  # fmt: skip
    nodes: list[subprocess.Popen] = []
    logs = (tmp_path / "head.log", tmp_path / "node.log")
    try:
        for namespace in namespaces:
            _ip("netns", "add", namespace)
        veths = (f"rsa{tag}", f"rsb{tag}")  # an interface's name is at most 15 characters
        _ip("link", "add", veths[0], "netns", namespaces[0], "type", "veth", "peer", "name", veths[1], "netns",
            namespaces[1])  # fmt: skip
        for namespace, veth, ip in zip(namespaces, veths, ips, strict=True):
            _ip("-n", namespace, "addr", "add", f"{ip}/24", "dev", veth)
            _ip("-n", namespace, "link", "set", veth, "up")
            _ip("-n", namespace, "link", "set", "lo", "up")
        head = [*ray, "--head", "--node-ip-address", ips[0], "--port", str(PORT), "--temp-dir", str(temp_dirs[0]),
                "--include-dashboard=false"]  # fmt: skip
        second = [*ray, "--address", f"{ips[0]}:{PORT}", "--node-ip-address", ips[1], "--temp-dir", str(temp_dirs[1])]
        # The second node's mounts are its own (``ip netns exec`` gives it a mount namespace): the test's folder
        # is hidden under an empty one there.
        hide = ["sh", "-c", 'mount -t tmpfs rs_hidden "$0" && exec "$@"', str(tmp_path)]
        for namespace, command, log, temp_dir in zip(namespaces, (head, hide + second), logs, temp_dirs, strict=True):
            # TMPDIR: what a node's actors write (their scratch) stays in its temp dir, removed with it.
            with log.open("w") as out:
                node = subprocess.Popen(
                    ["ip", "netns", "exec", namespace, *command],
                    env={**env, "TMPDIR": str(temp_dir)},
                    stdout=out,
                    stderr=subprocess.STDOUT,
                    start_new_session=True,
                )
            nodes.append(node)
        cluster = TwoNodes(namespaces, ips, temp_dirs, env, nodes)
        _wait_for_both(cluster, logs)
        yield cluster
    finally:
        left = {namespace: _stop(namespace) for namespace in namespaces}
        for node in nodes:
            with contextlib.suppress(subprocess.TimeoutExpired):  # reported below, with what is left
                node.wait(timeout=STOP_TIMEOUT)  # reaped: its processes were just killed
        if shutil.which("ip") is not None:
            for namespace in namespaces:
                subprocess.run(["ip", "netns", "del", namespace], capture_output=True)
        for temp_dir in temp_dirs:
            shutil.rmtree(temp_dir, ignore_errors=True)
    # After the cleanup, and only where the test itself did not fail first (its failure is the one to read).
    assert not any(left.values()), f"processes left in the namespaces after SIGKILL: {left}"


def _wait_for_both(cluster: TwoNodes, logs: tuple[Path, Path]) -> None:
    deadline = time.monotonic() + JOIN_TIMEOUT
    alive: list[str] = []
    while sorted(alive) != sorted(cluster.ips):
        for node, log in zip(cluster.nodes, logs, strict=True):
            if node.poll() is not None:
                pytest.fail(f"a Ray node stopped (exit code {node.returncode}); its log:\n{_log(log)}")
        if time.monotonic() > deadline:
            pytest.fail(f"the two Ray nodes were not both up in {JOIN_TIMEOUT:.0f} s (alive: {alive}); the head's "
                        f"log:\n{_log(logs[0])}\nthe second node's log:\n{_log(logs[1])}")  # fmt: skip
        try:
            done = cluster.run_on_head([sys.executable, "-c", ALIVE_NODES, cluster.address, *cluster.ips], 120)
        except subprocess.TimeoutExpired:  # the head did not answer yet: asked again
            continue
        alive = json.loads(done.stdout.splitlines()[-1]) if done.returncode == 0 and done.stdout.strip() else []


def test_a_sweep_on_two_ray_nodes_runs_on_both_and_ends_each_trial_as_the_process_pool_does(tmp_path, two_nodes):
    # An object every grasp tool takes and one too wide for the Panda's opening: outcomes differ between trials.
    study = {"name": "objects", "templates": ["pick_place"], "objects": ["apple", "tuna_can"],
             "grasps": ["central", "adaptive"]}  # fmt: skip
    path = tmp_path / "sweep.yaml"
    path.write_text(yaml.safe_dump({"sweep": "two_nodes", "study": study, "trials": 2}))

    sweep = [sys.executable, "-m", "roboscript.cli", "sweep", str(path), "--ray", two_nodes.address, "--out",
             str(tmp_path / "ray")]  # fmt: skip
    done = two_nodes.run_on_head(sweep, timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    (pool_run,) = run_sweep(load_sweep_file(path), tmp_path / "pool", LocalExecutor(2), progress=False)

    ray_dir = tmp_path / "ray" / pool_run.name
    pooled, rayed = sweep_outcomes(pool_run.directory.path), sweep_outcomes(ray_dir)
    assert len(pooled) == 2 * 2 * 2  # 2 objects x 2 grasp tools x 2 trials
    assert rayed == pooled
    assert {o[1] for o in pooled.values()} == {"ok", "planning_failure"}
    assert {r.node for r in read_records(ray_dir / "results.jsonl")} == set(two_nodes.ips)
    # Each node kept its session in its own temp dir, and the second node saw none of the test's files.
    for temp_dir, ip in zip(two_nodes.temp_dirs, two_nodes.ips, strict=True):
        raylet = temp_dir / "session_latest" / "logs" / "raylet.out"
        assert f"node_manager address: {ip}:" in raylet.read_text(), f"no session of the node at {ip} in {temp_dir}"
    seen_by_second = Path(f"/proc/{two_nodes.nodes[1].pid}/root") / tmp_path.relative_to("/")
    assert list(seen_by_second.iterdir()) == []
