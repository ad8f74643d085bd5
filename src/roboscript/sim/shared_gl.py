"""GL renderers kept across the worlds a process builds, and whether they may be kept across a fork.

Making a renderer costs a third of a second on a CPU rasteriser (a GL context, every mesh uploaded, the rasteriser's
shaders compiled at the first renders): a good part of a short trial. What a GL context holds of a model (meshes,
textures, height fields, skins) does not change with where the objects stand, so a renderer made for one build of a
world renders any other build of it (another seed) as well: :func:`gl_renderer` hands out the one kept for a
model of the same geometry and size, once :func:`share_renderers` has been called.

A benchmark worker (:mod:`roboscript.bench.workers`) makes them and forks each trial from there. That is sound only
where the GL driver keeps no threads and no device handles that a fork would lose: Mesa's software rasteriser with
its threads off (``LP_NUM_THREADS=0``), which :func:`fork_safe` checks in a throwaway process so that a GPU driver
is never started in the process that forks.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import select
import signal
from collections.abc import Callable

import mujoco

from roboscript.kept import Kept

SOFTWARE_GL_THREADS = "LP_NUM_THREADS"  # Mesa's software rasteriser's thread count; 0 keeps GL state forkable
SOFTWARE_RENDERERS = ("llvmpipe", "softpipe")  # Mesa's CPU rasterisers, as glGetString(GL_RENDERER) names them
PROBE_TIMEOUT = 30.0  # seconds a probe may take to make a context before GL counts as unsafe to fork
KEPT_RENDERERS = 8  # renderers a sharing process keeps (some 80 MB each); the least recently used is closed past that

_shared: Kept[mujoco.Renderer] | None = None  # None: renderers are not shared in this process


def geometry_key(model: mujoco.MjModel) -> str:
    """A digest of everything a GL context holds of ``model``: two models with the same key render with the same
    context."""
    digest = hashlib.blake2b(digest_size=16)
    for name in (
        "mesh_vertadr", "mesh_vertnum", "mesh_faceadr", "mesh_facenum", "mesh_vert", "mesh_face", "mesh_normal",
        "mesh_texcoord", "mesh_facenormal", "mesh_facetexcoord", "tex_type", "tex_height", "tex_width", "tex_data",
        "hfield_size", "hfield_nrow", "hfield_ncol", "hfield_data", "skin_vertnum", "skin_vert", "skin_face",
    ):  # fmt: skip
        digest.update(getattr(model, name).tobytes())
    return digest.hexdigest()


def share_renderers() -> None:
    """From now on, :func:`gl_renderer` keeps the renderers it makes in this process and hands them out again."""
    global _shared
    if _shared is None:
        _shared = Kept(KEPT_RENDERERS, give_up=lambda renderer: renderer.close())


def stop_sharing() -> None:
    """Closes the renderers kept and makes them afresh for each user again."""
    global _shared
    if _shared is not None:
        _shared.clear()
    _shared = None


def sharing() -> bool:
    """Whether this process shares renderers (see :func:`share_renderers`)."""
    return _shared is not None


def gl_renderer(
    model: mujoco.MjModel, width: int, height: int, antialiasing: bool, make: Callable[[], mujoco.Renderer]
) -> tuple[mujoco.Renderer, bool]:
    """A GL renderer for ``model`` at that size: the one kept for a model of the same geometry where renderers are
    shared, else one from ``make``. Returns it and whether it is shared (a shared one is never closed by its user).

    A shared renderer's model is whichever its last user rendered: the user sets it before each render."""
    if _shared is None:
        return make(), False
    return _shared.get((geometry_key(model), width, height, antialiasing), make), True


def fork_safe() -> bool:
    """Whether GL state made in this process still works in a child forked from it: MuJoCo renders offscreen with
    Mesa's software rasteriser (EGL or OSMesa) and ``LP_NUM_THREADS`` is 0. Found out in a throwaway child, which
    makes a small context and reads the renderer's name, so that this process starts no GL driver."""
    if os.environ.get("MUJOCO_GL") not in ("egl", "osmesa") or os.environ.get(SOFTWARE_GL_THREADS) != "0":
        return False
    reader, writer = os.pipe()
    pid = os.fork()
    if pid == 0:  # the probe
        code = 1
        try:
            os.close(reader)
            os.write(writer, _renderer_name().encode()[:200])
            code = 0
        finally:
            os._exit(code)
    os.close(writer)
    try:
        ready, _, _ = select.select([reader], [], [], PROBE_TIMEOUT)
        name = os.read(reader, 256).decode(errors="replace") if ready else ""
    finally:
        os.close(reader)
        if not name:
            _kill_quietly(pid)
        os.waitpid(pid, 0)
    return any(software in name.lower() for software in SOFTWARE_RENDERERS)


def _renderer_name() -> str:
    from OpenGL import GL

    model = mujoco.MjModel.from_xml_string("<mujoco><worldbody><geom size='0.1'/></worldbody></mujoco>")
    with mujoco.Renderer(model, 8, 8):
        return (GL.glGetString(GL.GL_RENDERER) or b"").decode(errors="replace")


def _kill_quietly(pid: int) -> None:
    with contextlib.suppress(ProcessLookupError):
        os.kill(pid, signal.SIGKILL)
