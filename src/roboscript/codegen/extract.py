"""Getting the program out of a model's answer."""

from __future__ import annotations

import re

_FENCE = re.compile(r"```[ \t]*(?:python|py)?[ \t]*\n(.*?)(?:```|\Z)", re.DOTALL | re.IGNORECASE)


def extract_code(text: str) -> str:
    """The code in ``text``: its fenced blocks joined (an unterminated last fence counts), else the whole text."""
    blocks = [b.strip("\n") for b in _FENCE.findall(text)]
    code = "\n\n".join(b for b in blocks if b.strip()) if blocks else text
    return code.strip("\n") + "\n"
