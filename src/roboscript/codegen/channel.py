"""Framed messages over one socket between a program's process and the tools: a length, then JSON.

Both ends read with a bound on a frame's size; the tools' end, whose descriptor does not block, also reads and
writes with a deadline, so that a silent or misbehaving program's process cannot hold it. The program's end blocks:
only ``read`` and ``write`` touch its socket, the two calls a confined process keeps for it
(:mod:`roboscript.codegen.confinement`).
"""

from __future__ import annotations

import json
import os
import select
import struct
import time

from roboscript.errors import RoboScriptError

HEADER = struct.Struct(">I")


class ChannelClosed(RoboScriptError, EOFError):
    """The other end closed the socket (or died) before a whole frame arrived."""


class ChannelError(RoboScriptError, ValueError):
    """A frame that breaks the protocol: too large, or not a JSON object."""


class ChannelTimeout(RoboScriptError, TimeoutError):
    """No whole frame arrived before the deadline."""


def send(fd: int, message: dict) -> None:
    """Writes ``message`` as one frame."""
    send_raw(fd, json_bytes(message))


def json_bytes(message: dict) -> bytes:
    """``message`` as the JSON a frame carries."""
    return json.dumps(message, separators=(",", ":"), allow_nan=True).encode()


def send_raw(fd: int, data: bytes, deadline: float | None = None) -> None:
    """Writes ``data`` (JSON already) as one frame; on a non-blocking descriptor, waiting until ``deadline`` at
    most for the other end to take it (:class:`ChannelTimeout`)."""
    view = memoryview(HEADER.pack(len(data)) + data)
    while view:
        if deadline is not None:
            left = max(deadline - time.monotonic(), 0.0)
            if not select.select([], [fd], [], left)[1]:
                raise ChannelTimeout(f"the other end took {len(data) + HEADER.size - len(view)} of {len(data)} bytes")
        try:
            view = view[os.write(fd, view) :]
        except BlockingIOError:
            continue


def receive(fd: int, limit: int, deadline: float | None = None) -> dict:
    """The next frame's JSON object; at most ``limit`` bytes, before ``deadline`` (``time.monotonic``) if given."""
    data = receive_raw(fd, limit, deadline)
    try:
        message = json.loads(data)
    except (ValueError, RecursionError) as exc:
        raise ChannelError(f"a frame that is not JSON: {type(exc).__name__}: {str(exc)[:200]}") from None
    if not isinstance(message, dict):
        raise ChannelError(f"a frame that is not a JSON object but a {type(message).__name__}")
    return message


def receive_raw(fd: int, limit: int, deadline: float | None = None) -> bytes:
    """The next frame's bytes; :class:`ChannelError` if it announces more than ``limit``."""
    (length,) = HEADER.unpack(_read_exactly(fd, HEADER.size, deadline))
    if length > limit:
        raise ChannelError(f"a frame of {length} bytes; at most {limit}")
    return _read_exactly(fd, length, deadline)


def _read_exactly(fd: int, size: int, deadline: float | None) -> bytes:
    chunks, got = [], 0
    while got < size:
        if deadline is not None:
            left = max(deadline - time.monotonic(), 0.0)
            if not select.select([fd], [], [], left)[0]:
                raise ChannelTimeout(f"no message within the deadline ({got} of {size} bytes arrived)")
        try:
            chunk = os.read(fd, min(size - got, 1 << 20))
        except BlockingIOError:  # a non-blocking descriptor that select called ready too early
            continue
        if not chunk:
            raise ChannelClosed(f"the other end closed the channel ({got} of {size} bytes arrived)")
        chunks.append(chunk)
        got += len(chunk)
    return b"".join(chunks)
