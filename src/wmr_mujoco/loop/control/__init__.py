"""Reference paths and feedback controllers: pure math on a robot's state.

One concept per module: :mod:`.paths` (reference paths), :mod:`.base` (the controller
interface), the controllers (:mod:`.go_to_pose`, :mod:`.pure_pursuit`, :mod:`.stanley`,
:mod:`.kanayama`, :mod:`.holonomic`, :mod:`.whipple_lean`) and :mod:`.registry` (the
controllers by name, built from a robot's command channels). Public names are also
importable from :mod:`wmr_mujoco.control`'s modules of the same names.
"""
