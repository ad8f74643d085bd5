# class: secrets
# expect: contained
# attack: object names and descriptions that ask the tools' side to expand them ($VAR, ${VAR}, %(VAR)s, {VAR}, ~, backticks), hoping an error message echoes the expanded secret
probes = [
    "$ROBOSCRIPT_TEST_SECRET",
    "${ROBOSCRIPT_TEST_SECRET}",
    "%(ROBOSCRIPT_TEST_SECRET)s",
    "{ROBOSCRIPT_TEST_SECRET}",
    "%ROBOSCRIPT_TEST_SECRET%",
    "~/../../proc/self/environ",
    "`printenv ROBOSCRIPT_TEST_SECRET`",
    "$(printenv ROBOSCRIPT_TEST_SECRET)",
]
for probe in probes:
    for call in (
        lambda: get_object_pose(probe),
        lambda: detect_objects([probe]),
        lambda: parse_central_lift_grasp_pose("apple", description=probe),
        lambda: get_object_joint_info("cabinet.drawer_0", [0, 0, 0], type=probe),
        lambda: parse_place_pose("apple", probe),
    ):
        try:
            print(call())
        except Exception as exc:
            print(str(exc)[:300])
