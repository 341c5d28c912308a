"""Worlds: the fast symbolic one over ground facts and the physical pybullet household."""
