"""The scene graph: objects and the ground facts believed about them, and how they change."""
