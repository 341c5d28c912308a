"""A new motion skill from a plugin distribution, run in pybullet with no change to the simulator.

``examples/wipe-skill`` is a distribution of its own (pyproject + one module) declaring ``wipe``
under the entry-point group ``vap_bt.skills``. The test installs it with pip into a folder (the
shared virtualenv untouched), finds it through plugin discovery, binds it to a pybullet world
like every installed skill and sends it a goal. The arm's driver measures the hand passing just
above the counter's top, along it; all the world heard of it is that a ``wipe`` goal began and
ended — no result, no outcome, nothing it could know a wipe by.
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from driver_scripts import kitchen, world_of

from conftest import ROOT
from vap_bt import plugins
from vap_bt.skill import GoalState
from vap_bt.app.inprocess import InProcessSkillClient

pytestmark = [pytest.mark.slow, pytest.mark.timeout(240)]

EXAMPLE = ROOT / "examples" / "wipe-skill"


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    target = tmp_path_factory.mktemp("wipe") / "site"
    subprocess.run([sys.executable, "-m", "pip", "install", "-q", "--no-deps", "--target", str(target), str(EXAMPLE)],
                   check=True, capture_output=True, timeout=170)
    return target


def test_the_installed_wipe_plugin_moves_the_arm_over_the_surface(installed, monkeypatch, tmp_path):
    monkeypatch.syspath_prepend(str(installed))
    entries = plugins.discover_skills()
    wipe = next(e for e in entries if e.action == "wipe")
    assert (wipe.distribution, wipe.version, wipe.robot, wipe.resource) == ("vap-bt-wipe", "0.1.0", "ur5e", "arm")
    assert str(installed) in sys.modules[wipe.cls.__module__].__file__  # the installed copy, not the source

    w = world_of(tmp_path, "wipe", kitchen({"counter": "type: surface"}))
    heard = []
    monkeypatch.setattr(w, "begin_action", lambda *a: heard.append(("begin", *a)))
    monkeypatch.setattr(w, "end_action", lambda *a: heard.append(("end", *a)))
    tcp = []
    follow = w.drivers.arm.follow

    def measured(trajectory, cancelled):  # the driver's own tcp after every arm motion
        result = follow(trajectory, cancelled)
        tcp.append(w.drivers.arm.tcp_pose()[:3, 3].copy())
        return result

    monkeypatch.setattr(w.drivers.arm, "follow", measured)
    try:
        skills = plugins.instantiate(w, entries=entries)
        assert type(skills["wipe"]) is wipe.cls
        goal = InProcessSkillClient(skills).send_goal("wipe", ("counter",))
        assert goal.state() is GoalState.SUCCEEDED, goal.result().message

        f = w.plan.furniture["counter"]
        along = np.array([f.front[1], -f.front[0]])
        top = f.kind.size[2]
        over = [p for p in tcp if abs((p[:2] - (f.x, f.y)) @ f.front[:2]) < f.kind.size[1] / 2
                and abs((p[:2] - (f.x, f.y)) @ along) < f.kind.size[0] / 2 and top < p[2] < top + 0.08]
        assert len(over) >= 4, tcp  # down, the strokes there and back
        reach = [float((p[:2] - (f.x, f.y)) @ along) for p in over]
        assert max(reach) - min(reach) > 0.2  # swept along the top, not one spot
        assert np.allclose(w.drivers.arm.joint_state().positions, w.robot.cfg.arm.home, atol=0.05)  # folded after

        assert heard == [("begin", "wipe", ("counter",)), ("end", "wipe", ("counter",))]
        assert not hasattr(w, "perform") and w.injected() == []
    finally:
        w.close()
