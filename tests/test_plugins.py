"""Skill plugins: discovery through entry points, the rules for broken and clashing plugins,
and the in-process client that runs skills synchronously.

Broken and clashing plugins are real distributions: a ``.dist-info`` folder with an
``entry_points.txt`` on ``sys.path``, which is what ``importlib.metadata`` reads for installed
packages too.
"""

from __future__ import annotations

import logging
import textwrap

import pytest

from plugin_fixtures.fact_world import FactWorld
from skills.base import MotionSkill
from vap_bt import plugins
from vap_bt.domain.atoms import Atom
from vap_bt.skill import GoalState, Skill, SkillResult, WorldActionSkill
from vap_bt.robot.camera import Aim
from vap_bt.app.inprocess import InProcessRobot, InProcessSkillClient

BUILTIN = {"navigate": "base", "find": "base", "grasp": "ur5e", "takeout": "ur5e", "placein": "ur5e",
           "placeon": "ur5e", "open": "ur5e", "close": "ur5e", "turnon": "ur5e", "cut": "ur5e",
           "fill": "ur5e", "push": "ur5e"}


def fake_distribution(root, name: str, entry_points: dict[str, str], modules: dict[str, str]):
    """An installed-looking distribution under ``root`` (put ``root`` on sys.path)."""
    info = root / f"{name.replace('-', '_')}-0.1.dist-info"
    info.mkdir(parents=True)
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {name}\nVersion: 0.1\n")
    lines = "\n".join(f"{k} = {v}" for k, v in entry_points.items())
    (info / "entry_points.txt").write_text(f"[vap_bt.skills]\n{lines}\n")
    for module, source in modules.items():
        (root / f"{module}.py").write_text(textwrap.dedent(source))


def test_builtin_skills_are_found_through_the_entry_point_group():
    entries = plugins.discover_skills()
    assert {e.action: e.robot for e in entries if e.distribution == "vap-bt"} == BUILTIN
    grasp = next(e for e in entries if e.action == "grasp")
    assert (grasp.name, grasp.resource, grasp.module) == ("grasp", "arm", "skills.manipulation:Grasp")
    assert issubclass(grasp.cls, MotionSkill) and grasp.version == "0.1.0"
    assert plugins.routes(entries) == BUILTIN


def test_instantiate_binds_skills_to_the_world_per_robot():
    world = FactWorld()
    base = plugins.instantiate(world, robot="base")
    assert set(base) == {"navigate", "find"} and base["find"].world is world
    assert set(plugins.instantiate(world)) == set(BUILTIN)
    # a world without drivers cannot be moved by motion skills: it performs their actions itself,
    # under the plugins' robots and resources
    assert not MotionSkill.binds(world)
    find = base["find"]
    assert isinstance(find, WorldActionSkill) and (find.robot, find.resource) == ("base", "base")


def test_broken_plugins_are_one_warning_each_and_skipped(tmp_path, monkeypatch, caplog):
    fake_distribution(tmp_path, "broken-skills", {
        "missing": "no_such_module_xyz:Thing",
        "raises": "vapbt_raises:Thing",
        "notaskill": "vapbt_plain:Thing",
        "abstract": "vapbt_plain:Abstract",
    }, {
        "vapbt_raises": "raise ImportError('needs a GPU driver')\n",
        "vapbt_plain": """
            from vap_bt.skill import Skill
            class Thing:
                pass
            class Abstract(Skill):
                action = "abstract"
        """,
    })
    monkeypatch.syspath_prepend(str(tmp_path))
    with caplog.at_level(logging.WARNING, logger="vap_bt.plugins"):
        entries = plugins.discover_skills()
    assert {e.action for e in entries} == set(BUILTIN)
    messages = sorted(r.getMessage() for r in caplog.records)
    assert len(messages) == 4 and not any(r.exc_info for r in caplog.records)
    assert messages[0].startswith("skill plugin 'abstract' (vapbt_plain:Abstract, from broken-skills) "
                                  "skipped: Abstract is abstract")
    assert "skill plugin 'missing'" in messages[1] and "No module named 'no_such_module_xyz'" in messages[1]
    assert "is not a subclass of vap_bt.skill.Skill" in messages[2]
    assert "ImportError: needs a GPU driver" in messages[3]


def test_two_plugins_for_one_action_is_an_error_naming_both(tmp_path, monkeypatch, cli):
    fake_distribution(tmp_path, "better-grasp", {"grasp2": "vapbt_grasp2:Grasp2"}, {
        "vapbt_grasp2": """
            from vap_bt.skill import WorldActionSkill
            class Grasp2(WorldActionSkill):
                action = "grasp"
        """,
    })
    monkeypatch.syspath_prepend(str(tmp_path))
    entries = plugins.discover_skills()
    with pytest.raises(plugins.SkillConflictError) as err:
        plugins.instantiate(FactWorld(), entries=entries)
    assert str(err.value) == (
        "two skill plugins bind action 'grasp': grasp = skills.manipulation:Grasp (vap-bt 0.1.0) and "
        "grasp2 = vapbt_grasp2:Grasp2 (better-grasp 0.1); uninstall one or exclude one by entry-point name"
    )
    assert plugins.skill_table(entries, exclude=["grasp"])["grasp"].name == "grasp2"
    code, out, errtext = cli("skills")
    assert code == 2 and "grasp2" in out and "two skill plugins bind action 'grasp'" in errtext


def test_skills_command_lists_every_plugin(cli):
    code, out, err = cli("skills")
    assert code == 0, err
    header, *rows = out.strip().splitlines()
    assert header.split() == ["ACTION", "ROBOT", "RESOURCE", "ENTRY_POINT", "CLASS", "DISTRIBUTION"]
    assert sorted(r.split()[0] for r in rows) == sorted(BUILTIN)
    assert any(r.split()[:4] == ["navigate", "base", "base", "navigate"] for r in rows)


class Echo(Skill):
    action = "echo"

    def execute(self, args, ctx):
        ctx.feedback(0.5, "half")
        return SkillResult(not ctx.cancelled(), " ".join(args), {"n": len(args)})


def test_inprocess_client_finishes_goals_inside_send_goal():
    world = FactWorld()
    skills = {**plugins.instantiate(world), "echo": Echo(world)}
    client = InProcessSkillClient(skills)
    grasp = client.send_goal("grasp", ("cup", "table"))
    assert grasp.state() is GoalState.SUCCEEDED and world.oracle.holds(Atom("holding", ("cup",)))
    assert grasp.feedback().progress == 1.0
    again = client.send_goal("grasp", ("cup", "table"))
    assert again.state() is GoalState.ABORTED and "preconditions" in again.result().message
    echo = client.send_goal("echo", ("a", "b"))
    assert (echo.result().message, echo.result().data, echo.feedback().text) == ("a b", {"n": 2}, "half")
    unknown = client.send_goal("fly", ())
    assert unknown.state() is GoalState.REJECTED
    assert unknown.result().message.startswith("no skill for action 'fly' here (serving: close, cut, echo")
    assert len({grasp.goal_id, again.goal_id, echo.goal_id, unknown.goal_id}) == 4
    client.close()


def test_inprocess_robot_forwards_the_robot_interfaces_and_nothing_else():
    world = FactWorld()
    robot = InProcessRobot(world)
    frame = robot.capture(Aim(("cup",)))
    assert [(x.label, x.name) for x in frame.detections] == [("cup", "")] and frame.aim == ("cup",) and world.view == 1
    assert robot.move_view(Aim(("cup",)), "above") and world.view == 2
    assert robot.state().room == "kitchen" and robot.state().gripper_holding is False
    assert {r.name for r in robot.site_map().rooms} == {"kitchen", "hall"}
    assert not hasattr(robot, "oracle") and not hasattr(robot, "__dict__")  # no way to the truth
