"""The viewer's default layout (a rerun blueprint) and the entity paths it arranges.

One screen answers "what is the robot doing and why": the behaviour tree with its status
colours and the event log on the left; on the right what the camera saw for the current check
(RGB, depth, segmentation, and the 3-D scene with the camera frustum), and below it the page of
the current verification round, the belief as a fact sheet and as a graph. The recorder logs to
the paths named here, so the layout and the data cannot drift apart.
"""

from __future__ import annotations

import rerun.blueprint as rrb

TREE = "tree"
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
#: the timelines: the executive's tick (counted on across episodes), the wall clock, and the
#: number of camera images logged so far (several rounds can share one tick)
TICK, TIME, VIEW = "tick", "time", "view"


def blueprint() -> rrb.Blueprint:
    return rrb.Blueprint(
        rrb.Horizontal(
            rrb.Vertical(
                rrb.GraphView(origin=TREE, name="behaviour tree"),
                rrb.TextLogView(origin=EVENTS, name="events"),
                row_shares=[3, 2],
            ),
            rrb.Vertical(
                rrb.Tabs(
                    rrb.Spatial2DView(origin=f"{WORLD}/camera", name="camera"),
                    rrb.Spatial3DView(origin=WORLD, name="world"),
                ),
                rrb.Tabs(
                    rrb.TextDocumentView(origin=ROUND_PAGE, name="verification round"),
                    rrb.TextDocumentView(origin=SCENE_FACTS, name="belief"),
                    rrb.GraphView(origin=SCENE_GRAPH, name="scene graph"),
                ),
            ),
            column_shares=[3, 2],
        ),
        collapse_panels=False,
    )
