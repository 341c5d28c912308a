"""The built-in skill plugins: one small class per action of the household domain.

They are registered under the entry-point group ``vap_bt.skills`` in ``pyproject.toml`` exactly as
a third-party distribution would register its own (see ``docs/plugins.md``); nothing in the
executive imports this package by name. Every built-in skill hands its action to the world it is
bound to (:class:`skills.base.WorldActionSkill`), so the same classes drive the symbolic world,
the pybullet household and, later, a real robot's world adapter.
"""
