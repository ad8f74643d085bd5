"""RoboScript: free-form instructions to robot programs, run in MuJoCo or on a real arm."""

from roboscript._gl import choose_gl_backend
from roboscript._threads import calm_thread_pools

choose_gl_backend()
calm_thread_pools()

__version__ = "0.1.0"
