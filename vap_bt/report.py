"""The episode report: everything needed to judge a run and to run it again.

``success`` is the executive's own claim; ``goal_satisfied`` is the world's truth about the goal,
read after the episode. They are reported side by side so that a claim the world denies shows.
The report also records the seed, versions, world and VLM parameters, every plan, action,
verification, situation (detected, and injected by the world) and replan.

A claim is only as good as what it rests on: ``goal_evidence`` says, per goal atom, whether the
goal's last check looked at it (a VLM verdict), felt it (proprioception), rests on an earlier
check that confirmed it and still stands (``earlier``: its goal checks could not settle it) or left
it to belief (the map, never checked), and every verification its ``basis``. Accuracy figures count the values
a sense gave at the time (:func:`verification_counts`); a value reused from an earlier check is
counted apart and never as verified.

Every situation carries the executive's ``diagnosis`` (perception error, world change or
execution failure: :mod:`vap_bt.bt.diagnosis`) and the world's ``diagnosis_truth``
(:mod:`vap_bt.sim.situation_truth`); ``diagnosis`` sums them per episode
(:func:`diagnosis_summary`) and :func:`confusion_matrix` over many reports.

A run stopped by Ctrl-C, at whatever moment, writes the same report with what was known by then
(:class:`vap_bt.app.runner.EpisodeInterrupted`): the same keys, so that a reader needs no second
schema; ``interrupted`` says it was stopped and ``phase`` what the episode was doing.
"""

from __future__ import annotations

import json
import platform
import sys
from importlib import metadata
from pathlib import Path

from vap_bt.numerics import blas_cores, numpy_simd


def versions() -> dict[str, str]:
    """The installed version of Python and of each package a run's result depends on ("not installed" for
    a missing one), and the OpenBLAS kernels and SIMD targets numpy and scipy run."""
    out = {"python": platform.python_version()}
    for dist in ("vap-bt", "py-trees", "unified-planning", "up-fast-downward", "eclipse-zenoh", "pybullet", "pin"):
        try:
            out[dist] = metadata.version(dist)
        except metadata.PackageNotFoundError:
            out[dist] = "not installed"
    # the kernels numpy's and scipy's OpenBLAS run round differently by CPU (vap_bt.numerics)
    out["openblas"] = ", ".join(f"{lib} {core}" for lib, core in blas_cores().items()) or "not loaded"
    out["numpy_simd"] = numpy_simd()
    return out


#: the bases of a value a sense gave when its check ran (vap_bt.bt.context.Basis): the verified ones
SENSED = ("vlm", "proprioception")


def verification_counts(verifications: list[dict]) -> dict:
    """The report's ``perception.verifications``, from its ``verifications`` (each with the world's
    ``truth`` when it settled): ``n`` values a sense settled — looked at (the VLM's verdict) or felt
    (the gripper) — and how many matched the world (``correct``); of them, those looked at alone
    (``looked``, ``looked_correct``); the ``unsettled`` checks (belief stood) and the ``reused``
    values (the lean protocol's: an earlier check's, nothing looked at — neither verified nor
    correct, and outside any accuracy's denominator). The runner and the benches all count here."""
    def right(vs: list[dict]) -> int:
        return sum(v["value"] == v.get("truth") for v in vs)

    sensed = [v for v in verifications if v["basis"] in SENSED]
    looked = [v for v in sensed if v["basis"] == "vlm"]
    return {"n": len(sensed), "correct": right(sensed), "looked": len(looked), "looked_correct": right(looked),
            "unsettled": sum(v["basis"] == "belief" for v in verifications),
            "reused": sum(v["basis"] == "reused" for v in verifications)}


#: a situation's diagnosis and its truth take these values (vap_bt.bt.diagnosis, vap_bt.sim.situation_truth)
DIAGNOSES = ("perception_error", "world_change", "execution_failure")


def diagnosis_summary(situations: list[dict]) -> dict:
    """The report's ``diagnosis``: of its ``situations`` (each with ``diagnosis`` and
    ``diagnosis_truth``), how many were diagnosed as the world's record says (``correct``), out of
    ``total``, and the ``confusion`` matrix, shaped as :func:`confusion_matrix`'s."""
    confusion = {t: {d: 0 for d in DIAGNOSES} for t in DIAGNOSES}
    for s in situations:
        confusion[s["diagnosis_truth"]][s["diagnosis"]] += 1
    return {"correct": sum(confusion[d][d] for d in DIAGNOSES), "total": len(situations), "confusion": confusion}


def confusion_matrix(reports) -> dict:
    """The diagnoses of every situation of ``reports`` (episode reports, or anything with their
    ``situations``) against the truth: ``{"correct": n, "total": n, "confusion": {truth:
    {diagnosis: count}}}``, both levels keyed by all three of :data:`DIAGNOSES` (zeros included),
    so ``confusion["world_change"]["perception_error"]`` counts the world changes the executive
    took for perception errors; ``correct`` is the diagonal's sum. Reports without situations (or
    without the key: an episode that crashed) add nothing."""
    return diagnosis_summary([s for rep in reports for s in rep.get("situations") or ()])


def command_line() -> str:
    """The command that started this process, as a user would type it again (``vap-bt ...``)."""
    return " ".join(["vap-bt" if Path(sys.argv[0]).name in ("vap-bt", "cli.py") else sys.argv[0], *sys.argv[1:]])


def write(report: dict, path: str | Path) -> None:
    """Write atomically: a reader never sees half a report, and an old one is replaced whole."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(path.suffix + ".part")
    tmp.write_text(json.dumps(report, indent=2, sort_keys=False, default=str) + "\n")
    tmp.replace(path)
