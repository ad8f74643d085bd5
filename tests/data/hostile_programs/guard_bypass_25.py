# class: guard_bypass
# expect: contained
# attack: typing's aliases forward attribute assignment to their origin (_BaseGenericAlias.__setattr__ calls setattr(self.__origin__, ...)): typing.Mapping.get = f replaces collections.abc.Mapping.get (and .keys/.items, Sequence.index...) for every Mapping subclass in the program's process, os.environ included; and `from typing import io, re` reach the deprecated typing.io / typing.re classes through import_from's sys.modules fallback (the namespace is named "typing")
from typing import Mapping, Sequence, io, re


def spy(self, key, default=None):
    print("Mapping.get called on", repr(self)[:80], "for", key)
    return "planted"


Mapping.get = spy
Sequence.count = spy
print("typing.io:", io, io.IO, io.TextIO)
print("typing.re:", re, re.Pattern)
io.IO.read = spy
print("IO.read replaced:", io.IO.read is spy, "Mapping.get replaced:", Mapping.get is spy)
