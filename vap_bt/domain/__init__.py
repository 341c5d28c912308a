"""Action knowledge: PDDL domains and problems, grounded actions, and the planner."""
