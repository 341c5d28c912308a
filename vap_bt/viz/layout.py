"""The viewer's default layout (a rerun blueprint) and the entity paths it arranges.

One screen answers "what is the robot doing and why", without a click:

* left, most of the screen: the behaviour tree as drawn by :mod:`~vap_bt.viz.tree_graph` (the
  plan as a column, the open action spread out, status colours), and under it the event log —
  situations and replans are warnings — with the whole tree in words (py_trees' unicode display
  with status marks, per tick) in a tab behind it, where it has the column's width;
* middle: the page of the check the tree highlights (its questions, the answers as they arrive,
  vote, view sufficiency, verdict), and under it the belief as a scene graph laid out by
  :mod:`~vap_bt.viz.scene_graph` (the facts as a list in a tab behind it);
* right: what the camera saw for the current check and the 3-D scene (point cloud, boxes,
  robot and camera pose), and four plots, each on its own axes: VLM queries so far (the
  count the command line prints at the end), VLM queries per action, replans, and situations
  by kind.

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
CLOUDS = f"{WORLD}/clouds"
CAMERA = f"{WORLD}/camera"
STATS = "stats"
STATS_QUERIES = f"{STATS}/vlm_queries"
STATS_PER_ACTION = f"{STATS}/queries_per_action"
STATS_REPLANS = f"{STATS}/replans"
STATS_SITUATIONS = f"{STATS}/situations"
#: the timelines: the executive's tick (counted on across episodes), the wall clock, and the
#: number of camera images logged so far (several rounds can share one tick)
TICK, TIME, VIEW = "tick", "time", "view"


def _area(bounds: tuple[float, float, float, float] | None) -> rrb.VisualBounds2D | None:
    return None if bounds is None else rrb.VisualBounds2D(x_range=[bounds[0], bounds[2]], y_range=[bounds[1], bounds[3]])


def blueprint(tree_bounds: tuple[float, float, float, float] | None = None,
              scene_bounds: tuple[float, float, float, float] | None = None) -> rrb.Blueprint:
    """The layout; ``tree_bounds`` and ``scene_bounds`` (x0, y0, x1, y1) fix the two graph views'
    visible areas — without them, a graph view fits the first drawing it sees and keeps that
    zoom, cutting off a later, wider one."""
    return rrb.Blueprint(
        rrb.Horizontal(
            rrb.Vertical(
                rrb.GraphView(origin=TREE, name="behaviour tree", visual_bounds=_area(tree_bounds)),
                rrb.Tabs(
                    rrb.TextLogView(origin=EVENTS, name="events"),
                    # wrapped: a running skill's line (name, mark, progress) reaches 120 characters,
                    # wider than the column in a 1920-px window; a wrapped line loses nothing
                    rrb.TextDocumentView(origin=TREE_TEXT, name="tree (py_trees)", format_options=rrb.archetypes
                                         .TextDocumentFormat(monospace=True, word_wrap=True)),
                ),
                row_shares=[4, 1],
            ),
            rrb.Vertical(
                rrb.TextDocumentView(origin=ROUND_PAGE, name="verification"),
                rrb.Tabs(
                    rrb.GraphView(origin=SCENE_GRAPH, name="scene graph (belief)", visual_bounds=_area(scene_bounds)),
                    rrb.TextDocumentView(origin=SCENE_FACTS, name="belief (facts)"),
                ),
                row_shares=[1, 1],
            ),
            rrb.Vertical(
                rrb.Horizontal(
                    rrb.Spatial2DView(origin=CAMERA, name="camera"),
                    rrb.Spatial3DView(origin=WORLD, name="scene"),
                ),
                rrb.Horizontal(
                    rrb.TimeSeriesView(origin=STATS_QUERIES, name="VLM queries"),
                    rrb.BarChartView(origin=STATS_PER_ACTION, name="VLM queries per action"),
                ),
                rrb.Horizontal(
                    rrb.TimeSeriesView(origin=STATS_REPLANS, name="replans"),
                    rrb.TimeSeriesView(origin=STATS_SITUATIONS, name="situations by kind"),
                ),
                row_shares=[3, 1, 1],
            ),
            column_shares=[9, 5, 6],
        ),
        rrb.BlueprintPanel(state="collapsed"),
        rrb.SelectionPanel(state="collapsed"),
        rrb.TimePanel(state="collapsed", timeline=TICK),
    )
