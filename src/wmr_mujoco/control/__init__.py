"""Closing the loop: reference paths, feedback controllers, and their runs on both backends.

One concept per module: :mod:`.paths` (reference paths), :mod:`.base` (the controller
interface), the controllers (:mod:`.go_to_pose`, :mod:`.pure_pursuit`, :mod:`.stanley`,
:mod:`.kanayama`, :mod:`.holonomic`, :mod:`.whipple_lean`).
"""
