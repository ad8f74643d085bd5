"""``--record``: a trial as an MCAP file, read back with the mcap library's own reader: every tool call with its
answer or error, camera images, perceived boxes, the planning scene, planned and executed paths, the checks."""

import base64
import io
from collections import Counter

from PIL import Image

from roboscript.bench.trial import TrialSpec, run_trial
from roboscript.cli.main import main
from roboscript.record.recording import read_recording

# The apple is grasped and lifted, then placed into a receptacle the world does not have: the trial fails there.
FAILING = """detect_objects()
open_gripper()
grasp_pose = parse_central_lift_grasp_pose(object_name='apple', description='center')
grasp(grasp_pose)
close_gripper()
attach_object('apple')
move_in_direction(direction=[0, 0, 1], distance=0.1)
place_pose = parse_place_pose(object_name='apple', receptacle_name='basket')
move_to_pose(place_pose)
"""


def test_a_recording_of_a_failed_trial_holds_every_tool_call_and_the_scene(tmp_path):
    path = tmp_path / "trial.mcap"
    record = run_trial(TrialSpec("simple_0", "panda", 0, 0, FAILING, record=str(path)))
    assert not record.success and "UnknownObjectError" in record.error
    messages = list(read_recording(path))
    topics = Counter(topic for topic, _, _ in messages)
    calls = [m for topic, _, m in messages if topic == "/tool_calls"]
    assert [c["tool"] for c in calls] == [
        "detect_objects", "open_gripper", "parse_central_lift_grasp_pose", "grasp", "close_gripper",
        "attach_object", "move_in_direction", "parse_place_pose"]  # fmt: skip
    assert calls[2]["arguments"] == ['object_name="apple"', 'description="center"']
    assert calls[2]["answer"].startswith('"Pose(position=Point(') and calls[2]["error"] is None
    assert calls[-1]["error"].startswith("UnknownObjectError: no object named 'basket'")
    assert [c["index"] for c in calls] == list(range(1, 9))
    times = [t for _, t, _ in messages]
    assert times == sorted(times)  # one timeline, simulated seconds
    for camera in ("camera_left", "camera_right", "camera_top"):
        assert topics[f"/camera/{camera}/calibration"] == 1 and topics[f"/camera/{camera}/image"] >= 2
    image = next(m for topic, _, m in messages if topic == "/camera/camera_top/image")
    with Image.open(io.BytesIO(base64.b64decode(image["data"]))) as picture:
        assert picture.format == "JPEG" and picture.width >= 320
    objects = [m for topic, _, m in messages if topic == "/perception/objects"][-1]
    labels = {t["text"] for t in objects["entities"][0]["texts"]}
    assert {"apple", "footed_bowl", "table", "cabinet.drawer_1"} <= labels
    scene = [m for topic, _, m in messages if topic == "/planning_scene"][-1]
    assert len(scene["entities"][0]["cubes"]) >= 5
    planned = [m for topic, _, m in messages if topic == "/paths/planned"]
    assert len(planned) >= 2 and all(len(m["entities"][0]["lines"][0]["points"]) >= 2 for m in planned)
    executed = [m for topic, _, m in messages if topic == "/paths/executed"][-1]
    lifted = [p["z"] for p in executed["entities"][0]["lines"][0]["points"]]
    assert max(lifted) - min(lifted) > 0.08  # the TCP went down to the apple and lifted it 10 cm
    logs = [m for topic, _, m in messages if topic == "/log"]
    assert len(logs) == len(calls) and logs[-1]["level"] == 4  # the failed call is an error line
    (checks,) = [m for topic, _, m in messages if topic == "/checks"]
    assert checks["checks"][0]["check"] == "in(apple, footed_bowl)" and not checks["checks"][0]["passed"]


def test_exec_writes_the_recording_it_is_asked_for(tmp_path):
    program = tmp_path / "p.py"
    program.write_text("detect_objects()\nopen_gripper()\nprint(get_object_center_position('apple'))\n")
    path = tmp_path / "out" / "r.mcap"
    # the program leaves the apple where it is: the task fails (exit status 1), and the trial is recorded all the same
    assert main(["exec", str(program), "--task", "simple_0", "--trials", "1", "--record", str(path)]) == 1
    calls = [m["tool"] for topic, _, m in read_recording(path) if topic == "/tool_calls"]
    assert calls == ["detect_objects", "open_gripper", "get_object_center_position"]
