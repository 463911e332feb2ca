"""Closed-loop tasks on a stepped robot, and the validation scenarios that judge them.

:mod:`.tracking` (a controller on a path, physics beside the kinematic model),
:mod:`.bracket` (the Lie-bracket parking cycle), :mod:`.upright` (the Whipple bicycle
kept upright after a push) and :mod:`.families` (their judged scenario families, added
to every robot's registry entry from its command map).
"""
