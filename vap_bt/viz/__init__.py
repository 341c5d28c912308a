"""The live rerun view of an episode: the only room that imports rerun.

``TreeRecorder.open("save run.rrd")`` (or ``"spawn"``, ``"serve [PORT]"``) opens a recording;
pass ``recorder.on_tree`` as the executive's ``on_tree`` callback and ``close()`` it at the end.
The modules, one idea each:

* :mod:`~vap_bt.viz.sink` — where the recording goes (viewer, loopback gRPC server, file);
* :mod:`~vap_bt.viz.tree_recorder` — the callback that reads the executive's record each tick;
* :mod:`~vap_bt.viz.tree_graph` — a behaviour tree as a graph with status colours;
* :mod:`~vap_bt.viz.events` — the episode as lines of text;
* :mod:`~vap_bt.viz.observation_view` — a camera observation as images, pinhole and pose;
* :mod:`~vap_bt.viz.scene_view` — the scene graph as facts, graph and boxes;
* :mod:`~vap_bt.viz.layout` — the viewer's default layout and the entity paths.

See ``docs/viz.md``.
"""

from vap_bt.viz.sink import SinkSpec, ViewerError
from vap_bt.viz.tree_recorder import TreeRecorder

__all__ = ["SinkSpec", "TreeRecorder", "ViewerError"]
