# class: lazy_iterator
# expect: contained
# attack: endless iterators made of builtins (iter(str, sentinel), filter over a huge range, map over count-like ranges) passed where tools iterate a list of names or poses
endless = [
    iter(str, "never"),
    filter(None, range(1, 10 ** 18)),
    map(str, range(10 ** 18)),
    zip(map(str, range(10 ** 18))),
    enumerate(iter(str, "never")),
    reversed(range(10 ** 18)),
]
for value in endless:
    for call in (lambda: detect_objects(value), lambda: follow_path(value), lambda: detect_objects(object_list=value)):
        try:
            call()
            print("returned")
        except Exception as exc:
            print("refused:", str(exc)[:100])
