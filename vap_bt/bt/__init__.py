"""Behaviour trees: the plan → py_trees compiler, its behaviours and decorators, the closed loop."""
