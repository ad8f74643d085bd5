# class: pickle_into_trusted
# expect: contained
# attack: random generators and seed sequences built from a 20000-bit seed and a tampered state, passed to tools so their reconstruction (constructors, __setstate__) runs on the tools' side
seed = (1 << 20_000) - 12345
rng = np.random.default_rng(seed)
rng.bit_generator.state = {"bit_generator": "PCG64", "state": {"state": 3, "inc": 5}, "has_uint32": 1, "uinteger": 9}
children = rng.spawn(3)
sequence = rng.bit_generator.seed_seq
for value in (rng, rng.bit_generator, sequence, children, [sequence] * 1000):
    try:
        detect_objects([value])
    except Exception as exc:
        print("refused:", str(exc)[:120])
    try:
        get_plane_normal("table", value)
    except Exception as exc:
        print("refused:", str(exc)[:120])
