"""Motion: kinematics, IK, time-optimal path timing and online jerk-limited tracking.

Pure array code over pinocchio, coal, toppra and ruckig; nothing here imports pybullet or
py_trees, so the same functions drive the simulated and a real robot.

* :mod:`~vap_bt.motion.se3`        — 4x4 pose helpers
* :mod:`~vap_bt.motion.limits`     — joint limits from the robot's YAML
* :mod:`~vap_bt.motion.kinematics` — pinocchio model of a joint chain, FK
* :mod:`~vap_bt.motion.collision`  — self and scene-box collision checks (coal)
* :mod:`~vap_bt.motion.ur_analytic` — closed-form UR solutions, used to seed IK
* :mod:`~vap_bt.motion.ik`         — damped-least-squares IK with seeds and collision rejection
* :mod:`~vap_bt.motion.trajectory` — the sampled trajectory type and limit checks
* :mod:`~vap_bt.motion.timing`     — toppra timing of paths through waypoints
* :mod:`~vap_bt.motion.tracking`   — ruckig point-to-point and online tracking (arm and base)
"""
