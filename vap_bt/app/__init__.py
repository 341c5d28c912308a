"""The composition root: the one room that knows which parts exist and wires them together.

Everything below it is a component with one job — the domain's knowledge and planner
(:mod:`vap_bt.domain`), the scene graph (:mod:`vap_bt.scene`), perception, the behaviour
tree (:mod:`vap_bt.bt`), skills, the wire (:mod:`vap_bt.transport`) and the worlds
(:mod:`vap_bt.sim`). This room picks one of each for a run and connects them, and nothing
below imports it back:

* :mod:`.runner`        — an episode: a task, a world, skills, robot interfaces, a VLM, the executive.
* :mod:`.arguments`     — each command's flags, derived from the settings' declarations (:mod:`vap_bt.settings`).
* :mod:`.inprocess`     — skills and robot interfaces in the executive's own process.
* :mod:`.embedded`      — the default: skill servers and the executive in one command, over Zenoh.
* :mod:`.connected`     — the executive against parts that run elsewhere (``--connect``).
* :mod:`.serve`         — ``vap-bt serve`` / ``vap-bt skills``: one robot's skill servers.
* :mod:`.world_factory` — the world a ``serve`` binds its skills to.
* :mod:`.remote_robot`  — a robot whose world runs in another process.
* :mod:`.locked_world`  — a world shared by several server threads, one call at a time.
* :mod:`.sim_host`      — ``vap-bt sim``: the pybullet world in a process of its own.
* :mod:`.launch`        — ``vap-bt launch``: a connected set-up's parts started and stopped as one.
* :mod:`.census`        — ``vap-bt parts``: who is on the network, from liveliness tokens.
"""
