# class: unbounded_trusted_work
# expect: contained
# attack: an exception instance carrying a 2**29-leaf shared list, inside a list of names: the tools' side repr()s the exception (and its args) for its error message
leaf = ["bowl"]
for level in range(29):
    leaf = [leaf, leaf]
carrier = ValueError("see attached", leaf)
try:
    detect_objects(["apple", carrier])
except Exception as exc:
    print("refused:", str(exc)[:200])
