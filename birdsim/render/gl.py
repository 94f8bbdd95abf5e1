"""Headless OpenGL back-end for MuJoCo's offscreen renderer: OSMesa or EGL.

MuJoCo picks its GL back-end from ``MUJOCO_GL`` when it is first imported, and
PyOpenGL picks its platform from ``PYOPENGL_PLATFORM`` at its first import.  Call
:func:`select_gl` before anything imports :mod:`mujoco`; it checks that the system
library really loads (without OSMesa, ``import mujoco`` under ``MUJOCO_GL=osmesa``
dies with an obscure PyOpenGL AttributeError), sets both variables and returns the
back-end's name.

``auto`` = ``MUJOCO_GL`` when it already names osmesa or egl and that library loads
(the user's choice, or this process's earlier one), else OSMesa when ``libOSMesa``
loads (the design's default), else EGL.  When
:mod:`mujoco` was already imported with another back-end, :func:`select_gl` points
MuJoCo's renderer at the chosen back-end's context class, or says in one line that
it cannot.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os
import sys

from birdsim.errors import BirdsimError

#: Allowed values of ``--gl``.
GL_CHOICES = ("auto", "osmesa", "egl")

#: Per back-end: the shared library MuJoCo needs and the Debian packages that bring it.
_LIBRARIES = {
    "osmesa": ("OSMesa", "libOSMesa.so", "libosmesa6"),
    "egl": ("EGL", "libEGL.so", "libegl1 libegl-mesa0"),
}


class GLError(BirdsimError):
    """No usable headless OpenGL back-end (names the missing system library)."""


def library_available(backend: str) -> bool:
    """Whether the system library of ``backend`` ("osmesa" or "egl") can be loaded."""
    short, soname, _ = _LIBRARIES[backend]
    candidates = [
        ctypes.util.find_library(short),
        f"{soname}.8",
        f"{soname}.1",
        f"{soname}.6",
        soname,
    ]
    for name in candidates:
        if not name:
            continue
        try:
            ctypes.CDLL(name)
        except OSError:
            continue
        return True
    return False


def missing_message(backend: str) -> str:
    short, soname, debian = _LIBRARIES[backend]
    return f"--gl {backend}: the system library {soname} ({short}) is not installed; install it with `apt-get install {debian}` (or run scripts/setup_gl.sh as root)"


def resolve_gl(requested: str = "auto") -> str:
    """The back-end that ``--gl requested`` means on this machine, or one clear error."""
    if requested not in GL_CHOICES:
        raise GLError(f"--gl {requested!r} is unknown; allowed: {', '.join(GL_CHOICES)}")
    if requested != "auto":
        if not library_available(requested):
            raise GLError(missing_message(requested))
        return requested
    preset = os.environ.get("MUJOCO_GL", "").strip().lower()
    if preset in ("osmesa", "egl") and library_available(preset):
        return preset  # the user's (or this process's earlier) choice stands
    for backend in ("osmesa", "egl"):
        if library_available(backend):
            return backend
    raise GLError(
        "--gl auto: neither libOSMesa.so (Debian: libosmesa6) nor libEGL.so (Debian: libegl1 libegl-mesa0) "
        "is installed; install one, e.g. `apt-get install libosmesa6` (scripts/setup_gl.sh does it as root)"
    )


def select_gl(requested: str = "auto") -> str:
    """Choose the back-end for ``requested`` and make MuJoCo use it; returns its name."""
    backend = resolve_gl(requested)
    if "mujoco" not in sys.modules:
        os.environ["MUJOCO_GL"] = backend
        os.environ["PYOPENGL_PLATFORM"] = backend
        return backend
    _retarget_loaded_mujoco(backend)
    return backend


def active_gl() -> str | None:
    """The back-end MuJoCo's renderer will use now (None when undecided)."""
    if "mujoco" not in sys.modules:
        return os.environ.get("MUJOCO_GL")
    ctx = _context_module()
    cls = getattr(ctx, "GLContext", None) if ctx else None
    if cls is None:
        return None
    mod = cls.__module__
    for backend in ("osmesa", "egl", "glfw"):
        if f".{backend}" in mod:
            return backend
    return mod


def _context_module():  # the module whose ``GLContext`` mujoco.Renderer instantiates
    try:
        from mujoco.rendering.classic import gl_context
    except ImportError:  # older MuJoCo
        try:
            from mujoco import gl_context  # type: ignore[no-redef]
        except ImportError:
            return None
    return gl_context


def _retarget_loaded_mujoco(backend: str) -> None:
    """MuJoCo is already imported: swap its renderer's context class if needed."""
    if active_gl() == backend:
        return
    platform = os.environ.get("PYOPENGL_PLATFORM")
    opengl_loaded = "OpenGL.platform" in sys.modules
    if opengl_loaded and platform and platform.lower() != backend:
        raise GLError(
            f"--gl {backend}: this process already loaded OpenGL for {platform!r}; "
            f"start it with MUJOCO_GL={backend} PYOPENGL_PLATFORM={backend}"
        )
    os.environ["PYOPENGL_PLATFORM"] = backend
    os.environ["MUJOCO_GL"] = backend
    try:
        if backend == "egl":
            from mujoco.egl import GLContext
        else:
            from mujoco.osmesa import GLContext  # type: ignore[no-redef]
    except (ImportError, AttributeError, OSError) as exc:
        raise GLError(
            f"--gl {backend}: MuJoCo's {backend} context cannot be loaded: {exc}"
        ) from None
    ctx = _context_module()
    if ctx is None:
        raise GLError(f"--gl {backend}: this MuJoCo has no offscreen GL context module")
    ctx.GLContext = GLContext
    try:  # mujoco.Renderer keeps its own reference in some versions
        from mujoco.rendering.classic import renderer as _renderer

        if hasattr(_renderer, "GLContext"):
            _renderer.GLContext = GLContext
    except ImportError:
        pass


__all__ = [
    "GLError",
    "GL_CHOICES",
    "active_gl",
    "library_available",
    "missing_message",
    "resolve_gl",
    "select_gl",
]
