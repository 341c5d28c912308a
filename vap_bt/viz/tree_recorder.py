"""TreeRecorder: the executive's ``on_tree`` callback that turns an episode into a rerun recording.

The executive knows nothing of rerun. After every tick it hands its ``BehaviourTree`` to
``on_tree(tree, tick)``; that is enough, because every behaviour of a compiled tree holds the
episode's :class:`~vap_bt.bt.context.ExecutionContext`, and the context holds the record: the
actions, the verifications with their rounds, the pending situation, and the scene graph with its
history of changes. The recorder reads all of it *incrementally* — it keeps how many actions,
verifications and belief changes it has logged, and which rounds and goals it has seen — so each
tick costs only what is new, and logs only what changed:

* the tree (``tree``): the drawing of :mod:`~vap_bt.viz.tree_graph` (nodes, positions, status
  colours, edges) whenever it differs from the last one logged, and with it (``tree_text``)
  the whole tree in words with status marks (:mod:`~vap_bt.viz.tree_text`) — unchanged ticks log
  nothing, which keeps a tick cheap (the check is one pass over the nodes' statuses);
* the events (``events/*``), in the order the tree ran them: plan and replan, action start and
  result, each round of looking with its questions and answers, each settled verification, each
  situation, each change of belief;
* the image of each round (``world/camera/*``) when the observation has pixels, logged the tick
  it arrives and paired exactly with its round because a ``VerifyPredicate`` keeps the
  observation it voted on until it runs again;
* the page of the check (``verification/round``) in step with the tree: at every tick the page
  names the check the tree highlights (the running ``ActivePerception``) and says what it is
  doing — capturing, asking with the answers as they arrive, judging the view, choosing or moving
  to the next viewpoint — and is logged last in the tick, after the page of any round that ended
  and the verdict of any check that was decided in it (with the situation, when it is one);
* the belief (``scene/facts``, ``scene/graph``, ``world/objects`` boxes and, where the runner
  hands the recorder the scene-graph builder's fused clouds (:attr:`TreeRecorder.clouds`),
  ``world/clouds/<object>`` — beside the last frame's depth, lifted to points in the 3-D view)
  at the start of an episode and whenever it changed;
* plots (``stats/*``), each on its own axes: the VLM queries so far, every one the metered
  model answered (the count the command line prints), the queries of each action's checks as a
  bar chart, the replans, and the situations by kind — each logged when it grows.

Timelines: ``tick`` (the executive's tick, counted on across the episodes of a session so time
never runs backwards), ``time`` (wall clock) and ``view`` (images logged so far: several rounds
can happen within one tick). Belief corrections the executive makes between a failing tick and
the first tick of the new tree are logged at that first tick, before its events.
"""

from __future__ import annotations

import time
from typing import Callable, Sequence

import numpy as np
import py_trees
import rerun as rr
from py_trees.common import Status

from vap_bt.bt.apply_effects import ApplyEffects
from vap_bt.bt.active_perception import ActivePerception
from vap_bt.bt.context import ExecutionContext, Situation
from vap_bt.bt.execute_skill import ExecuteSkill
from vap_bt.bt.recovery import RecoveryRoot
from vap_bt.bt.verify_predicate import VerifyPredicate
from vap_bt.viz import events as ev
from vap_bt.viz import layout as L
from vap_bt.viz.observation_view import camera_entities, has_pixels
from vap_bt.viz import scene_graph
from vap_bt.viz.scene_view import facts_document, object_boxes
from vap_bt.viz.sink import OpenRecording, SinkSpec, open_recording
from vap_bt.viz.tree_graph import TreeGraph, TreeView
from vap_bt.viz.tree_text import tree_document


#: points per object's fused cloud in a recording, at most (a cloud is thinned evenly to it)
CLOUD_POINTS = 600


class TreeRecorder:
    """Plug into ``Executive(..., on_tree=recorder.on_tree)``; call :meth:`close` at the end."""

    def __init__(self, recording: OpenRecording, images: bool = True) -> None:
        self.recording = recording
        self.stream: rr.RecordingStream = recording.stream
        self.images = images
        self.episodes = 0
        self.views = 0  # images logged (the ``view`` timeline)
        self._offset = 0  # ticks of the finished episodes of this session
        self._last_tick = 0
        self._ctx: ExecutionContext | None = None
        self._tree: py_trees.trees.BehaviourTree | None = None
        self._graph: TreeGraph | None = None
        self._signature: tuple | None = None
        self._view: TreeView | None = None
        self.queries = 0  # VLM queries so far (``stats/vlm_queries``), the session's finished episodes too
        self._queries_before = 0  # those of the finished episodes
        self._situations: dict[str, int] = {}  # situations by kind, so far (``stats/situations/<kind>``)
        #: each graph view's visible area so far (``tree``, ``scene``): see :meth:`_fit_views`
        self._bounds: dict[str, tuple[float, float, float, float]] = {}
        #: where the fused point clouds come from (name -> (N, 3) map-frame points), if anywhere:
        #: the runner points it at the executive's scene-graph builder
        self.clouds: Callable[[], dict[str, np.ndarray]] | None = None
        self._cloud_signatures: dict[str, tuple] = {}
        self._reset_indices()

    @classmethod
    def open(cls, sink: SinkSpec | str | Sequence[str], name: str | None = None, images: bool = True) -> "TreeRecorder":
        """Open a recording on ``sink`` (``SinkSpec``, ``"save run.rrd"``, ``["spawn"]`` …).

        Raises :class:`~vap_bt.viz.sink.ViewerError` (spawn/serve could not start) or
        :class:`~vap_bt.errors.InputError` (bad words or path) — both one-line CLI errors."""
        spec = sink if isinstance(sink, SinkSpec) else SinkSpec.parse(sink)
        return cls(open_recording(spec, recording_name=name, blueprint=L.blueprint()), images=images)

    @property
    def hint(self) -> str:
        """One line for the user: where the recording goes and how to look at it."""
        return self.recording.hint

    # ---- the executive's callback -------------------------------------------------------------

    def on_tree(self, tree: py_trees.trees.BehaviourTree, tick: int) -> None:
        """The executive's per-tick callback: log what changed in ``tree`` and its context since the last
        tick (see the module docstring), at tick ``tick``. A recovery tree's root logs its steps."""
        ctx = context_of(tree.root)
        if ctx is not None and ctx is not self._ctx:
            self._begin_episode(ctx)
        self._last_tick = tick
        self.stream.set_time(L.TICK, sequence=self._offset + tick)
        self.stream.set_time(L.TIME, timestamp=time.time())
        if isinstance(tree.root, RecoveryRoot):
            if self._ctx is not None:
                self._log_recovery(tree)
            return
        if ctx is None:
            return
        new_tree = tree is not self._tree
        if new_tree:
            self._new_tree(tree)
        # corrections made between ticks (undo, correct, relocate, survey) came before this tick
        pending_changes = ctx.graph.history[self._n_changes:]
        self._n_changes = len(ctx.graph.history)
        for c in [c for c in pending_changes if c.cause != "apply"]:
            self._text(L.EV_BELIEF, ev.change_text(c))
        applied = [c for c in pending_changes if c.cause == "apply"]
        board = ctx.board
        actions = board.actions[self._n_actions:]
        self._n_actions = len(board.actions)
        n_before = self._n_verifications
        verifications = board.verifications[n_before:]
        self._n_verifications = len(board.verifications)
        self._walk(tree.root, actions, verifications, applied)
        for entry in actions:  # anything the walk could not place (not expected)
            self._text(L.EV_ACTIONS, *ev.action_result_text(entry))
        for v in verifications:
            self._text(L.EV_VERIFICATIONS, *ev.verification_text(v))
        self._log_queries(ctx)
        for c in applied:
            self._text(L.EV_BELIEF, ev.change_text(c))
        if board.situation is not None and board.situation is not self._situation:
            self._situation = board.situation
            self._text(L.EV_SITUATIONS, ev.situation_text(board.situation), ev.WARN)
            kind = board.situation.kind
            self._situations[kind] = self._situations.get(kind, 0) + 1
            self.stream.log(f"{L.STATS_SITUATIONS}/{kind}", rr.Scalars(self._situations[kind]))
        if pending_changes:
            self._log_belief(ctx, pending_changes[-1])
        self._log_running_check()
        self._log_tree(new_tree)

    # ---- free-form notes and the end ----------------------------------------------------------

    def note(self, text: str, level: str = ev.INFO) -> None:
        """Log a line of the run's own progress (e.g. tee the executive's ``progress`` here)."""
        self._text(L.EV_PLAN, text, level)

    def scored(self, situations: Sequence[Situation], truths: Sequence[str]) -> None:
        """After the episode: each situation once more, its diagnosis with the truth the world's
        record gives beside it (``truths``, in the same order), then how many were right."""
        for s, truth in zip(situations, truths):
            self._text(L.EV_SITUATIONS, ev.situation_text(s, truth), ev.INFO if truth == s.diagnosis else ev.WARN)
        right = sum(truth == s.diagnosis for s, truth in zip(situations, truths))
        self._text(L.EV_SITUATIONS, f"diagnosis: {right} of {len(truths)} situations as the world's record says")

    def close(self) -> None:
        """Flush and close the sink (a saved file gets its footer; a served stream ends)."""
        if self._ctx is not None:  # queries asked after the last tick (a last look at the goal)
            self._log_queries(self._ctx)
        self.recording.close()

    def serve_until_interrupted(self, say=print) -> None:
        """In ``serve`` mode, keep serving after the run until Ctrl-C, so that a viewer that
        connects late still receives the whole recording; returns at once in other modes."""
        if self.recording.spec.mode != "serve":
            return
        say(f"{self.hint} — Ctrl-C to stop serving")
        try:
            while True:
                time.sleep(3600)
        except KeyboardInterrupt:
            pass

    def __enter__(self) -> "TreeRecorder":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    # ---- internals ----------------------------------------------------------------------------

    def _reset_indices(self) -> None:
        self._n_actions = self._n_verifications = self._n_changes = 0
        self._replans = -1
        self._situation: Situation | None = None
        self._seen: set[int] = set()
        self._view_of: dict[int, int] = {}  # id of a frame -> its number on the ``view`` timeline
        self._running_check: ActivePerception | None = None
        self._page_signature: tuple | None = None
        #: VLM queries of each action's checks, by (plan, step) in the order they ran
        self._per_action: dict[tuple[int, int], int] = {}
        self._keep: list[object] = []  # strong references, so that ids in _seen are never reused

    def _begin_episode(self, ctx: ExecutionContext) -> None:
        if self._ctx is not None:
            self._log_queries(self._ctx)
            self._queries_before = self.queries
            self._offset += self._last_tick
        self._ctx, self._tree, self._graph, self._signature, self._view = ctx, None, None, None, None
        self._reset_indices()
        self.episodes += 1
        self.stream.set_time(L.TICK, sequence=self._offset)
        self.stream.set_time(L.TIME, timestamp=time.time())
        self._text(L.EV_PLAN, f"episode {self.episodes}: {len(ctx.graph.facts)} facts believed, "
                              f"verification {ctx.strategy.name}, K={ctx.budget}")
        self._log_belief(ctx, None, where="initial survey")

    def _new_tree(self, tree: py_trees.trees.BehaviourTree) -> None:
        self._tree, self._graph = tree, TreeGraph.of(tree.root)
        self._replans += 1
        plan = [str(b.action) for b in self._graph.actions]
        self._text(L.EV_PLAN, ev.plan_text(plan, self._replans), ev.WARN if self._replans else ev.INFO)
        self.stream.log(L.STATS_REPLANS, rr.Scalars(self._replans))
        self._fit_views(tree=self._graph.extent())

    def _fit_views(self, **extents: tuple[float, float, float, float]) -> None:
        """Send the layout again with a graph view's visible area (``tree``, ``scene``) grown to
        hold the given extent — only when one grows, so the zoom of a session changes seldom
        (sending a layout resets the viewer's)."""
        grown = False
        for view, extent in extents.items():
            old = self._bounds.get(view)
            new = extent if old is None else (min(old[0], extent[0]), min(old[1], extent[1]),
                                              max(old[2], extent[2]), max(old[3], extent[3]))
            grown |= new != old
            self._bounds[view] = new
        if grown:
            self.stream.send_blueprint(L.blueprint(self._bounds.get("tree"), self._bounds.get("scene")),
                                       make_active=True, make_default=True)

    def _log_recovery(self, tree: py_trees.trees.BehaviourTree) -> None:
        """A recovery's tree (:mod:`vap_bt.bt.recovery`) drawn in the tree's panel while it runs,
        and a line for it and for each step as it ends. Belief is not read here: a step's routine
        may be changing it on another thread; its changes are logged at the next plan's first tick."""
        new_tree = tree is not self._tree
        if new_tree:
            self._tree, self._graph = tree, TreeGraph.of(tree.root)
            self._steps_done = 0
            self._text(L.EV_PLAN, f"recovering: {tree.root.reason}", ev.WARN)
            self._fit_views(tree=self._graph.extent())
        steps = tree.root.children
        done = sum(1 for c in steps if c.status == Status.SUCCESS)
        for c in steps[self._steps_done:done]:
            self._text(L.EV_PLAN, f"    {c.name}: done")
        self._steps_done = max(self._steps_done, done)
        self._log_tree(new_tree)

    def _log_tree(self, new_tree: bool) -> None:
        """The drawing, and with it the text, only when the drawing changed since the last tick:
        a skill's progress changes a feedback message on most ticks, and the text — the whole
        tree, a few kilobytes — logged on each of those was a third of a recording's bytes."""
        signature = self._graph.signature()
        if not new_tree and signature == self._signature:
            return
        self._signature = signature
        view = self._graph.view()
        if view != self._view:
            self.stream.log(L.TREE, view.nodes(), view.links())
            self.stream.log(L.TREE_TEXT, tree_document(self._graph.root))
            self._view = view
            if new_tree:  # a new tree's first drawing goes out now, not with the next batch: a
                self.stream.flush(timeout_sec=5.0)  # viewer reading the file draws it before the rest

    def _walk(self, node, actions: list[dict], verifications: list, applied: list) -> None:
        """Log what ``node`` and its subtree did this tick, in the order the tree ran it."""
        if isinstance(node, ExecuteSkill) and node.handle is not None and self._first(node.handle):
            self._text(L.EV_ACTIONS, ev.action_start_text(node.step, str(node.action)))
        if isinstance(node, VerifyPredicate):
            if node.observation is not None and self._first(node.observation):
                self._log_frame(node.observation)
            if node.round is not None and self._first(node.round):
                self._log_round(node)
        if isinstance(node, ActivePerception) and node.status == Status.RUNNING:
            self._running_check = node  # the deepest one the walk meets is the one the tree highlights
        for child in node.children:
            self._walk(child, actions, verifications, applied)
        if isinstance(node, ExecuteSkill):
            entry = _pop(actions, lambda e: e["step"] == node.step and e["action"] == str(node.action))
            if entry is not None:
                self._text(L.EV_ACTIONS, *ev.action_result_text(entry))
        if isinstance(node, ApplyEffects) and node.status == Status.SUCCESS and self._first(node):
            c = _pop(applied, lambda c: c.added <= node.action.may_add and c.removed <= node.action.may_delete)
            if c is not None:
                self._text(L.EV_BELIEF, ev.change_text(c))
        if isinstance(node, ActivePerception):
            action = str(node.action) if node.action else "goal"
            v = _pop(verifications, lambda v: v.atom == node.verify.atom and v.phase == node.phase
                     and v.action == action)
            if v is not None:
                self._text(L.EV_VERIFICATIONS, *ev.verification_text(v))
                situation = node.ctx.board.situation if v.outcome == "contradicted" else None
                self._page(ev.verdict_markdown(v, situation))
                key = (self._replans, node.step)
                self._per_action[key] = self._per_action.get(key, 0) + v.queries
                self.stream.log(L.STATS_PER_ACTION, rr.BarChart(list(self._per_action.values())))

    def _log_frame(self, obs) -> None:
        """The image of a round, logged the tick it arrives (paired with its round by identity)."""
        if not (self.images and has_pixels(obs)):
            return
        self.views += 1
        self._view_of[id(obs)] = self.views
        self.stream.set_time(L.VIEW, sequence=self.views)
        for path, archetype in camera_entities(obs):
            self.stream.log(path, archetype)

    def _log_round(self, node: VerifyPredicate) -> None:
        parent = node.parent if isinstance(node.parent, ActivePerception) else None
        phase = parent.phase if parent else "check"
        action = (str(parent.action) if parent.action else "goal") if parent else "?"
        view_no = self._view_of.get(id(node.observation))
        self._text(L.EV_ROUNDS, ev.round_text(phase, action, node.atom, node.expected, node.round, view_no))
        self._page(ev.round_markdown(phase, action, node.atom, node.expected, node.round))

    def _log_running_check(self) -> None:
        """The page of the check the tree highlights, whenever what it shows changed: its view,
        what it is doing, and the questions of the round in flight with the answers so far —
        logged last in the tick, so at every tick the page names the atom the tree highlights."""
        check, self._running_check = self._running_check, None
        if check is None:
            return
        p = check.verify.progress() if check.stage == "look" else None
        stage = p.stage if p is not None else check.stage
        signature = (id(check), len(check.rounds), stage, tuple(sorted(p.answers.items())) if p else ())
        if signature == self._page_signature:
            return
        action = str(check.action) if check.action else "goal"
        self._page(ev.check_markdown(check.phase, action, check.atom, check.verify.expected, len(check.rounds),
                                     check.ctx.budget, stage, p.questions if p and stage != "done" else (),
                                     p.answers if p else None, check.rounds[-1] if check.rounds else None))
        self._page_signature = signature

    def _page(self, markdown: str) -> None:
        self.stream.log(L.ROUND_PAGE, rr.TextDocument(markdown, media_type=rr.MediaType.MARKDOWN))
        self._page_signature = None

    def _log_belief(self, ctx: ExecutionContext, change, where: str = "") -> None:
        self.stream.log(L.SCENE_FACTS, facts_document(ctx.graph, change, where))
        drawing = scene_graph.draw(ctx.graph)
        self.stream.log(L.SCENE_GRAPH, drawing.nodes(), drawing.links())
        self._fit_views(scene=drawing.bounds())
        boxes = object_boxes(ctx.graph)  # belief's boxes, beside the last frame's points in 3-D
        if boxes is not None:
            self.stream.log(L.OBJECT_BOXES, boxes)
        self._log_clouds()

    def _log_clouds(self) -> None:
        """Each object's fused cloud whose points changed since it was last logged (at most
        :data:`CLOUD_POINTS` of them: enough to see a shape, little beside the images); a cloud
        the builder dropped is cleared."""
        clouds = self.clouds() if self.clouds is not None else {}
        for name in set(self._cloud_signatures) - set(clouds):
            self.stream.log(f"{L.CLOUDS}/{name}", rr.Clear(recursive=False))
            del self._cloud_signatures[name]
        for name, points in clouds.items():
            signature = (len(points), points[:1].tobytes(), points[-1:].tobytes())  # before any copy
            if self._cloud_signatures.get(name) == signature:
                continue
            self._cloud_signatures[name] = signature
            step = max(1, -(-len(points) // CLOUD_POINTS))
            self.stream.log(f"{L.CLOUDS}/{name}", rr.Points3D(np.asarray(points[::step], dtype=np.float32), radii=0.004))

    def _log_queries(self, ctx: ExecutionContext) -> None:
        """The VLM queries so far, when they grew: the metered model's count — every query of the
        episode, surveys and viewpoint questions too, the count the command line prints — or,
        for a model nobody meters, the queries of the settled checks."""
        total = getattr(ctx.vlm, "total", None)
        if total is None:
            total = sum(v.queries for v in ctx.board.verifications)
        if self._queries_before + total != self.queries:
            self.queries = self._queries_before + total
            self.stream.log(L.STATS_QUERIES, rr.Scalars(self.queries))

    def _text(self, path: str, text: str, level: str = ev.INFO) -> None:
        self.stream.log(path, rr.TextLog(text, level=level))

    def _first(self, obj: object) -> bool:
        """True the first time ``obj`` (a round, a goal handle, a node) is seen this episode."""
        if id(obj) in self._seen:
            return False
        self._seen.add(id(obj))
        self._keep.append(obj)
        return True


def context_of(root: py_trees.behaviour.Behaviour) -> ExecutionContext | None:
    """The episode's context, held by every behaviour of a compiled tree."""
    for node in root.iterate():
        ctx = getattr(node, "ctx", None)
        if isinstance(ctx, ExecutionContext):
            return ctx
    return None


def _pop(items: list, match):
    for i, x in enumerate(items):
        if match(x):
            return items.pop(i)
    return None
