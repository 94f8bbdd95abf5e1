"""libmujoco's C functions for compiled code: numba ``ExternalFunction`` declarations.

The mujoco Python package ships ``libmujoco.so``; loading it into LLVM's symbol table
(``llvmlite.binding.load_library_permanently``) lets a numba function call its C
functions by name, so a compiled loop can step MuJoCo without returning to Python.
The calls are resolved when numba links the function, also when it loads it from its
on-disk cache (``cache=True`` works: no address is baked into the cached code).

Arguments: ``mjModel*`` and ``mjData*`` are the Python objects' ``_address``
(integers), arrays are passed by their data address (``arr.ctypes.data`` in numba), C
``int`` as int32.  On x86-64 and arm64 a pointer and a 64-bit integer travel in the same
register, which is what declaring them ``intp`` relies on.

:data:`AVAILABLE` is False when numba or the library is missing; the callers then keep
the Python path.
"""

from __future__ import annotations

import glob
import os

import mujoco

from birdsim.physics.jit import numba

#: mjtObj's mjOBJ_SITE (the object type of mj_objectVelocity)
OBJ_SITE = int(mujoco.mjtObj.mjOBJ_SITE)


def _library() -> str | None:
    here = os.path.dirname(mujoco.__file__)
    found = sorted(glob.glob(os.path.join(here, "libmujoco.so*")))
    found += sorted(glob.glob(os.path.join(here, "libmujoco*.dylib")))
    return found[0] if found else None


AVAILABLE = False
if numba is not None:  # pragma: no branch
    try:
        import llvmlite.binding as _llvm
        from numba import types as _t

        _lib = _library()
        if _lib is not None:
            _llvm.load_library_permanently(_lib)
            _p, _i = _t.intp, _t.int32
            mj_step1 = _t.ExternalFunction("mj_step1", _t.void(_p, _p))
            mj_step2 = _t.ExternalFunction("mj_step2", _t.void(_p, _p))
            mj_fwdPosition = _t.ExternalFunction("mj_fwdPosition", _t.void(_p, _p))
            mj_fwdVelocity = _t.ExternalFunction("mj_fwdVelocity", _t.void(_p, _p))
            #: mj_fullM(m, d, dst)
            mj_fullM = _t.ExternalFunction("mj_fullM", _t.void(_p, _p, _p))
            #: mj_objectVelocity(m, d, objtype, objid, res[6], flg_local)
            mj_objectVelocity = _t.ExternalFunction(
                "mj_objectVelocity", _t.void(_p, _p, _i, _i, _p, _i)
            )
            #: mj_mulM(m, d, res, vec): res = M vec
            mj_mulM = _t.ExternalFunction("mj_mulM", _t.void(_p, _p, _p, _p))
            #: mj_applyFT(m, d, force[3], torque[3], point[3], body, qfrc_target)
            mj_applyFT = _t.ExternalFunction("mj_applyFT", _t.void(_p, _p, _p, _p, _p, _i, _p))
            AVAILABLE = True
    except Exception:  # pragma: no cover - a broken llvmlite: the Python path runs
        AVAILABLE = False

__all__ = ["AVAILABLE", "OBJ_SITE"]
