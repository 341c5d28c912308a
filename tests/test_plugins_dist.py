"""A third-party skill, end to end: its own distribution, installed, discovered, run by a goal.

The test writes a tiny project (pyproject + one module) declaring an entry point in the group
``vap_bt.skills``, builds and installs it with pip into a target folder (the build backend comes
from pip's configured index, a local one here; the shared virtualenv is left untouched), and then: ``discover_skills`` finds it with its distribution
and version, ``vap-bt skills`` lists it, and a ``vap-bt serve`` process with that folder on its
path hosts it, so a goal sent over Zenoh runs the plugin's code.
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import pytest

from plugin_fixtures.zenoh_net import endpoint, free_port, server_process, session, wait_until
from vap_bt import plugins
from vap_bt.skill import GoalState
from vap_bt.transport.client import ZenohSkillClient

pytestmark = pytest.mark.timeout(180)

PYPROJECT = """
[build-system]
requires = ["setuptools>=68"]
build-backend = "setuptools.build_meta"

[project]
name = "vap-bt-wave"
version = "1.2.3"

[project.entry-points."vap_bt.skills"]
wave = "vap_bt_wave:Wave"
"""

MODULE = '''
"""A skill that waves: robot "greeter", resource "hand"."""
from vap_bt.skill import Skill, SkillResult


class Wave(Skill):
    action = "wave"
    robot = "greeter"
    resource = "hand"

    def execute(self, args, ctx):
        ctx.feedback(0.5, "waving")
        return SkillResult(True, f"waved at {args[0]}", {"times": 3})
'''


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    root = tmp_path_factory.mktemp("wave")
    project, target = root / "project", root / "site"
    project.mkdir()
    (project / "pyproject.toml").write_text(textwrap.dedent(PYPROJECT))
    (project / "vap_bt_wave.py").write_text(MODULE)
    subprocess.run(
        [sys.executable, "-m", "pip", "install", "-q", "--no-deps", "--target", str(target), str(project)],
        check=True, capture_output=True, timeout=170,
    )
    return target


@pytest.mark.slow
def test_installed_plugin_is_discovered_listed_and_runs_a_goal(installed, monkeypatch, cli):
    monkeypatch.syspath_prepend(str(installed))
    wave = next(e for e in plugins.discover_skills() if e.action == "wave")
    assert (wave.distribution, wave.version, wave.robot, wave.module) == (
        "vap-bt-wave", "1.2.3", "greeter", "vap_bt_wave:Wave")

    code, out, _ = cli("skills")
    assert code == 0
    assert ["wave", "greeter", "hand", "wave", "vap_bt_wave:Wave", "vap-bt-wave", "1.2.3"] in [
        line.split() for line in out.splitlines()]

    port = free_port()
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(installed), os.environ.get("PYTHONPATH", "")]))
    with server_process(port, robot="greeter"), session(connect=(endpoint(port),)) as s:
        client = ZenohSkillClient(s, plugins.routes(plugins.discover_skills()))
        assert client.routes["wave"] == "greeter"
        wait_until(lambda: client._alive["greeter"], 3)
        handle = client.send_goal("wave", ("visitor",))
        assert handle.wait(3) is GoalState.SUCCEEDED
        assert (handle.result().message, handle.result().data) == ("waved at visitor", {"times": 3})
        assert handle.feedback().text == "waving"
        client.close()
