"""Robot interfaces: what a real robot's drivers and its localization offer the executive.

Everything the executive believes comes through these types: RGB-D frames with the detector's
instance masks (:mod:`.frame`), the robot's own state — base pose from localization, joints,
gripper (:mod:`.state`) — and the static map of the site (:mod:`.site_map`). A camera service
(:mod:`.camera`) aims the wrist camera, drives to viewpoints and captures frames. A pybullet
world implements them on the world's side; a real UR5e and base would implement them over their
drivers. Nothing here imports a simulator.
"""
