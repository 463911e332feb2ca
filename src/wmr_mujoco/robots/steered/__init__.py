"""The steered family: what the centred-steerable-wheel robots share.

The builder parts (a fork on a vertical steering hinge carrying a driven wheel, the chassis
plate), the parameters' shared checks (``params.py``) and the analytic model of the two
steered classes (the (2,1) Chaplygin sleigh and the (1,2) double-steer kinematics), used
by ``robots/single_steer/`` and ``robots/double_steer/``. No registry entry of its own.
"""
