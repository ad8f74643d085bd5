# class: numpy_raw_memory
# expect: contained
# attack: `x.astype(...)` is checked only when x is an array or a numpy scalar: called on the scalar type itself (np.float64.astype(value, dtype), the unbound method) it is not, and makes raw void scalars (a float's bytes as V8) and records with object fields; then np.void (the scalar's dtype.type) reads raw bytes into a record of objects, and a void scalar's bytes go back through astype to objects (repr of a void scalar imports numpy._core.arrayprint through the program's own __import__, and fails)
v = np.float64.astype(np.float64(5e-324), 'V8')
record = np.float64.astype(np.float64(1.0), [('a', 'O'), ('b', '<f8')])
void_type = v.dtype.type
out = [v.dtype.str, record.dtype.names, record['b'], repr(void_type)]
for attempt in (lambda: void_type(v, dtype=[('a', 'O')]), lambda: void_type.astype(v, [('a', 'O')]),
                lambda: void_type.astype(v, 'O'), lambda: void_type(b'\x10' * 8, dtype=[('a', 'O')])):
    try:
        r = attempt()
        out.append(r.dtype.names if isinstance(r, np.ndarray) or repr(r).startswith('np.void') else r)
    except Exception as exc:
        out.append('refused: ' + str(exc)[:80])
print(out)
