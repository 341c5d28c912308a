"""The VLM-planner baseline (``--verify vlm_planner``): the model names each next action, no planner, no checks.

The model side is a real HTTP server on 127.0.0.1 speaking OpenAI's chat completions (the server
of ``test_vlm_backends``), its replies scripted here: it is the protocol's test double, not the
simulated VLM (which cannot plan, and is refused). The next-action prompts get the scripted
replies in turn; every other question (the survey asks which doors are open) gets "yes". The
runs go through ``vap-bt run`` in the symbolic world, and the world judges the goal.
"""

from __future__ import annotations

import json
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest
from py_trees.common import Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.propose_action import ProposeNextAction
from vap_bt.domain.atoms import Atom
from vap_bt.errors import EXIT_BAD_INPUT, EXIT_GOAL_NOT_REACHED, EXIT_OK
from vap_bt.perception.action_proposal import ActionSyntaxError, action_errors, action_list, read_action
from vap_bt.perception.prompts import book
from vap_bt.robot.frame import Frame
from vap_bt.scene.graph import SceneGraph
from vap_bt.taskfile import load

from conftest import TREES
from test_vlm_backends import FAST, HANG, chat, decoded, gemini_at, generate, openai, serve  # noqa: F401 (serve: a fixture)

CUP = TREES / "collect_cup.yaml"
CUP_TASK = load(CUP).planning
#: what the planner finds for collect_cup after the survey (tests/test_goal_parsing's run says the same)
SOLUTION = ["(find floor_living_room cup living_room)", "(grasp cup coffee_table living_room)",
            "(navigate living_room kitchen door_lk cup)", "(find door_lk counter kitchen)",
            "(placeon cup counter kitchen)", "done"]
#: the next-action prompt's fixed opening, before its first placeholder
PLANNING_HEAD = book().vlm_planner.split("{", 1)[0]


def text_of(body: dict) -> str:
    """The prompt of a chat-completions request (a string, or the text part after the image)."""
    content = body["messages"][0]["content"]
    return content if isinstance(content, str) else "".join(p.get("text", "") for p in content)


def images_of(body: dict) -> list[str]:
    content = body["messages"][0]["content"]
    return [] if isinstance(content, str) else [p["image_url"]["url"] for p in content if p["type"] == "image_url"]


class PlannerServer:
    """The scripted model: ``replies`` to the next-action prompts, in turn; "yes" to every other question."""

    def __init__(self, serve, replies: list[str]) -> None:
        self.replies, self.prompts, self._lock = list(replies), [], threading.Lock()
        self.server = serve(script=self._reply)

    def _reply(self, i, seen):
        text = text_of(seen.body)
        if not text.startswith(PLANNING_HEAD):
            return chat("yes")
        with self._lock:
            self.prompts.append(seen.body)
            return chat(self.replies[min(len(self.prompts), len(self.replies)) - 1])

    @property
    def url(self) -> str:
        return f"{self.server.url}/v1"


def run(cli, tmp_path, server: PlannerServer, *extra):
    report = tmp_path / "report.json"
    code, out, err = cli("run", CUP, "--world", "symbolic", "--vlm", "openai", "--vlm-url", server.url,
                         "--vlm-model", "m", "--verify", "vlm_planner", "--no-injection", "--transport", "inproc",
                         "--report", report, "-q", *extra)
    return code, json.loads(report.read_text()), out + err  # the summary table, and what went wrong


# --- an episode ---------------------------------------------------------------------------------

def test_the_vlm_names_each_action_the_skills_execute_it_and_the_world_confirms_the_goal(cli, serve, tmp_path):
    server = PlannerServer(serve, SOLUTION)
    code, rep, err = run(cli, tmp_path, server)
    assert code == EXIT_OK, err
    assert rep["strategy"]["name"] == "vlm_planner" and rep["success"] and rep["goal_satisfied"]
    assert rep["reason"] == "the VLM said done" and rep["plans"] == [] and rep["verifications"] == []
    assert "5 executed; named one at a time by the VLM (6 steps)" in err
    assert [a["action"] for a in rep["actions_executed"]] == [
        str(CUP_TASK.knowledge.ground(a.predicate, a.args)) for a in map(Atom.parse, SOLUTION[:-1])]
    steps = rep["vlm_planner"]["steps"]
    assert [s["done"] for s in steps] == [False] * 5 + [True] and all(not s["reasked"] for s in steps)
    assert [s["result"] for s in steps[:-1]] == ["succeeded"] * 5
    assert rep["vlm"]["by_purpose"]["plan"] == 6 == len(server.prompts)
    first, last = (text_of(b) for b in (server.prompts[0], server.prompts[-1]))
    # the domain knowledge: every action with its parameters, precondition and effects
    assert action_list(CUP_TASK) in first and "grasp(?o - item, ?s - surface, ?r - room)" in first
    assert "precondition: holding(o) and inview(s)" in first
    # the scene as believed after the survey, and the goal (the task's words and its atoms)
    assert "on(cup, coffee_table)" in first and "robot_in(living_room)" in first
    assert "Goal: on(cup, counter)" in first and "Instruction: Take the cup from the living-room table" in first
    assert "Actions done so far:\n(none yet)" in first
    # belief follows the actions done (ApplyEffects), and the history says what their skills reported
    assert "on(cup, counter)" in last and "on(cup, coffee_table)" not in last
    assert "5. (placeon cup counter kitchen): succeeded" in last
    # each step's frame goes with its prompt, image first
    for body in server.prompts:
        assert len(images_of(body)) == 1 and images_of(body)[0].startswith("data:image/png;base64,")
        assert body["messages"][0]["content"][0]["type"] == "image_url"
        assert "structured_outputs" not in body and "logprobs" not in body


def test_a_failed_skill_is_said_in_the_history_and_belief_keeps_what_it_held(cli, serve, tmp_path):
    """Grasping from the wrong spot fails in the world (the cup is not in view); nothing replans:
    the model is told, and belief does not take on the grasp's effects."""
    server = PlannerServer(serve, ["(grasp cup coffee_table living_room)", *SOLUTION])
    code, rep, err = run(cli, tmp_path, server)
    assert code == EXIT_OK, err
    steps = rep["vlm_planner"]["steps"]
    assert steps[0]["result"].startswith("failed") and steps[1]["result"] == "succeeded"
    second = text_of(server.prompts[1])
    assert "1. (grasp cup coffee_table living_room): failed" in second and "holding(cup)" not in second
    assert rep["situations"] == [] and rep["replans"] == 0


# --- what the model says, read strictly ---------------------------------------------------------

def test_a_malformed_reply_is_asked_again_once_with_the_error_and_the_correction_taken(cli, serve, tmp_path):
    server = PlannerServer(serve, ["(fly cup living_room)", *SOLUTION])
    code, rep, err = run(cli, tmp_path, server)
    assert code == EXIT_OK, err
    step = rep["vlm_planner"]["steps"][0]
    assert step["reasked"] and step["action"] == "find(floor_living_room, cup, living_room)"
    again = text_of(server.prompts[1])
    assert again.startswith(text_of(server.prompts[0]))  # the prompt as it was, then the error
    assert "Your previous answer was: (fly cup living_room)" in again
    assert "It is not a valid action: unknown action 'fly'" in again
    assert step["attempts"][0]["frame_id"] == step["attempts"][1]["frame_id"]  # the same picture


def test_two_malformed_replies_end_the_episode_with_a_clear_reason(cli, serve, tmp_path):
    server = PlannerServer(serve, ["I would pick up the cup first.", "(grasp cup sofa living_room)"])
    code, rep, err = run(cli, tmp_path, server)
    assert code == EXIT_GOAL_NOT_REACHED and "Traceback" not in err
    assert not rep["success"] and not rep["goal_satisfied"] and rep["actions_executed"] == []
    assert rep["reason"] == ("no usable action from the VLM at step 0 (asked again): unknown object 'sofa' in "
                             "(grasp cup sofa living_room) (not among the available objects)")
    assert [a["error"] is not None for a in rep["vlm_planner"]["steps"][0]["attempts"]] == [True, True]
    assert len(server.prompts) == 2


def test_done_before_the_goal_holds_is_a_claimed_success_the_world_denies(cli, serve, tmp_path):
    server = PlannerServer(serve, ["(find floor_living_room cup living_room)", "done"])
    code, rep, err = run(cli, tmp_path, server)
    assert rep["success"] and rep["goal_satisfied"] is False and code == EXIT_GOAL_NOT_REACHED
    assert rep["strategy"]["name"] == "vlm_planner" and len(rep["actions_executed"]) == 1


def test_the_step_budget_ends_an_episode_the_model_never_calls_done(cli, serve, tmp_path):
    server = PlannerServer(serve, ["(find floor_living_room cup living_room)"])
    code, rep, err = run(cli, tmp_path, server, "--max-steps", "3")
    assert code == EXIT_GOAL_NOT_REACHED and not rep["success"]
    assert rep["reason"] == "step budget (3) exhausted before the VLM said done" and len(server.prompts) == 3


@pytest.mark.parametrize("reply, atom", [
    ("(grasp cup coffee_table living_room)", Atom("grasp", ("cup", "coffee_table", "living_room"))),
    ("```\n(grasp cup coffee_table living_room)\n```", Atom("grasp", ("cup", "coffee_table", "living_room"))),
    ("Next action: `(open door_lk)`.", Atom("open", ("door_lk",))),
    ("Done.", None), ("done", None)])
def test_a_reply_is_one_action_in_pddl_form_or_done(reply, atom):
    assert read_action(reply) == atom


@pytest.mark.parametrize("reply", ["", "grasp(cup, coffee_table, living_room)", "I think (grasp cup)",
                                   "(grasp cup coffee_table living_room)\n(placeon cup counter kitchen)",
                                   "done, then (open door_lk)"])
def test_anything_else_is_not_an_action(reply):
    with pytest.raises(ActionSyntaxError):
        read_action(reply)


@pytest.mark.parametrize("action, needle", [
    ("(fly cup)", "unknown action 'fly'"), ("(grasp cup coffee_table)", "takes 3 arguments, got 2"),
    ("(grasp cup sofa living_room)", "unknown object 'sofa'"), ("(grasp cup kitchen living_room)", "is a room")])
def test_validation_names_actions_arities_objects_and_types(action, needle):
    assert needle in action_errors(Atom.parse(action), CUP_TASK, sorted(CUP_TASK.objects))


# --- the request: free text about a frame ------------------------------------------------------

def test_both_protocols_send_the_frame_with_a_free_text_request_and_no_constraint(serve):
    rgb = np.arange(8 * 8 * 3, dtype=np.uint8).reshape(8, 8, 3)
    frame = Frame("f-1", 0.0, rgb=rgb)
    server = serve(chat("(open door_lk)"))
    vlm = openai(server, FAST)
    reply = vlm.complete("which next?", "plan", frame)
    body = server.seen[0].body
    assert reply.text == "(open door_lk)" and text_of(body) == "which next?"
    assert (decoded(images_of(body)[0].split(",", 1)[1]) == rgb).all()
    assert body["max_tokens"] == vlm.text_max_tokens and not {"structured_outputs", "guided_choice", "grammar",
                                                              "logprobs"} & set(body)
    record = vlm.requests[0]
    assert record.purpose == "plan" and record.frame_id == "f-1" and record.frame_sha1 is not None
    vlm.complete("which next?", "plan", Frame("f-2", 0.0))  # no pixels: the prompt goes alone
    assert server.seen[1].body["messages"][0]["content"] == "which next?"

    gserver = serve(generate("done"))
    gvlm = gemini_at(gserver, FAST)
    assert gvlm.complete("which next?", "plan", frame).text == "done"
    gbody = gserver.seen[0].body
    parts, config = gbody["contents"][0]["parts"], gbody["generationConfig"]
    assert "inline_data" in parts[0] and parts[-1] == {"text": "which next?"}
    assert config["maxOutputTokens"] == gvlm.text_max_tokens and "responseSchema" not in config
    assert "responseLogprobs" not in config


class StillCamera:
    """A camera that gives one picture, wherever it is aimed."""

    def capture(self, aim=None) -> Frame:
        return Frame("still", 0.0, rgb=np.zeros((8, 8, 3), np.uint8))


def test_the_models_call_is_work_in_flight_polled_and_dropped_on_a_halt(serve):
    """update() never waits for the model: RUNNING while it thinks; a halt leaves nothing to wait for."""
    server = serve(HANG)
    ctx = ExecutionContext(graph=SceneGraph.of_facts(CUP_TASK.init), vlm=None, camera=StillCamera(), skills=None,
                           executor=ThreadPoolExecutor(2))
    node = ProposeNextAction(ctx, openai(server, FAST), CUP_TASK, "take the cup", 0, [])
    try:
        started = time.monotonic()
        for _ in range(3):
            node.tick_once()
            assert node.status == Status.RUNNING
        assert time.monotonic() - started < 0.3
        node.stop(Status.INVALID)
        assert node.status == Status.INVALID and not node.proposal.attempts
    finally:
        server.release.set()
        ctx.executor.shutdown(wait=True)
    assert len(server.seen) >= 1 and text_of(server.seen[0].body).startswith(PLANNING_HEAD)


# --- offline: refused, never faked --------------------------------------------------------------

@pytest.mark.parametrize("vlm", ["sim", "sim-http"])
def test_the_simulated_vlm_cannot_plan_and_is_refused_in_one_line(cli, vlm):
    code, out, err = cli("run", CUP, "--world", "symbolic", "--vlm", vlm, "--verify", "vlm_planner")
    assert code == EXIT_BAD_INPUT and not out
    assert err.strip() == ("vap-bt: --verify: vlm_planner needs a real VLM backend (openai, gemini): "
                           "the simulated VLM cannot plan")


def test_vlm_planner_has_no_tree_to_show(cli):
    code, _, err = cli("tree", CUP, "--verify", "vlm_planner")
    assert code == EXIT_BAD_INPUT and err.strip().startswith("vap-bt: --verify: vlm_planner compiles no tree")
