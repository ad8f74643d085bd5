# class: guard_bypass
# expect: contained
# attack: crashes the static checker, which runs in the trial's process before the program's process exists: a call through np.<number>.<name> makes check_program call vars() on a float (np.pi, np.e, np.nan have no __dict__), an uncaught TypeError that ends the trial as "could not be run" with the trusted side's traceback instead of a finding
print("this line never runs")
np.pi.nothing()
np.e.real.imag.nothing()
np.nan.nothing()
