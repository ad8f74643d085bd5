# class: unbounded_trusted_work
# expect: contained
# attack: a 2**29-leaf shared-reference list of numbers as a direction: np.asarray(dtype=float) on the tools' side allocates and fills 4 GB without a signal check
leaf = [0.5]
for level in range(29):
    leaf = [leaf, leaf]
try:
    move_in_direction(leaf, 0.05)
except Exception as exc:
    print("refused:", str(exc)[:200])
