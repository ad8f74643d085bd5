# class: lazy_iterator
# expect: contained
# attack: a range of a billion numbers (three ints on the wire) given as a position vector: the tools' side converts it to an array in one C call (a list of 10**9 ints, then 8 GB of floats)
table = get_3d_bbox("table")
try:
    get_plane_normal("table", range(10 ** 9))
except Exception as exc:
    print("refused:", str(exc)[:200])
try:
    parse_place_pose("apple", position=range(3 * 10 ** 8))
except Exception as exc:
    print("refused:", str(exc)[:200])
