"""RoboScript: free-form instructions to robot programs, run in MuJoCo or on a real arm."""

from roboscript._gl import choose_gl_backend

choose_gl_backend()

__version__ = "0.1.0"
