"""Goals in words (paper Alg. 1 line 2): the appendix prompt, strict reading, validation, one re-ask.

The model side is a real HTTP server on 127.0.0.1 speaking each protocol (the servers of
``test_vlm_backends``): the tests read what it received — a text-only request carrying the
appendix prompt filled in verbatim — and what the parser made of its replies. The end-to-end
runs go through ``vap-bt run`` in the symbolic world.
"""

from __future__ import annotations

import json
import time
from types import SimpleNamespace

import pytest
import yaml

from vap_bt.domain.atoms import Atom, Literal
from vap_bt.errors import EXIT_BAD_INPUT, EXIT_TRANSPORT
from vap_bt.perception.backends import GeminiVLM, OpenAICompatVLM, RetryPolicy
from vap_bt.perception.goal_parsing import (
    GoalParseError, GoalParser, GoalSyntaxError, follow_up, goal_errors, goal_prompt, predicate_list, read_goal)
from vap_bt.perception.prompts import book
from vap_bt.taskfile import load

from conftest import HOUSEHOLD, TREES
from test_vlm_backends import FAST, HANG, chat, generate, serve  # noqa: F401 (serve is a fixture)

CUP_TASK = load(TREES / "collect_cup.yaml").planning
OBJECTS = sorted(CUP_TASK.objects)
WORDS = "bring the cup to the kitchen counter"
GOOD = "on(cup, counter)"


def openai_at(server, policy=FAST) -> OpenAICompatVLM:
    return OpenAICompatVLM(f"{server.url}/v1", "qwen2.5-vl", policy=policy)


def gemini_at(server, policy=FAST) -> GeminiVLM:
    return GeminiVLM(f"{server.url}/v1beta", "gemini-test", api_key="gm-key", policy=policy)


#: per protocol: (backend factory, a reply with this text, the prompt text a request carries)
PROTOCOLS = {
    "openai": (openai_at, chat, lambda body: body["messages"][0]["content"]),
    "gemini": (gemini_at, generate, lambda body: body["contents"][0]["parts"][-1]["text"]),
}


def parser(vlm) -> GoalParser:
    return GoalParser(vlm, CUP_TASK, WORDS, where="--goal")


# --- the prompt -------------------------------------------------------------------------------------

def test_prompt_is_the_appendix_text_filled_with_the_graphs_objects_and_the_domains_predicates():
    prompt = goal_prompt(WORDS, OBJECTS, CUP_TASK.knowledge)
    assert prompt == book().goal_parsing.format(instruction=WORDS, object_list=", ".join(OBJECTS),
                                                predicate_list=predicate_list(CUP_TASK.knowledge))
    assert f"Instruction: {WORDS}\n" in prompt
    assert "Available objects: coffee_table, counter, cup, door_lk, floor_kitchen," in prompt
    preds = predicate_list(CUP_TASK.knowledge)
    assert preds.startswith("robot_in(X), in_room(X,Y), connects(X,Y,Z), ")
    assert "on(X,Y), inside(X,Y), holding(X), hand_empty, open(X)" in preds  # the prompt's own notation
    assert preds.split(", ")[-1] == "heated(X)"
    wide = SimpleNamespace(predicates={"route": ("a", "b", "c", "d"), "lit": ()})
    assert predicate_list(wide) == "route(X1,X2,X3,X4), lit"


def test_follow_up_keeps_the_appendix_text_and_appends_the_reply_and_the_error():
    prompt = goal_prompt(WORDS, OBJECTS, CUP_TASK.knowledge)
    again = follow_up(prompt, "in(cup, counter)\n", "unknown predicate 'in'.")
    assert again.startswith(prompt + "\n\n")
    assert again[len(prompt):] == ("\n\nYour previous answer was: in(cup, counter)\n"
                                   "It is not a valid goal: unknown predicate 'in'.\n"
                                   "Answer again with the goal only, in the format above, "
                                   "using only the available objects and predicates.")


# --- reading and validating a reply ------------------------------------------------------------------

@pytest.mark.parametrize("reply,atoms", [
    ("on(cup, counter)", ["on(cup, counter)"]),
    ("  on(cup,counter), closed(door_lk)\n", ["on(cup, counter)", "closed(door_lk)"]),
    ("Goal: on(cup, counter).", ["on(cup, counter)"]),
    ("Output: inside(cup, cabinet)", ["inside(cup, cabinet)"]),
    ("```\non(cup, counter)\n```", ["on(cup, counter)"]),
    ("`on(cup, counter)`", ["on(cup, counter)"]),
    ("[on(cup, counter), hand_empty]", ["on(cup, counter)", "hand_empty"]),
    ("hand_empty(), on(cup, counter), on(cup, counter)", ["hand_empty", "on(cup, counter)"]),
])
def test_a_reply_in_the_format_is_read_after_taking_off_unambiguous_wrapping(reply, atoms):
    assert [str(a) for a in read_goal(reply)] == atoms


@pytest.mark.parametrize("reply", [
    "", "   ", "Goal:", "The cup should end up on the counter.", "on(cup, counter) and closed(door_lk)",
    "not on(cup, coffee_table)", "- on(cup, counter)\n- closed(door_lk)", "on(cup, counter);", "on(cup counter)",
    "on(cup, counter), ", "on(cup, counter)\nclosed(door_lk)", "on[cup, counter]",
])
def test_anything_else_is_not_a_goal(reply):
    with pytest.raises(GoalSyntaxError):
        read_goal(reply)


@pytest.mark.parametrize("atom,needle", [
    ("in(cup, counter)", "unknown predicate 'in'"),
    ("on(cup)", "on takes 2 argument(s), got 1"),
    ("on(mug, counter)", "unknown object 'mug'"),
    ("on(counter, cup)", "'counter' is a surface, on expects a item"),
    ("hand_empty(cup)", "hand_empty takes 0 argument(s)"),
])
def test_validation_names_predicates_arities_objects_and_types(atom, needle):
    (error,) = goal_errors([Atom.parse(atom)], OBJECTS, CUP_TASK)
    assert needle in error


def test_only_the_graphs_objects_are_available():
    """An object of the task that the survey's graph does not hold cannot be in the goal."""
    atom = Atom.parse(GOOD)
    assert goal_errors([atom], OBJECTS, CUP_TASK) == []
    (error,) = goal_errors([atom], [o for o in OBJECTS if o != "counter"], CUP_TASK)
    assert "unknown object 'counter'" in error and "available objects" in error


# --- against servers speaking each protocol -------------------------------------------------------------

@pytest.mark.parametrize("protocol", PROTOCOLS)
def test_text_only_request_carries_the_filled_appendix_prompt_and_no_image(serve, protocol):
    backend, reply, prompt_of = PROTOCOLS[protocol]
    server = serve(reply(GOOD))
    with backend(server) as vlm:
        goal = parser(vlm)(OBJECTS)
        record = vlm.requests[0]
    assert goal == (Literal(Atom("on", ("cup", "counter"))),)
    (req,) = server.seen
    body = req.body
    assert prompt_of(body) == goal_prompt(WORDS, OBJECTS, CUP_TASK.knowledge)
    assert "image" not in json.dumps(body) and "inline_data" not in json.dumps(body)
    if protocol == "openai":
        assert req.path == "/v1/chat/completions"
        assert body["messages"] == [{"role": "user", "content": prompt_of(body)}]
        assert body["model"] == "qwen2.5-vl" and body["temperature"] == 0 and body["max_tokens"] == vlm.text_max_tokens
        assert not {"structured_outputs", "guided_choice", "grammar", "logprobs"} & set(body)
    else:
        assert req.path == "/v1beta/models/gemini-test:generateContent"
        assert body["contents"] == [{"role": "user", "parts": [{"text": prompt_of(body)}]}]
        config = body["generationConfig"]
        assert config["temperature"] == 0 and config["maxOutputTokens"] == vlm.text_max_tokens
        assert config["thinkingConfig"] == {"thinkingBudget": 0}
        assert not {"responseMimeType", "responseSchema", "responseLogprobs", "logprobs"} & set(config)
    assert record.kind == "text" and record.purpose == "goal" and record.outcome == "answer"
    assert record.frame_id == "" and record.frame_sha1 is None and record.reply == GOOD


@pytest.mark.parametrize("protocol", PROTOCOLS)
def test_an_invalid_predicate_is_asked_again_with_the_error_and_the_correction_taken(serve, protocol):
    backend, reply, prompt_of = PROTOCOLS[protocol]
    server = serve(reply("in(cup, counter)"), reply(GOOD))
    with backend(server) as vlm:
        p = parser(vlm)
        goal = p(OBJECTS)
    assert [str(l) for l in goal] == [GOOD]
    first, second = (prompt_of(s.body) for s in server.seen)
    assert first == goal_prompt(WORDS, OBJECTS, CUP_TASK.knowledge)
    assert second.startswith(first + "\n\n")  # the appendix text unchanged, the error after it
    assert "Your previous answer was: in(cup, counter)" in second and "unknown predicate 'in'" in second
    rec = p.record
    assert rec.reasked and rec.error is None and [a.reply for a in rec.attempts] == ["in(cup, counter)", GOOD]
    assert "unknown predicate 'in'" in rec.attempts[0].error and rec.attempts[1].error is None
    report = rec.to_json()
    assert report["goal"] == [GOOD] and report["attempts"][1]["prompt"] == second


@pytest.mark.parametrize("protocol", PROTOCOLS)
def test_garbage_twice_is_one_clear_error(serve, protocol):
    backend, reply, _ = PROTOCOLS[protocol]
    server = serve(reply("Sure! The robot should move the cup."), reply("on(cup, the counter)"))
    with backend(server) as vlm, pytest.raises(GoalParseError) as err:
        parser(vlm)(OBJECTS)
    exc = err.value
    assert exc.exit_code == EXIT_BAD_INPUT and len(server.seen) == 2
    message = str(exc)
    assert message.startswith("--goal: ") and "\n" not in message
    assert repr(WORDS) in message and "asked again" in message and "format" in message
    assert exc.record.goal is None and [a.outcome for a in exc.record.attempts] == ["answer", "answer"]


@pytest.mark.parametrize("protocol", PROTOCOLS)
def test_a_server_that_never_answers_is_one_clear_error_within_the_deadline(serve, protocol):
    backend, _, _ = PROTOCOLS[protocol]
    server = serve(HANG)
    policy = RetryPolicy(timeout_s=0.3, deadline_s=0.8, attempts=4, backoff_s=0.05)
    t0 = time.monotonic()
    with backend(server, policy) as vlm, pytest.raises(GoalParseError) as err:
        parser(vlm)(OBJECTS)
    took = time.monotonic() - t0
    assert took < policy.deadline_s + 0.5  # no re-ask after no reply: it would only wait as long again
    (attempt,) = err.value.record.attempts
    assert attempt.reply is None and attempt.outcome == "timeout"
    assert "(asked once): timeout: no reply within the timeout" in str(err.value)


@pytest.mark.parametrize("reply,outcome", [
    ((404, {}, {"error": {"message": "model 'qwen2.5-vl' not found"}}), "http_error"),
    ((503, {}, {"error": "overloaded"}), "server_error"),
])
def test_no_reply_from_the_model_is_not_asked_again(serve, reply, outcome):
    server = serve(reply)
    with openai_at(server) as vlm, pytest.raises(GoalParseError) as err:
        parser(vlm)(OBJECTS)
    (attempt,) = err.value.record.attempts
    assert attempt.outcome == outcome and attempt.reply is None and f"(asked once): {outcome}:" in str(err.value)


def test_a_refusal_is_asked_again(serve):
    server = serve(chat("", refusal="I can't help with that."), chat(GOOD))
    with openai_at(server) as vlm:
        p = parser(vlm)
        assert [str(l) for l in p(OBJECTS)] == [GOOD]
    assert [a.outcome for a in p.record.attempts] == ["refusal", "answer"]
    assert "Your previous answer was: (nothing)" in server.seen[1].body["messages"][0]["content"]


@pytest.mark.parametrize("protocol,cut", [("openai", chat(GOOD, finish="length")),
                                          ("gemini", generate(GOOD, finish="MAX_TOKENS"))])
def test_a_reply_cut_off_at_the_token_budget_is_not_a_goal(serve, protocol, cut):
    backend, reply, _ = PROTOCOLS[protocol]
    server = serve(cut, reply("on(cup, counter), closed(door_lk)"))
    with backend(server) as vlm:
        p = parser(vlm)
        goal = p(OBJECTS)
    assert p.record.attempts[0].outcome == "unparsed" and "token budget" in p.record.attempts[0].error
    assert [str(l) for l in goal] == [GOOD, "closed(door_lk)"]


# --- the command line and the runner -------------------------------------------------------------------

def test_offline_a_goal_in_words_is_refused_in_one_line(cli):
    code, out, err = cli("run", TREES / "collect_cup.yaml", "--goal", WORDS)
    assert code == EXIT_BAD_INPUT and out == ""
    assert err.strip().splitlines() == [err.strip()] and err.startswith("vap-bt: --goal: the sim VLM does not parse")


def instruction_only(tmp_path, name="words"):
    """collect_cup without its goal: atoms (its instruction: stays)."""
    raw = yaml.safe_load((TREES / "collect_cup.yaml").read_text())
    del raw["goal"]
    raw["domain"] = str(HOUSEHOLD)
    path = tmp_path / f"{name}.yaml"
    path.write_text(yaml.safe_dump(raw))
    return path


def test_a_task_with_only_an_instruction_needs_a_real_vlm(cli, tmp_path):
    path = instruction_only(tmp_path)
    assert load(path).planning.goal == ()
    code, _, err = cli("run", path)
    assert code == EXIT_BAD_INPUT and f"{path}: field goal: no goal: atoms" in err and "--vlm openai|gemini" in err
    code, _, err = cli("export", path)
    assert code == EXIT_BAD_INPUT and "field goal" in err


def goal_server(serve, goal_reply: str):
    """An OpenAI-compatible server: the goal prompt gets ``goal_reply``, every question "yes"."""
    head = book().goal_parsing.split("\n", 1)[0]

    def script(i, seen):
        text = seen.body["messages"][0]["content"]
        return chat(goal_reply if isinstance(text, str) and text.startswith(head) else "yes")

    return serve(script=script)


def run_report(cli, tmp_path, *argv):
    report = tmp_path / "report.json"
    code, out, err = cli("run", *argv, "--report", report, "-q")
    return code, json.loads(report.read_text()), err


def test_a_run_with_a_goal_in_words_over_zenoh_pursues_the_parsed_goal(cli, serve, tmp_path):
    server = goal_server(serve, GOOD)
    code, rep, err = run_report(cli, tmp_path, TREES / "collect_cup.yaml", "--world", "symbolic",
                                "--vlm", "openai", "--vlm-url", f"{server.url}/v1", "--vlm-model", "m", "--goal", WORDS,
                                "--seed", "3", "--verify", "none")
    assert code in (0, 1), err  # success is the world's to say; the run ends either way
    parsed = rep["goal_parsing"]
    assert parsed["goal"] == [GOOD] and parsed["source"] == "--goal" and parsed["instruction"] == WORDS
    assert parsed["attempts"][0]["prompt"] == goal_prompt(WORDS, parsed["objects"], CUP_TASK.knowledge)
    assert parsed["file_goal"] == [GOOD] and rep["task"]["goal"] == [GOOD]
    assert rep["success"] <= rep["goal_satisfied"]  # never a success the world denies
    assert rep["vlm"]["backend"] == "openai" and rep["vlm"]["by_purpose"]["goal"] == 1
    records = rep["vlm"]["requests"]
    assert [r["purpose"] for r in records if r["kind"] == "text"] == ["goal"]
    # the symbolic world's frames carry no pixels: what the survey asks is an abstention, nothing is sent
    assert {r["outcome"] for r in records if r["kind"] != "text"} <= {"no_image"}
    assert len(server.seen) == 1


def test_a_real_vlm_in_a_world_without_pictures_is_refused_unless_it_only_parses_goals(cli, serve):
    """Every check it was asked would be an abstention: 355 of them, then "stuck" (issue 26)."""
    server = goal_server(serve, GOOD)
    code, _, err = cli("run", TREES / "collect_cup.yaml", "--world", "symbolic", "--vlm", "openai",
                       "--vlm-url", f"{server.url}/v1", "--vlm-model", "m", "--goal", WORDS)
    assert code == EXIT_BAD_INPUT and err.startswith("vap-bt: --vlm: the openai VLM answers from pictures")
    assert len(err.strip().splitlines()) == 1 and "--verify none" in err and not server.seen


def test_a_vlm_server_that_is_not_there_is_one_line_and_exit_4_within_seconds(cli):
    """Nothing listens on 127.0.0.1:9 (discard, never served here): the run says so before any
    world starts, instead of spending every query's retries (39 warnings in 150 s)."""
    started = time.monotonic()
    code, _, err = cli("run", TREES / "collect_cup.yaml", "--world", "pybullet", "--vlm", "openai",
                       "--vlm-url", "http://127.0.0.1:9/v1", "--vlm-model", "m", "-q")
    assert code == EXIT_TRANSPORT and time.monotonic() - started < 20
    assert err.startswith("vap-bt: --vlm-url: no VLM server answers at http://127.0.0.1:9/v1: nothing accepts")
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err


def test_an_instruction_is_parsed_and_the_world_judges_the_parsed_goal(cli, serve, tmp_path):
    server = goal_server(serve, "holding(cup)")
    code, rep, err = run_report(cli, tmp_path, instruction_only(tmp_path), "--world", "symbolic",
                                "--vlm", "openai", "--vlm-url", f"{server.url}/v1", "--vlm-model", "m",
                                "--verify", "none", "--no-injection", "--transport", "inproc")
    assert code == 0, err
    parsed = rep["goal_parsing"]
    assert parsed["source"] == "instruction" and parsed["instruction"].startswith("Take the cup")
    assert parsed["goal"] == ["holding(cup)"] and parsed["file_goal"] is None
    assert rep["success"] and rep["goal_satisfied"] and rep["task"]["goal"] == ["holding(cup)"]
    assert rep["plans"][0]["actions"][-1].startswith("grasp(cup")


def test_parse_instruction_keeps_the_file_goal_as_the_reference(cli, serve, tmp_path):
    server = goal_server(serve, "holding(cup)")
    code, rep, err = run_report(cli, tmp_path, TREES / "collect_cup.yaml", "--world", "symbolic",
                                "--parse-instruction", "--vlm", "openai", "--vlm-url", f"{server.url}/v1",
                                "--vlm-model", "m", "--verify", "none", "--no-injection", "--transport", "inproc")
    assert code == 0, err
    parsed = rep["goal_parsing"]
    assert parsed["goal"] == ["holding(cup)"] and parsed["file_goal"] == [GOOD]
    assert rep["goal_satisfied"] and parsed["file_goal_satisfied"] is False


def test_a_goal_the_vlm_cannot_give_ends_the_run_with_exit_2_and_a_report(cli, serve, tmp_path):
    server = goal_server(serve, "I would put the cup on the counter.")
    code, rep, err = run_report(cli, tmp_path, TREES / "collect_cup.yaml", "--world", "symbolic",
                                "--vlm", "openai", "--vlm-url", f"{server.url}/v1", "--vlm-model", "m", "--goal", WORDS,
                                "--transport", "inproc", "--verify", "none")
    assert code == EXIT_BAD_INPUT and err.startswith("vap-bt: --goal: the openai VLM gave no usable goal")
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    parsed = rep["goal_parsing"]
    assert not rep["success"] and rep["reason"] == "goal not parsed" and parsed["goal"] is None
    assert [a["reply"] for a in parsed["attempts"]] == ["I would put the cup on the counter."] * 2
    assert parsed["reasked"] and "format" in parsed["error"] and len(server.seen) == 2


@pytest.mark.slow
def test_in_pybullet_the_questions_reach_the_same_backend_with_the_frame_attached(cli, serve, tmp_path):
    """The frames have pixels here: every verification question goes to the server too, image first."""
    server = goal_server(serve, GOOD)
    code, rep, err = run_report(cli, tmp_path, TREES / "collect_cup.yaml", "--world", "pybullet", "--vlm", "openai",
                                "--vlm-url", f"{server.url}/v1", "--vlm-model", "m", "--goal", WORDS, "--seed", "3")
    assert rep["goal_parsing"]["goal"] == [GOOD] and rep["task"]["goal"] == [GOOD]
    # a model that says yes to everything is believed; the world's word decides the exit code
    assert code == (0 if rep["success"] and rep["goal_satisfied"] else 1), err
    records = rep["vlm"]["requests"]
    questions = [r for r in records if r["kind"] != "text"]
    assert questions and all(r["frame_sha1"] for r in questions)
    # "yes" answers every yes/no question; to "which way to look" (asked when the detector vetoes a
    # view) it is no answer at all, and the record says so
    assert all(r["outcome"] == ("answer" if r["kind"] == "yesno" else "unparsed") for r in questions), \
        [(r["kind"], r["outcome"]) for r in questions]
    assert len(server.seen) == len(records) == rep["vlm_queries"]
    images = [s for s in server.seen if isinstance(s.body["messages"][0]["content"], list)]
    assert len(images) == len(questions)
    assert all(s.body["messages"][0]["content"][0]["type"] == "image_url" for s in images)
