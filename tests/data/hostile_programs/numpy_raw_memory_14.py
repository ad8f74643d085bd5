# class: numpy_raw_memory
# expect: contained
# attack: ways to an array of records or raw bytes past the argument check: a dtype argument that is an object of
# attack: the program's whose .dtype property numpy follows (the check sees neither a str nor a dtype, and the
# attack: property runs program code inside numpy's conversion), raw scalar classes reached through a.dtype.type
# attack: (np.object_, np.bytes_), byteswap(inplace=True) on an object array (its pointers), Generator.permuted into
# attack: an object out= array, and void/record casts through methods the wrapper does not see.
class D:
    def __init__(self, spec):
        self.spec = spec
    @property
    def dtype(self):
        print("dtype property read by numpy")
        return self.spec
def t(name, f):
    try:
        r = f()
        print(name, "->", repr(r)[:120])
    except Exception as e:
        print(name, "!!", repr(e)[:110])
x = np.arange(4)
o = x.cumsum(dtype="O")
t("zeros D(V8)", lambda: np.zeros(2, dtype=D("V8")))
t("zeros D(rec O)", lambda: np.zeros(2, dtype=D([("a", "O"), ("b", "i8")])))
t("astype D(V8)", lambda: x.astype(D("V8")))
t("astype D(O,i8)", lambda: x.astype(D("O,i8")))
t("sum dtype D", lambda: x.sum(dtype=D("V8")))
t("cumsum dtype D", lambda: x.cumsum(dtype=D("O")))
t("object_", lambda: o.dtype.type([1, None]))
t("bytes_", lambda: np.array([b"abcdefgh"]).dtype.type(b"\x00" * 8))
t("byteswap", lambda: o.copy().byteswap(inplace=True))
t("permuted out", lambda: np.random.default_rng(0).permuted(x, out=o.copy()))
t("S8 to int", lambda: np.array([b"12345678"]).astype("i8"))
t("S8 to V8", lambda: np.array([b"12345678"]).astype("V8"))
t("asarray D", lambda: np.asarray(x, dtype=D("V8")))
t("mean D", lambda: np.mean(x, dtype=D("O")))
