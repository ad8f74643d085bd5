# class: swallowed_timeout
# expect: contained
# attack: a loop in numpy's C code that no timer signal interrupts: take(mode="wrap") with index -2**63 adds the
# attack: axis length until the index is non-negative (2**63 / 3 iterations); the program's process must still
# attack: end as a timeout, killed by the tools' side at its limit plus the grace, not run for hours.
a = np.arange(3)
print(a.take([-2**63], mode="wrap"))
