"""The simulated VLM (model vlm-2): structural errors, relation observability, calibration.

Every test builds capture records by hand — what a frame shows of each object — and asks the
world-side model about them, as the executive's questions would. Bounds are a few standard errors
wide, so each test can fail if the model stops behaving as docs/perception.md documents.
"""

from __future__ import annotations

import math

import pytest
from scipy.stats import multivariate_normal, norm

from vap_bt.domain.atoms import Atom
from vap_bt.perception.protocol import Protocol
from vap_bt.perception.verification import viewpoint_query
from vap_bt.perception.vlm import Query
from vap_bt.robot.frame import Frame
from vap_bt.sim.captures import CaptureRecord, ObjectView
from vap_bt.sim.oracle import FunctionOracle
from vap_bt.sim.sim_vlm import SimVLM, VlmModel

ON = Atom("on", ("cup", "table"))
INSIDE = Atom("inside", ("cup", "cabinet"))


def records(n: int, truth=lambda a: True, visibility=None, masks=None, views=None, labels=None,
            picture=lambda i: f"pic-{i}", fingers=None) -> dict[str, CaptureRecord]:
    """``n`` capture records f-0 ... f-(n-1), each a different picture unless ``picture`` says otherwise."""
    oracle = FunctionOracle(truth, lambda: [])
    return {f"f-{i}": CaptureRecord(f"f-{i}", 0, dict(visibility or {}), oracle, lambda: 0, masks=dict(masks or {}),
                                    views=dict(views or {}), labels=dict(labels or {}), fingers=fingers,
                                    picture=picture(i))
            for i in range(n)}


def ask(vlm: SimVLM, i: int, atom: Atom = ON, prompt: str = "Is the cup on the table?", purpose: str = "predicate"):
    return vlm.ask(Query(prompt, purpose=purpose, about=(atom,), objects=atom.args), Frame(f"f-{i}", 0.0))


PLAIN = dict(visibility={"cup": 1.0, "table": 1.0}, views={"cup": ObjectView(contact=1.0), "table": ObjectView(top=1.0)})


def test_the_same_picture_and_question_get_the_same_answer_and_a_new_view_draws_anew():
    """Two captures of one unchanged view are one picture: every question gets the answer it got
    before, in any order; different pictures get independent answers."""
    same = SimVLM(records(200, picture=lambda i: "one-picture", **PLAIN).get, seed=4).ask
    prompts = [f"Is the cup on the table? ({k})" for k in range(5)]
    first = [same(Query(p, about=(ON,), objects=ON.args), Frame("f-0", 0.0)).value for p in prompts]
    for i in range(1, 200):
        assert [same(Query(p, about=(ON,), objects=ON.args), Frame(f"f-{i}", 0.0)).value for p in reversed(prompts)] \
            == first[::-1]
    vlm = SimVLM(records(400, **{**PLAIN, "views": {"cup": ObjectView(contact=0.3)}}).get, seed=4)
    fresh = [ask(vlm, i).value for i in range(400)]
    assert 0 < sum(fresh) < len(fresh)  # new pictures: answers vary


def test_accuracy_at_full_observability_is_the_calibrated_one():
    m = VlmModel()
    n = 3000
    vlm = SimVLM(records(n, **PLAIN).get, seed=7)
    right = sum(ask(vlm, i).value is True for i in range(n))
    se = math.sqrt(m.accuracy["on"] * (1 - m.accuracy["on"]) / n)
    assert abs(right / n - m.accuracy["on"]) < 4 * se


def test_paraphrases_of_one_atom_in_one_view_are_correlated_as_documented():
    """Five paraphrases about one picture share the latent parts of their relation and atom
    (correlation 0.5): the correlation of two paraphrases' correctness is what the bivariate
    normal model gives, far above 0, and a majority of five is much less accurate than five
    independent answers would be."""
    m = VlmModel()
    n = 3000
    vlm = SimVLM(records(n, **{**PLAIN, "views": {"cup": ObjectView(contact=0.6)}}).get, seed=11)
    prompts = [f"Is the cup on the table? ({k})" for k in range(5)]
    right = [[ask(vlm, i, prompt=p).value is True for p in prompts] for i in range(n)]
    p = sum(map(sum, right)) / (5 * n)
    both = sum(r[0] and r[1] for r in right) / n
    phi = (both - p * p) / (p * (1 - p))
    # the model: correct iff mu + bias + e > 0, e ~ N(0, 1), two paraphrases' e correlated rho
    mu = 0.6 * norm.ppf(m.accuracy["on"]) + m.yes_bias * 0.4
    rho = m.paraphrase_correlation
    p_model = norm.cdf(mu)
    both_model = multivariate_normal([0, 0], [[1, rho], [rho, 1]]).cdf([mu, mu])
    phi_model = (both_model - p_model ** 2) / (p_model * (1 - p_model))
    assert abs(p - p_model) < 0.02
    assert abs(phi - phi_model) < 0.06 and phi > 0.2
    majority = sum(sum(r) >= 3 for r in right) / n
    independent = sum(math.comb(5, k) * p ** k * (1 - p) ** (5 - k) for k in range(3, 6))
    assert majority < independent - 0.05


def test_a_closed_containers_interior_is_never_confidently_reported():
    """The cup in the shut cabinet: the picture shows nothing of the inside. Answers are an
    abstention or a guess leaning to "yes", never stated with the confidence the lean protocol
    takes for a vote."""
    n = 1000
    vlm = SimVLM(records(n, visibility={"cabinet": 1.0}, views={"cabinet": ObjectView(interior=0.0, leaf=1.0)}).get, seed=2)
    answers = [ask(vlm, i, INSIDE, "Is the cup inside the cabinet?") for i in range(n)]
    said = [a for a in answers if a.value is not None]
    assert all(a.confidence < Protocol.parse("lean").confident for a in said)
    assert max(a.confidence for a in said) <= 0.5 + VlmModel().confidence_floor / 2 + 1e-9
    abstained = 1 - len(said) / n
    assert abs(abstained - VlmModel().abstain_rate) < 0.05
    yes = sum(a.value for a in said) / len(said)
    assert 0.5 < yes < 0.72  # a guess leaning to yes: Phi(0.25) = 0.6


def test_an_item_hidden_on_its_support_looks_absent_and_the_view_is_taken_for_enough():
    """The cup is on the table but hidden behind something: the table's top is in view, no cup.
    A model reading the picture says "no" — a systematic error no paraphrase cures — and, being
    overconfident, mostly calls the view sufficient."""
    n = 1000
    vlm = SimVLM(records(n, visibility={"table": 1.0}, views={"table": ObjectView(top=0.9)}).get, seed=5)
    said = [ask(vlm, i).value for i in range(n)]
    assert sum(said) / n < 0.2
    sufficient = [ask(vlm, i, purpose="sufficiency").value for i in range(n)]
    assert sum(sufficient) / n > 0.8


def test_view_sufficiency_is_overconfident():
    m = VlmModel()
    n = 2000
    for o, lo, hi in ((0.9, 0.85, 1.0), (0.3, 0.4, 0.6), (0.0, 0.1, 0.35)):
        vlm = SimVLM(records(n, **{**PLAIN, "views": {"cup": ObjectView(contact=o)}}).get, seed=9)
        yes = sum(ask(vlm, i, purpose="sufficiency").value for i in range(n)) / n
        expected = norm.cdf(m.sufficiency_slope * (o - m.sufficiency_threshold) + m.overconfidence)
        assert lo < yes < hi and abs(yes - expected) < 0.04, (o, yes, expected)


def test_stated_probabilities_say_something_about_being_right_but_overstate_it():
    n = 3000
    vlm = SimVLM(records(n, **{**PLAIN, "views": {"cup": ObjectView(contact=0.7)}}).get, seed=13)
    answers = [ask(vlm, i) for i in range(n)]
    right = [a.confidence for a in answers if a.value is True]
    wrong = [a.confidence for a in answers if a.value is False]
    accuracy = len(right) / n
    assert sum(right) / len(right) > sum(wrong) / len(wrong) + 0.05
    assert sum(a.confidence for a in answers) / n > accuracy + 0.02  # overconfident


def test_smaller_in_the_image_is_harder():
    n = 2000
    acc = []
    for share in (0.0008, 0.004, 0.04):
        vlm = SimVLM(records(n, visibility={"cup": 1.0, "table": 1.0}, masks={"cup": ((), share), "table": ((), 0.2)},
                             views={"cup": ObjectView(pixels=int(share * 76800) + 13, contact=1.0)}).get, seed=3)
        acc.append(sum(ask(vlm, i).value is True for i in range(n)) / n)
    assert acc[0] < acc[1] - 0.05 < acc[2] - 0.1


def test_noise_off_is_an_ideal_reader_of_the_picture():
    vlm = SimVLM(records(50, **{**PLAIN, "views": {"cup": ObjectView(contact=0.2)}}).get, noise=0.0, seed=1)
    assert all(ask(vlm, i).value is True for i in range(50))
    assert not any(ask(vlm, i, purpose="sufficiency").value for i in range(50))  # 0.2 < threshold
    hidden = SimVLM(records(50, visibility={"table": 1.0}, views={"table": ObjectView(top=1.0)}).get, noise=0.0, seed=1)
    assert not any(ask(hidden, i).value for i in range(50))  # what the picture shows: no cup


def test_a_model_reads_an_instance_name_as_its_class():
    """bottle1 is out of the picture, bottle2 stands on the counter in it: asked about "bottle1",
    a model answers about the bottle it sees."""
    truth = {Atom("on", ("bottle1", "counter")): False, Atom("on", ("bottle2", "counter")): True}
    recs = records(200, truth=lambda a: truth.get(a, False), visibility={"bottle2": 1.0, "counter": 1.0},
                   views={"bottle2": ObjectView(contact=1.0), "counter": ObjectView(top=1.0)},
                   labels={"bottle1": "bottle", "bottle2": "bottle", "counter": "counter"})
    vlm = SimVLM(recs.get, noise=0.0, seed=1)
    atom = Atom("on", ("bottle1", "counter"))
    assert all(ask(vlm, i, atom, "Is bottle1 on the counter?").value for i in range(20))


def test_does_not_answer_about_a_frame_it_has_no_record_of():
    vlm = SimVLM(records(1, **PLAIN).get, seed=1)
    assert vlm.ask(Query("q", about=(ON,), objects=ON.args), Frame("from-elsewhere", 0.0)).value is None


def test_sees_a_large_thing_the_frame_cuts_as_plainly_as_a_whole_one():
    """A cabinet filling a third of the image, cut by three edges (a fifth of it in the frame),
    is plainly in the picture; the same fifth covering 2 % of the image is not."""
    def sufficient(share: float) -> float:
        vlm = SimVLM(records(400, visibility={"cabinet": 0.2}, masks={"cabinet": (("bottom", "left", "right"), share)},
                             views={"cabinet": ObjectView(pixels=int(share * 76800))}).get, seed=3)
        return sum(ask(vlm, i, Atom("filled", ("cabinet",)), "Is the cabinet full?", "sufficiency").value
                   for i in range(400)) / 400

    assert sufficient(0.33) > 0.85
    assert sufficient(0.02) < 0.5


def viewpoint(vlm: SimVLM, i: int) -> str:
    return vlm.ask(viewpoint_query(ON, "Is the cup on the table?", "cup"), Frame(f"f-{i}", 0.0)).value


@pytest.mark.parametrize("want,vis,masks,views", [
    ("right", {"cup": 0.7}, {"cup": (("right",), 0.05)}, {}),
    ("closer", {"cup": 0.9}, {"cup": ((), 0.002)}, {}),
    ("above", {"cup": 0.3}, {"cup": ((), 0.05)}, {}),
    ("closer", {"cup": 1.0}, {"cup": ((), 0.05)}, {}),
    ("front", {"cup": 0.6}, {"cup": (("top",), 0.3)}, {}),
    ("above", {"cup": 1.0}, {"cup": ((), 0.05)}, {"cup": ObjectView(contact=0.1)}),  # the contact hidden
    ("above", {"table": 0.9}, {"table": ((), 0.2)}, {}),  # the cup out of the picture: over its place
    ("left", {"table": 0.6}, {"table": (("left",), 0.2)}, {}),
])
def test_reads_where_to_look_off_the_picture(want, vis, masks, views):
    vlm = SimVLM(records(40, visibility=vis, masks=masks, views=views).get, noise=0.0, seed=5)
    assert {viewpoint(vlm, i) for i in range(40)} == {want}


def test_a_viewpoint_read_off_nothing_is_a_guess_and_readings_are_sometimes_wrong():
    vlm = SimVLM(records(300).get, noise=0.0, seed=5)
    assert len({viewpoint(vlm, i) for i in range(300)}) == 6
    vlm = SimVLM(records(600, visibility={"table": 0.9}, masks={"table": ((), 0.2)}).get, seed=5)
    got = [viewpoint(vlm, i) for i in range(600)]
    misread = 1 - norm.cdf(0.9 * norm.ppf(VlmModel().viewpoint_accuracy))
    expected = 1 - misread + misread / 6
    assert abs(got.count("above") / len(got) - expected) < 0.06 and len(set(got)) == 6


def test_judges_the_instance_the_executive_marked():
    """Two bottles the detector labels alike: the executive took detection 0 (the world's bottle2)
    for bottle1. Asked whether bottle1 is on the counter about that frame, the model judges the
    bottle so marked (a set-of-marks prompt), and the runner scores the answer against it; a
    false positive taken for bottle1 is no bottle the picture shows: the view is not enough."""
    from types import SimpleNamespace

    from vap_bt.perception.verification import Round
    from vap_bt.robot.frame import marked_frame
    from vap_bt.app.runner import Session

    truth = {Atom("on", ("bottle2", "counter")): True, Atom("on", ("bottle1", "counter")): False}
    oracle = FunctionOracle(lambda a: truth.get(a, False), lambda: [])
    vis = {"bottle1": 1.0, "bottle2": 1.0, "counter": 1.0}
    recs = {"f": CaptureRecord("f", 0, vis, oracle, lambda: 0, instances=("bottle2", "bottle1", "counter"), marked=True),
            "g": CaptureRecord("g", 0, vis, oracle, lambda: 0, instances=("", "counter"), marked=True),
            "s": CaptureRecord("s", 0, vis, oracle, lambda: 0, instances=("bottle2",))}  # a world acting by name
    vlm = SimVLM(recs.get, noise=0.0, seed=1)
    on = Atom("on", ("bottle1", "counter"))
    q = Query("Is bottle1 on the counter?", about=(on,), objects=("bottle1", "counter"))
    assert vlm.ask(q, marked_frame("f", {"bottle1": 0, "counter": 2})).value is True  # the bottle it looked at
    assert vlm.ask(q, Frame("f", 0.0)).value is False  # nothing marked: the name's own
    suff = Query("Is the view sufficient?", purpose="sufficiency", about=(on,), objects=("bottle1", "counter"))
    assert vlm.ask(suff, marked_frame("g", {"bottle1": 0, "counter": 1})).value is False
    assert vlm.ask(suff, marked_frame("f", {"bottle1": 0, "counter": 2})).value is True
    assert vlm.ask(q, marked_frame("s", {"bottle1": 0})).value is False  # marks mean nothing there
    assert recs["f"].resolve_atom(on, {"bottle1": 0}) == Atom("on", ("bottle2", "counter"))
    assert recs["g"].resolve_atom(on, {"bottle1": 0}) is None
    # the runner scores a verdict, and records the truth, against what the robot looked at
    world = SimpleNamespace(captures=SimpleNamespace(get=recs.get), oracle=oracle)
    for view, value, right in (("f", True, True), ("f", False, False), ("g", False, True)):
        runner = SimpleNamespace(world=world, _truths={})
        runner._true_now = lambda atom, records: Session._true_now(runner, atom, records)
        v = SimpleNamespace(outcome="confirmed", atom=on, atoms=(on,), value=value,
                            rounds=[Round(view, identified={"bottle1": 0})])
        Session._score_verification(runner, v)
        assert (runner._truths[id(v)]["truth"] == value) == right, (view, value)
        assert runner._truths[id(v)]["truth"] == (view == "f") == runner._truths[id(v)]["first_truth"]


def test_a_truth_read_after_the_world_moved_on_is_counted_late_even_once_its_record_is_forgotten():
    """A question about a frame whose world has stepped since reads the truth now: the log counts
    it, and keeps the count when the record is evicted (the report's world.late_truth_readings);
    a reset clears it."""
    from vap_bt.sim.captures import CaptureLog

    now = [0]
    oracle = FunctionOracle(lambda a: True, lambda: [])
    log = CaptureLog(size=1)
    first = CaptureRecord("f-0", 0, {}, oracle, lambda: now[0])
    log.add(first)
    first.holds(ON)  # asked at once: read at capture, not late
    now[0] = 5
    first.holds(INSIDE)  # asked after the world stepped: late
    first.holds(INSIDE)  # remembered: no second reading
    assert log.late == 1
    log.add(CaptureRecord("f-1", 5, {}, oracle, lambda: now[0]))  # f-0 is forgotten
    assert log.get("f-0") is None and log.late == 1
    log.clear()
    assert log.late == 0
