# class: output_flood
# expect: contained
# attack: numpy run-time warnings with as many distinct texts as it can make (every ufunc, every kind of floating-point error) on many lines, in case warnings go to a shared stderr
zero = np.zeros(3)
big = np.full(3, 1e308)
neg = -np.ones(3)
functions = [np.log, np.log2, np.log10, np.sqrt, np.arcsin, np.arccos, np.exp, np.square, np.tan, np.arctan2, np.hypot, np.mod, np.floor, np.rint]
for round_ in range(50):
    for f in functions:
        for x in (zero, big, neg, zero / zero):
            try:
                f(x)
            except Exception:
                pass
            try:
                f(x, x)
            except Exception:
                pass
    a = zero / zero
    b = big * big
    c = 1 / zero
    d = np.mean(np.array([]))
    e = np.std(np.array([]))
    g = np.var(np.ones(1), ddof=5)
    h = np.percentile(np.array([np.nan]), 50)
print("done")
