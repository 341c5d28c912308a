"""vap_bt — a behaviour-tree executive that carries out PDDL plans and checks them by looking.

The package follows the flow of one run, one folder per room:

* :mod:`vap_bt.domain`     — action knowledge (PDDL through unified-planning) and the planner.
* :mod:`vap_bt.scene`      — the scene graph: objects and the ground facts believed about them.
* :mod:`vap_bt.perception` — vision-language models, prompt data and active perception.
* :mod:`vap_bt.bt`         — plan → py_trees compiler, behaviours, decorators, the closed loop.
* :mod:`vap_bt.robot`      — what a robot's drivers offer: arm, gripper, base, wrist camera.
* :mod:`vap_bt.transport`  — the wire: Zenoh keys, messages, skill client and skill server.
* :mod:`vap_bt.motion`     — IK, time-optimal timing and online tracking (pure array code).
* :mod:`vap_bt.sim`        — worlds: the fast symbolic one and the pybullet household.
* :mod:`vap_bt.viz`        — rerun logging; the only room that imports rerun.
* :mod:`vap_bt.app`        — the composition root: the command line and the set-ups that wire
  the rooms into processes; nothing imports it back.

:mod:`vap_bt.world` and :mod:`vap_bt.skill` are the two contracts between the rooms.
"""

from vap_bt import numerics as _numerics  # noqa: F401  (pins numpy's BLAS kernels before anything loads numpy)

__version__ = "0.1.0"
