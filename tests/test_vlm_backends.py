"""The HTTP VLM backends against local servers (127.0.0.1) that speak each protocol.

The servers here are real HTTP servers in a thread: they receive the backend's real requests,
check nothing themselves, and reply from a script (a reply, an error status, garbage, or no
reply at all). The tests read what the server received — the request shape — and what the
backend made of the reply: an answer, or an abstention with a record saying why; never an
exception and never an answer the reply does not give.
"""

from __future__ import annotations

import base64
import hashlib
import json
import math
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import cv2
import numpy as np
import pytest

from vap_bt.domain.atoms import Atom
from vap_bt.errors import EXIT_BAD_INPUT, InputError
from vap_bt.perception import prompts
from vap_bt.perception.backends import GeminiVLM, OpenAICompatVLM, RetryPolicy, make_backend
from vap_bt.perception.backends.reply import TokenChoice, option_confidence, read_answer
from vap_bt.perception.vlm import Query
from vap_bt.robot.frame import Frame
from vap_bt.robot.camera import VIEW_DIRECTIONS

from conftest import household_profile

HANG = "hang"  # a scripted "reply": keep the connection open and never answer
CUP = Atom("on", ("cup", "table"))
QUESTION = household_profile().questions(CUP)[0]
YESNO = Query(prompts.predicate_query(QUESTION), about=(CUP,), objects=CUP.args)
VIEWPOINT = Query(prompts.viewpoint_selection(QUESTION, "cup"), kind="choice", purpose="viewpoint",
                  about=(CUP,), objects=CUP.args, options=VIEW_DIRECTIONS)
RGB = np.random.default_rng(0).integers(0, 256, (24, 32, 3), dtype=np.uint8)  # not square: w/h swaps show
FRAME = Frame(frame_id="frame-7", stamp=1.5, rgb=RGB)
FAST = RetryPolicy(timeout_s=0.5, deadline_s=2.0, attempts=3, backoff_s=0.05, backoff_max_s=0.2)


@dataclass
class Seen:
    """One request as the server received it."""

    path: str
    headers: dict[str, str]
    body: object
    t: float


class ProtocolServer:
    """An HTTP server on 127.0.0.1 whose replies come from ``script(request_index, request)``.

    A reply is ``(status, headers, body)`` (a dict body is sent as JSON) or :data:`HANG`.
    """

    def __init__(self, script) -> None:
        self.script, self.seen, self.in_flight, self.most_in_flight = script, [], 0, 0
        self.release = threading.Event()
        self._lock = threading.Lock()
        server = self

        class Handler(BaseHTTPRequestHandler):
            def do_POST(self):  # noqa: N802 (http.server's naming)
                raw = self.rfile.read(int(self.headers.get("content-length", 0)))
                try:
                    body = json.loads(raw)
                except ValueError:
                    body = raw
                seen = Seen(self.path, {k.lower(): v for k, v in self.headers.items()}, body, time.monotonic())
                with server._lock:
                    index = len(server.seen)
                    server.seen.append(seen)
                    server.in_flight += 1
                    server.most_in_flight = max(server.most_in_flight, server.in_flight)
                try:
                    reply = server.script(index, seen)
                    if reply == HANG:
                        server.release.wait(10)
                        return
                    status, headers, payload = reply
                    data = json.dumps(payload).encode() if isinstance(payload, (dict, list)) else str(payload).encode()
                    self.send_response(status)
                    for k, v in {"content-type": "application/json", **headers}.items():
                        self.send_header(k, v)
                    self.send_header("content-length", str(len(data)))
                    self.end_headers()
                    self.wfile.write(data)
                finally:
                    with server._lock:
                        server.in_flight -= 1

            def log_message(self, *args):  # keep test output clean
                pass

        self.httpd = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.httpd.daemon_threads = True
        threading.Thread(target=self.httpd.serve_forever, kwargs={"poll_interval": 0.02}, daemon=True).start()

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.httpd.server_address[1]}"

    def close(self) -> None:
        self.release.set()
        self.httpd.shutdown()
        self.httpd.server_close()


@pytest.fixture
def serve():
    """``serve(*replies)`` starts a server replying with each in turn (the last one repeats)."""
    servers = []

    def start(*replies, script=None):
        s = ProtocolServer(script or (lambda i, _seen: replies[min(i, len(replies) - 1)]))
        servers.append(s)
        return s

    yield start
    for s in servers:
        s.close()


def chat(text, tokens=(), finish="stop", **message):
    """An OpenAI chat-completions reply; ``tokens``: (token, logprob, [(candidate, logprob), ...])."""
    choice = {"index": 0, "message": {"role": "assistant", "content": text, **message}, "finish_reason": finish}
    if tokens:
        choice["logprobs"] = {"content": [{"token": t, "logprob": lp, "top_logprobs": [
            {"token": c, "logprob": cl} for c, cl in top]} for t, lp, top in tokens]}
    return 200, {}, {"id": "cmpl-1", "object": "chat.completion", "model": "m", "choices": [choice]}


def generate(text, tokens=(), finish="STOP"):
    """A Gemini generateContent reply, with ``logprobsResult`` when ``tokens`` are given."""
    cand = {"content": {"role": "model", "parts": [{"text": text}]}, "finishReason": finish, "index": 0}
    if tokens:
        cand["logprobsResult"] = {
            "chosenCandidates": [{"token": t, "logProbability": lp} for t, lp, _ in tokens],
            "topCandidates": [{"candidates": [{"token": c, "logProbability": cl} for c, cl in top]}
                              for _, _, top in tokens]}
    return 200, {}, {"candidates": [cand], "modelVersion": "gemini-test"}


def openai(server, policy=FAST, **kw) -> OpenAICompatVLM:
    return OpenAICompatVLM(f"{server.url}/v1", "qwen2.5-vl", policy=policy, **kw)


def gemini_at(server, policy=FAST, **kw) -> GeminiVLM:
    return GeminiVLM(f"{server.url}/v1beta", "gemini-test", api_key="gm-key-42", policy=policy, **kw)


def decoded(b64: str) -> np.ndarray:
    png = base64.b64decode(b64)
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    return cv2.cvtColor(cv2.imdecode(np.frombuffer(png, np.uint8), cv2.IMREAD_COLOR), cv2.COLOR_BGR2RGB)


# --- OpenAI-compatible ----------------------------------------------------------------------------

def test_openai_request_carries_model_frame_appendix_prompt_and_constraints(serve):
    server = serve(chat("yes"))
    with openai(server, api_key="sk-test-123") as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is True and answer.raw == "yes"
    (req,) = server.seen
    body = req.body
    assert req.path == "/v1/chat/completions"
    assert req.headers["authorization"] == "Bearer sk-test-123"
    assert body["model"] == "qwen2.5-vl" and body["temperature"] == 0 and 0 < body["max_tokens"] <= 16
    (message,) = body["messages"]
    image, text = message["content"]
    assert message["role"] == "user" and image["type"] == "image_url" and text["type"] == "text"
    url = image["image_url"]["url"]
    assert url.startswith("data:image/png;base64,")
    assert np.array_equal(decoded(url.split(",", 1)[1]), RGB)  # lossless, right size, RGB order
    assert text["text"] == YESNO.prompt  # the appendix template, verbatim, around the paraphrase
    assert "Analyze this image carefully." in text["text"] and QUESTION in text["text"]
    assert body["structured_outputs"] == {"choice": ["yes", "no"]} and body["guided_choice"] == ["yes", "no"]
    assert body["grammar"] == 'root ::= "yes" | "no"'
    assert body["logprobs"] is True and body["top_logprobs"] == 5


def test_openai_without_key_sends_no_authorization_and_never_reports_a_key(serve):
    server = serve(chat("no"))
    with openai(server) as vlm:
        assert vlm.ask(YESNO, FRAME).value is False
        assert "authorization" not in server.seen[0].headers
        assert vlm.describe()["api_key"] == "unset"
    with openai(server, api_key="sk-secret-999") as vlm:
        vlm.ask(YESNO, FRAME)
        shown = json.dumps(vlm.describe()) + json.dumps([r.to_json() for r in vlm.requests])
    assert "sk-secret-999" not in shown and '"api_key": "set"' in shown


def test_openai_logprobs_give_the_answer_its_confidence(serve):
    # first answer token "Yes"; the top candidates split 0.70 + 0.05 (yes) against 0.20 (no)
    top = [("Yes", math.log(0.70)), ("No", math.log(0.20)), (" yes", math.log(0.05)), ("The", math.log(0.04))]
    server = serve(chat("Yes", tokens=[("Yes", math.log(0.70), top)]))
    with openai(server) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is True
    assert answer.confidence == pytest.approx(0.75 / 0.95)
    assert answer.p_yes == pytest.approx(0.75 / 0.95)
    assert vlm.requests[0].confidence == pytest.approx(0.75 / 0.95)


def test_openai_no_with_logprobs_gives_p_yes_below_half(serve):
    top = [("no", math.log(0.6)), ("yes", math.log(0.3))]
    server = serve(chat("no", tokens=[("no", math.log(0.6), top)]))
    with openai(server) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is False and answer.confidence == pytest.approx(2 / 3)
    assert answer.p_yes == pytest.approx(1 / 3)


def test_choice_query_constrains_to_the_options_and_parses_exactly_one(serve):
    top = [("left", math.log(0.5)), ("closer", math.log(0.3)), ("right", math.log(0.2))]
    server = serve(chat("left", tokens=[("left", math.log(0.5), top)]), chat("left or right"))
    with openai(server) as vlm:
        first = vlm.ask(VIEWPOINT, FRAME)
        second = vlm.ask(VIEWPOINT, FRAME)
    assert first.value == "left" and first.confidence == pytest.approx(0.5)
    assert second.value is None  # two options named: no answer
    body = server.seen[0].body
    assert body["structured_outputs"] == {"choice": list(VIEW_DIRECTIONS)}
    assert "Options: left, right, front, behind, above, closer" in body["messages"][0]["content"][1]["text"]
    assert [r.outcome for r in vlm.requests] == ["answer", "unparsed"]


@pytest.mark.parametrize("reply,outcome", [
    ((200, {}, "this is not JSON {"), "malformed"),
    ((200, {}, ["a", "list"]), "malformed"),
    ((200, {}, {"unexpected": "shape"}), "empty"),
    ((200, {}, {"choices": []}), "empty"),
    (chat(None), "empty"),
    (chat("purple monkey dishwasher"), "unparsed"),
    (chat("I can't help with that."), "refusal"),
    (chat("No, I cannot help with identifying that."), "refusal"),  # opens with "no", still no answer
    (chat("Yes and no."), "unparsed"),
    (chat("", refusal="I'm unable to assist with this request."), "refusal"),
    (chat("yes", finish="content_filter"), "refusal"),
    ((401, {}, {"error": {"message": "invalid api key"}}), "http_error"),
])
def test_openai_unusable_replies_are_abstentions_without_retry(serve, reply, outcome):
    server = serve(reply)
    with openai(server) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is None and answer.confidence is None
    assert vlm.requests[0].outcome == outcome
    assert len(server.seen) == 1  # the same question again would get the same reply


def test_429_with_retry_after_is_waited_then_answered(serve):
    server = serve((429, {"retry-after": "0.3"}, {"error": {"message": "slow down"}}), chat("yes"))
    with openai(server) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is True
    assert vlm.requests[0].attempts == 2 and vlm.requests[0].outcome == "answer"
    assert server.seen[1].t - server.seen[0].t >= 0.3  # the server's wait was honoured


def test_429_asking_for_longer_than_the_deadline_abstains_at_once(serve):
    server = serve((429, {"retry-after": "30"}, {"error": {"message": "quota"}}), chat("yes"))
    with openai(server) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    rec = vlm.requests[0]
    assert answer.value is None and rec.outcome == "rate_limited" and rec.status == 429
    assert len(server.seen) == 1 and rec.latency_s < FAST.deadline_s


def test_500_then_success_is_retried(serve):
    server = serve((500, {}, "internal error"), (503, {}, "overloaded"), chat("no"))
    with openai(server) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is False and vlm.requests[0].attempts == 3


def test_500_forever_abstains_after_the_attempts(serve):
    server = serve((500, {}, "internal error"))
    with openai(server) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    rec = vlm.requests[0]
    assert answer.value is None and rec.outcome == "server_error" and rec.status == 500
    assert len(server.seen) == FAST.attempts == rec.attempts


def test_a_server_that_never_answers_is_an_abstention_within_the_deadline(serve):
    server = serve(HANG)
    policy = RetryPolicy(timeout_s=0.3, deadline_s=0.8, attempts=4, backoff_s=0.05)
    with openai(server, policy=policy) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    rec = vlm.requests[0]
    assert answer.value is None and rec.outcome == "timeout" and rec.status is None
    assert 2 <= len(server.seen) <= 4  # retried, but only while the deadline allowed
    assert rec.latency_s < policy.deadline_s + 0.3


def test_an_unreachable_server_is_an_abstention(serve):
    server = serve(chat("yes"))
    url = server.url
    server.close()  # nothing listens on that port any more
    with OpenAICompatVLM(f"{url}/v1", "m", policy=FAST) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is None and vlm.requests[0].outcome == "unreachable"


def test_a_server_that_stops_answering_ends_the_episode_not_each_question(serve):
    """The run's wrapper (StopWhenSilent): answers pass; a query whose retries found no server at
    all, or no response within the deadline, is a TransportError ("transport down"); an error
    status is a response — the server is there — and stays an abstention."""
    from vap_bt.errors import TransportError
    from vap_bt.perception.backends.base import StopWhenSilent

    server = serve(chat("yes"), (500, {}, "overloaded"), (500, {}, "overloaded"), HANG)
    policy = RetryPolicy(timeout_s=0.3, deadline_s=0.8, attempts=2, backoff_s=0.05)
    with openai(server, policy=policy) as vlm:
        watched = StopWhenSilent(vlm)
        assert watched.ask(YESNO, FRAME).value is True and vlm.silent is None
        assert watched.ask(YESNO, FRAME).value is None and vlm.silent is None  # 500 twice: an answer of sorts
        with pytest.raises(TransportError, match=r"the VLM server at http://127\.0\.0\.1:\d+/v1 stopped "
                                                 r"answering \(timeout after 2 attempt\(s\)"):
            watched.ask(YESNO, FRAME)
    gone = serve(chat("yes"))
    url = gone.url
    gone.close()
    with OpenAICompatVLM(f"{url}/v1", "m", policy=FAST) as vlm:
        with pytest.raises(TransportError, match=r"stopped answering \(unreachable after 3 attempt\(s\)"):
            StopWhenSilent(vlm).ask(YESNO, FRAME)


def test_a_rejected_optional_field_is_dropped_and_the_question_asked_again(serve):
    def script(i, seen):
        if "guided_choice" in seen.body:
            return 400, {}, {"error": {"message": "Unrecognized request argument supplied: guided_choice"}}
        return chat("yes")

    server = serve(script=script)
    with openai(server) as vlm:
        assert vlm.ask(YESNO, FRAME).value is True
        assert vlm.ask(YESNO, FRAME).value is True
        assert vlm.describe()["dropped"] == ["guided_choice"]
    assert len(server.seen) == 3  # rejected once, then never sent again
    assert "structured_outputs" in server.seen[2].body and "guided_choice" not in server.seen[2].body


def test_concurrent_questions_of_a_round_are_each_answered_and_recorded(serve):
    def script(i, seen):
        time.sleep(0.1)  # long enough for the questions to overlap
        text = seen.body["messages"][0]["content"][1]["text"]
        return chat("yes" if "cup" in text else "no")

    server = serve(script=script)
    atoms = [Atom("on", ("cup", "table")), Atom("on", ("plate", "table"))] * 4
    queries = [Query(prompts.predicate_query(household_profile().questions(a)[0]), about=(a,)) for a in atoms]
    with openai(server) as vlm, ThreadPoolExecutor(max_workers=8) as pool:
        answers = list(pool.map(lambda q: vlm.ask(q, FRAME), queries))
    assert [a.value for a in answers] == [a.args[0] == "cup" for a in atoms]
    assert sorted(r.prompt for r in vlm.requests) == sorted(q.prompt for q in queries)
    assert server.most_in_flight > 1


def test_every_request_is_recorded_for_the_report(serve):
    server = serve(chat("Yes."))
    seen = []
    with openai(server, on_request=seen.append) as vlm:
        vlm.ask(YESNO, FRAME)
    (rec,) = vlm.requests
    assert seen == [rec]
    assert rec.purpose == "predicate" and rec.prompt == YESNO.prompt and rec.frame_id == "frame-7"
    assert rec.frame_sha1 == hashlib.sha1(RGB.tobytes()).hexdigest() and rec.image_size == (32, 24)
    assert rec.reply == "Yes." and rec.status == 200 and rec.attempts == 1 and rec.value is True
    assert rec.latency_s > 0 and json.loads(json.dumps(rec.to_json()))["outcome"] == "answer"


@pytest.mark.parametrize("rgb", [None, np.zeros((4, 4), np.uint8), np.zeros((4, 4, 3), np.float32)],
                         ids=["no-pixels", "grey", "float"])
def test_a_frame_without_an_rgb_image_is_an_abstention_and_sends_nothing(serve, rgb):
    server = serve(chat("yes"))
    with openai(server) as vlm:
        answer = vlm.ask(YESNO, Frame(frame_id="symbolic-1", stamp=0.0, rgb=rgb))
    assert answer.value is None and vlm.requests[0].outcome == "no_image" and server.seen == []


def test_close_cuts_a_retry_wait_short(serve):
    server = serve((429, {"retry-after": "5"}, {"error": {"message": "wait"}}), chat("yes"))
    vlm = openai(server, policy=RetryPolicy(timeout_s=0.5, deadline_s=10.0, attempts=3))
    with ThreadPoolExecutor(max_workers=1) as pool:
        pending = pool.submit(vlm.ask, YESNO, FRAME)
        while not (server.seen and server.in_flight == 0):  # the 429 has been sent
            time.sleep(0.01)
        time.sleep(0.05)
        vlm.close()  # e.g. the run is halted while a query waits out a rate limit
        answer = pending.result(timeout=2.0)  # not the 5 s the server asked for
    # "unreachable" only if this machine was too slow to read the 429 before the close
    assert answer.value is None and vlm.requests[0].outcome in ("rate_limited", "unreachable")
    assert len(server.seen) == 1


# --- Gemini ---------------------------------------------------------------------------------------

def test_gemini_request_carries_image_enum_schema_no_thinking_logprobs_and_key(serve):
    server = serve(generate("no"))
    with gemini_at(server) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is False
    (req,) = server.seen
    assert req.path == "/v1beta/models/gemini-test:generateContent"
    assert req.headers["x-goog-api-key"] == "gm-key-42" and "key=" not in req.path
    (content,) = req.body["contents"]
    image, text = content["parts"]
    assert content["role"] == "user" and image["inline_data"]["mime_type"] == "image/png"
    assert np.array_equal(decoded(image["inline_data"]["data"]), RGB)
    assert text["text"] == YESNO.prompt
    config = req.body["generationConfig"]
    assert config["temperature"] == 0 and 0 < config["maxOutputTokens"] <= 16
    assert config["responseMimeType"] == "text/x.enum"
    assert config["responseSchema"] == {"type": "STRING", "enum": ["yes", "no"]}
    assert config["thinkingConfig"] == {"thinkingBudget": 0}
    assert config["responseLogprobs"] is True and config["logprobs"] == 5


def test_gemini_choice_uses_the_options_as_enum_and_logprobs_give_confidence(serve):
    top = [("behind", math.log(0.6)), ("above", math.log(0.2)), ("be", math.log(0.1))]
    server = serve(generate("behind", tokens=[("behind", math.log(0.6), top)]))
    with gemini_at(server) as vlm:
        answer = vlm.ask(VIEWPOINT, FRAME)
    assert answer.value == "behind" and answer.confidence == pytest.approx(0.7 / 0.9)
    assert server.seen[0].body["generationConfig"]["responseSchema"]["enum"] == list(VIEW_DIRECTIONS)


def test_gemini_rate_limit_waits_the_retry_info_delay(serve):
    quota = {"error": {"code": 429, "status": "RESOURCE_EXHAUSTED", "message": "Quota exceeded", "details": [
        {"@type": "type.googleapis.com/google.rpc.QuotaFailure", "violations": []},
        {"@type": "type.googleapis.com/google.rpc.RetryInfo", "retryDelay": "0.4s"}]}}
    server = serve((429, {}, quota), generate("yes"))
    with gemini_at(server) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is True and vlm.requests[0].attempts == 2
    assert server.seen[1].t - server.seen[0].t >= 0.4


def test_gemini_model_without_logprobs_is_asked_again_without_them(serve):
    def script(i, seen):
        if "responseLogprobs" in seen.body["generationConfig"]:
            return 400, {}, {"error": {"code": 400, "status": "INVALID_ARGUMENT",
                                       "message": "Logprobs is not enabled for models/gemini-test"}}
        return generate("yes")

    server = serve(script=script)
    with gemini_at(server) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is True and answer.confidence is None
    assert vlm.describe()["dropped"] == ["logprobs"] and len(server.seen) == 2
    assert server.seen[1].body["generationConfig"]["thinkingConfig"] == {"thinkingBudget": 0}


@pytest.mark.parametrize("reply,outcome", [
    ((200, {}, {"promptFeedback": {"blockReason": "SAFETY"}}), "refusal"),
    (generate("", finish="SAFETY"), "refusal"),
    (generate("", finish="MAX_TOKENS"), "empty"),
    (generate("Maybe"), "unparsed"),
    (generate("I'm sorry, I can't determine that."), "refusal"),
    ((200, {}, "<html>bad gateway</html>"), "malformed"),
    ((400, {}, {"error": {"code": 400, "message": "API key not valid. Please pass a valid API key."}}), "http_error"),
])
def test_gemini_unusable_replies_are_abstentions(serve, reply, outcome):
    server = serve(reply)
    with gemini_at(server) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is None and vlm.requests[0].outcome == outcome and len(server.seen) == 1


def test_gemini_server_that_never_answers_is_an_abstention(serve):
    server = serve(HANG)
    policy = RetryPolicy(timeout_s=0.25, deadline_s=0.6, attempts=2, backoff_s=0.05)
    with gemini_at(server, policy=policy) as vlm:
        answer = vlm.ask(YESNO, FRAME)
    assert answer.value is None and vlm.requests[0].outcome == "timeout" and len(server.seen) == 2


# --- paraphrases written by the backend (the protocol's optional part) ---------------------------

WRITTEN = ["Is the truck {X} parked at the {Y}?", "Is the truck {X} standing at the {Y}?",
           "Can you see the truck {X} at the {Y}?", "Is the truck {X} located at the {Y}?",
           "Has the truck {X} arrived at the {Y}?"]


def test_openai_writes_paraphrases_in_a_text_only_request(serve):
    server = serve(chat("Here you are:\n" + "\n".join(f"{i}. {q}" for i, q in enumerate(WRITTEN, 1))))
    with openai(server) as vlm:
        texts = vlm.paraphrase("at", ("truck", "location"), 5)
        rec = vlm.requests[0]
    assert texts == WRITTEN
    (req,) = server.seen
    body = req.body
    assert req.path == "/v1/chat/completions" and body["model"] == "qwen2.5-vl" and body["temperature"] == 0
    (message,) = body["messages"]
    assert isinstance(message["content"], str), "text only: no image"
    assert "at(X - truck, Y - location)" in message["content"] and "{X}, {Y}" in message["content"]
    assert not {"structured_outputs", "guided_choice", "grammar", "logprobs"} & set(body)
    assert rec.purpose == "paraphrase" and rec.outcome == "answer" and rec.frame_id == ""


def test_gemini_writes_paraphrases_in_a_text_only_request(serve):
    server = serve(generate("\n".join(WRITTEN)))
    with gemini_at(server) as vlm:
        texts = vlm.paraphrase("at", ("truck", "location"), 5)
    assert texts == WRITTEN
    body = server.seen[0].body
    (part,) = body["contents"][0]["parts"]
    assert set(part) == {"text"} and "at(X - truck, Y - location)" in part["text"]
    config = body["generationConfig"]
    assert config["temperature"] == 0 and config["thinkingConfig"] == {"thinkingBudget": 0}
    assert "responseSchema" not in config and "responseLogprobs" not in config


@pytest.mark.parametrize("reply,outcome", [
    (chat("Is the truck at the depot?\nIs it there?"), "unparsed"),  # no placeholders: unusable
    (chat("\n".join(WRITTEN[:3])), "unparsed"),  # too few
    (chat("", refusal="I cannot help with that."), "refusal"),
    ((500, {}, "internal error"), "server_error"),
    (HANG, "timeout"),
])
def test_unusable_paraphrase_replies_give_none_and_the_profile_uses_templates(serve, reply, outcome):
    from vap_bt.domain.pddl import load_task
    from vap_bt.perception.paraphrase import template_paraphrases
    from vap_bt.perception.profile import resolve

    from conftest import DOMAINS

    server = serve(reply)
    policy = RetryPolicy(timeout_s=0.2, deadline_s=0.5, attempts=2, backoff_s=0.05)
    with openai(server, policy=policy) as vlm:
        assert vlm.paraphrase("at", ("truck", "location"), 5) is None
        assert vlm.requests[0].outcome == outcome
        task = load_task(DOMAINS / "logistics-domain.pddl", DOMAINS / "logistics-p1.pddl")
        at = resolve(task.knowledge, paraphraser=vlm).get("at", 2)
    assert at.origin == "templates" and at.paraphrases == tuple(template_paraphrases("at", ("physobj", "place")))
    assert at.fallback == "openai (qwen2.5-vl) wrote no 5 usable paraphrases"


def test_a_profile_resolved_with_a_writing_backend_uses_and_reports_its_paraphrases(serve):
    from vap_bt.domain.pddl import load_task
    from vap_bt.perception.profile import resolve

    from conftest import DOMAINS

    def script(i, seen):
        text = seen.body["messages"][0]["content"]
        name = text.split("Predicate: ", 1)[1].split("(", 1)[0]
        holes = " ".join(f"{{{c}}}" for c in "XY"[:text.count(" - ")])
        return chat("\n".join(f"Does {name} hold ({k}) for {holes}?" for k in range(5)))

    server = serve(script=script)
    with openai(server) as vlm:
        task = load_task(DOMAINS / "logistics-domain.pddl", DOMAINS / "logistics-p1.pddl")
        profile = resolve(task.knowledge, paraphraser=vlm)
        asked = [r.prompt for r in vlm.requests]
    assert len(asked) == 2  # at/2 and in/2: in-city/2 is rigid (the map's), not asked
    generated = {g["predicate"]: g for g in profile.to_json()["generated"]}
    assert set(generated) == {"at/2", "in/2"}
    assert generated["in/2"] == {"predicate": "in/2", "by": "openai (qwen2.5-vl)",
                                 "texts": [f"Does in hold ({k}) for {{X}} {{Y}}?" for k in range(5)]}
    assert profile.questions(Atom("in", ("pkg1", "truck1")))[0] == "Does in hold (0) for pkg1 truck1?"


# --- reading replies, and the factory ------------------------------------------------------------

def test_reply_reading_is_strict():
    assert read_answer("Yes.", "yesno", ("yes", "no")) is True
    assert read_answer("no, the cup is on the floor", "yesno", ("yes", "no")) is False
    assert read_answer("Yes, but no cup is visible", "yesno", ("yes", "no")) is None
    assert read_answer("Sorry, no idea", "yesno", ("yes", "no")) is None
    assert read_answer("closer", "choice", VIEW_DIRECTIONS) == "closer"
    assert read_answer("I cannot tell, maybe left", "choice", VIEW_DIRECTIONS) is None


def test_confidence_skips_leading_markup_and_needs_evidence():
    tokens = [TokenChoice('"', -0.01, (('"', -0.01),)),
              TokenChoice("yes", math.log(0.8), (("yes", math.log(0.8)), ("no", math.log(0.1))))]
    assert option_confidence(tokens, ("yes", "no"), "yes") == pytest.approx(0.8 / 0.9)
    assert option_confidence(tokens, ("yes", "no"), None) is None
    assert option_confidence([TokenChoice("The", -0.1, (("The", -0.1),))], ("yes", "no"), "yes") is None
    assert option_confidence([], ("yes", "no"), "yes") is None


def test_make_backend_builds_from_names_and_environment(serve):
    server = serve(generate("yes"))
    vlm = make_backend("gemini", f"{server.url}/v1beta", timeout_s=0.5, env={"GEMINI_API_KEY": "env-key"})
    with vlm:
        assert isinstance(vlm, GeminiVLM) and vlm.ask(YESNO, FRAME).value is True
        d = vlm.describe()
    assert server.seen[0].headers["x-goog-api-key"] == "env-key"
    assert d["model"] == "gemini-2.5-flash" and d["timeout_s"] == 0.5 and d["deadline_s"] == 1.5
    assert "env-key" not in json.dumps(d)
    with make_backend("openai", model="llava", env={"OPENAI_BASE_URL": "http://127.0.0.1:1/v1"}) as o:
        assert o.describe()["url"] == "http://127.0.0.1:1/v1" and o.describe()["api_key"] == "unset"


def test_unreachable_says_why_no_server_answers_and_nothing_when_one_does(serve):
    import socket

    server = serve(chat("yes"))
    with make_backend("openai", f"{server.url}/v1", "m", env={}) as up:
        assert up.unreachable() is None  # a GET of the API root is a 501 here: an answer all the same
    assert server.seen == []  # the probe asked nothing of the model
    with make_backend("openai", "http://127.0.0.1:9/v1", "m", env={}) as down:  # nothing listens on 9 here
        assert down.unreachable(timeout_s=2.0).startswith("nothing accepts a connection there")
    with socket.socket() as mute:  # accepts connections, never answers
        mute.bind(("127.0.0.1", 0))
        mute.listen(1)
        with make_backend("gemini", f"http://127.0.0.1:{mute.getsockname()[1]}/v1beta", env={}) as silent:
            assert silent.unreachable(timeout_s=0.5) == "no answer within 0.5 s"


@pytest.mark.parametrize("args,where", [
    (("llama",), "--vlm"),
    (("openai", "http://127.0.0.1:8000/v1"), "--vlm-model"),
    (("openai", "127.0.0.1:8000", "m"), "--vlm-url"),
    (("gemini",), "GEMINI_API_KEY"),
])
def test_make_backend_rejects_bad_input_with_one_clear_error(args, where):
    with pytest.raises(InputError) as err:
        make_backend(*args, env={})
    assert err.value.where == where and err.value.exit_code == EXIT_BAD_INPUT
