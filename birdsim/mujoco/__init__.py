"""The MuJoCo side of birdsim: the articulated bird (MJCF built from the Bird), the
kinematic wing driver, the passive aerodynamic callback and the force cross-check.

Modules: :mod:`.model` (MjSpec -> MjModel, names, ``models/*.xml``), :mod:`.driver`
(analytic joint angles -> qpos/qvel/qacc), :mod:`.callback` (blade-element forces via
``mjcb_passive``), :mod:`.crosscheck` (MuJoCo's mean force against ``evaluate_cycle``).
The package name shadows the ``mujoco`` library only for relative imports; inside
birdsim import the library as ``import mujoco`` (absolute imports are the default).
"""
