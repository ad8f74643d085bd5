# class: guard_bypass
# expect: contained
# attack: import_from's sys.modules fallback on the typing namespace (named "typing"): typing.io and typing.re are in sys.modules on 3.11
from typing import io
from typing import re
print(io, re)
print(io.IO, re.Pattern, re.Match)
