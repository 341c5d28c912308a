"""The viewer's default layout (a rerun blueprint) and the entity paths it arranges.

One screen answers "what is the robot doing and why", without a click:

* left, most of the screen: the behaviour tree as drawn by :mod:`~vap_bt.viz.tree_graph` (the
  plan as a column, the open action spread out, status colours), and under it the event log —
  situations and replans are warnings;
* middle: the whole tree in words, py_trees' unicode display with status marks, per tick;
* right: what the camera saw for the current check and the 3-D scene (point cloud, boxes,
  robot and camera pose), the page of the current verification round (questions, answers,
  vote, view sufficiency; belief and scene graph in tabs behind it), and the VLM queries and
  replans so far as time series.

The time panel opens on the ``tick`` timeline, following the recording; the side panels are
collapsed so the views get the room. The recorder logs to the paths named here, so the layout
and the data cannot drift apart.
"""

from __future__ import annotations

import rerun.blueprint as rrb

TREE = "tree"
TREE_TEXT = "tree_text"
EVENTS = "events"
EV_PLAN = f"{EVENTS}/plan"
EV_ACTIONS = f"{EVENTS}/actions"
EV_ROUNDS = f"{EVENTS}/rounds"
EV_VERIFICATIONS = f"{EVENTS}/verifications"
EV_SITUATIONS = f"{EVENTS}/situations"
EV_BELIEF = f"{EVENTS}/belief"
ROUND_PAGE = "verification/round"
SCENE_FACTS = "scene/facts"
SCENE_GRAPH = "scene/graph"
WORLD = "world"
OBJECT_BOXES = f"{WORLD}/objects"
CAMERA = f"{WORLD}/camera"
STATS = "stats"
STATS_QUERIES = f"{STATS}/vlm_queries"
STATS_REPLANS = f"{STATS}/replans"
#: the timelines: the executive's tick (counted on across episodes), the wall clock, and the
#: number of camera images logged so far (several rounds can share one tick)
TICK, TIME, VIEW = "tick", "time", "view"


def blueprint(tree_bounds: tuple[float, float, float, float] | None = None) -> rrb.Blueprint:
    """The layout; ``tree_bounds`` (x0, y0, x1, y1) fixes the tree view's visible area — without
    it, the graph view fits the first drawing it sees and keeps that zoom, cutting off a later,
    wider one."""
    bounds = None if tree_bounds is None else rrb.VisualBounds2D(
        x_range=[tree_bounds[0], tree_bounds[2]], y_range=[tree_bounds[1], tree_bounds[3]])
    return rrb.Blueprint(
        rrb.Horizontal(
            rrb.Vertical(
                rrb.GraphView(origin=TREE, name="behaviour tree", visual_bounds=bounds),
                rrb.TextLogView(origin=EVENTS, name="events"),
                row_shares=[4, 1],
            ),
            rrb.TextDocumentView(origin=TREE_TEXT, name="tree (py_trees)",
                                 format_options=rrb.archetypes.TextDocumentFormat(monospace=True, word_wrap=False)),
            rrb.Vertical(
                rrb.Horizontal(
                    rrb.Spatial2DView(origin=CAMERA, name="camera"),
                    rrb.Spatial3DView(origin=WORLD, name="scene"),
                ),
                rrb.Tabs(
                    rrb.TextDocumentView(origin=ROUND_PAGE, name="verification"),
                    rrb.TextDocumentView(origin=SCENE_FACTS, name="belief"),
                    rrb.GraphView(origin=SCENE_GRAPH, name="scene graph"),
                ),
                rrb.TimeSeriesView(origin=STATS, name="VLM queries, replans"),
                row_shares=[3, 3, 2],
            ),
            column_shares=[9, 5, 6],
        ),
        rrb.BlueprintPanel(state="collapsed"),
        rrb.SelectionPanel(state="collapsed"),
        rrb.TimePanel(state="collapsed", timeline=TICK),
    )
