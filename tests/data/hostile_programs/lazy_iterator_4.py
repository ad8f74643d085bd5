# class: lazy_iterator
# expect: contained
# attack: a map whose only item is repr() of a 2**28-leaf list built from shared references: small to send, the tools' side makes the giant string when it pulls the first name
leaf = ["apple"]
for level in range(28):
    leaf = [leaf, leaf]
try:
    detect_objects(map(repr, [leaf]))
except Exception as exc:
    print("refused:", str(exc)[:200])
try:
    detect_objects(map(str, [leaf, leaf]))
except Exception as exc:
    print("refused:", str(exc)[:200])
