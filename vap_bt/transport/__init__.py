"""Getting goals to skills and observations back, in-process or over Zenoh.

* :mod:`.execution`  — running one goal on a skill: context, cancel flag, terminal state.
* :mod:`.inprocess`  — :class:`InProcessSkillClient` / :class:`InProcessCamera`, the fast path.
* :mod:`.keys`       — the Zenoh key expressions, namespaced per robot.
* :mod:`.messages`   — the versioned wire schema (goals, status, observations).
* :mod:`.config`     — Zenoh session configuration: loopback by default, files passed through.
* :mod:`.server`     — :class:`SkillServer`: hosts one robot's skills and its camera.
* :mod:`.client`     — :class:`ZenohSkillClient` / :class:`ZenohCamera`.
* :mod:`.serve`      — the ``vap-bt serve`` and ``vap-bt skills`` commands.
* :mod:`.launch`     — ``vap-bt launch``: a connected set-up's parts started and stopped as one.
* :mod:`.census`     — ``vap-bt parts``: the parts and goals on the network, from liveliness.

Behaviours only see the :class:`~vap_bt.skill.SkillClient` and :class:`~vap_bt.skill.Camera`
protocols, so they cannot tell the two paths apart.
"""
