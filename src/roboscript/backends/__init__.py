"""Robot backends: the interface and its implementations."""

from roboscript.backends.base import Backend, BackendError

__all__ = ["Backend", "BackendError"]
