"""The wire: how goals reach skills and observations come back over Zenoh.

* :mod:`.execution`      — running one goal on a skill: context, cancel flag, terminal state
  (the same code serves a Zenoh server and the in-process client of :mod:`vap_bt.app.inprocess`).
* :mod:`.keys`           — the Zenoh key expressions, namespaced per robot.
* :mod:`.messages`       — the versioned wire schema (goals, status, observations).
* :mod:`.config`         — Zenoh session configuration: loopback by default, files passed through.
* :mod:`.server`         — :class:`SkillServer`: hosts one robot's skills and its camera.
* :mod:`.client`         — :class:`ZenohSkillClient`, :class:`ZenohRobot`, :class:`ZenohVLM`.
* :mod:`.drivers`        — a robot's drivers served and used over Zenoh.
* :mod:`.world_hooks`    — the sim-only action hook of Table II injection, over Zenoh.
* :mod:`.world_services` — the world-side VLM and oracle a simulator offers over Zenoh.

Which processes exist and how they are wired together (``vap-bt run``'s embedded and connected
set-ups, ``serve``, ``sim``, ``launch``, ``parts``) is :mod:`vap_bt.app`'s, not this room's:
nothing here imports it back.
"""
