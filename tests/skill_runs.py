"""Running the installed skills on a pybullet world open-loop, the way the executive sends them.

A test names a sequence of plan actions; each becomes one goal on the in-process skill client
over :func:`vap_bt.plugins.instantiate` — the same skills, kit and drivers a run uses — with the
hints a correct belief would send (:func:`believed`). Views go through the skills' camera
service (:class:`skills.views.ViewService`), which aims the wrist camera; the world only renders.

The hints and the aims are the one place these helpers read the world's truth: they stand in for
a scene graph that matches the world, so that a test exercises the motion, not perception. For
the same reason a world here has exact sensors unless a test asks for the real ones
(``sensors="real"``: the D435i-like depth and the AMCL-like localiser every run has): a test of
a motion on exact sensors guards the motion; the same test on real sensors shows whether the
skill copes with what a real robot measures.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from skills.kit import kit_for
from skills.views import ViewService
from vap_bt import plugins
from vap_bt.domain.atoms import Atom
from vap_bt.sim.situations import SituationModel
from vap_bt.skill import GoalState, Hint
from vap_bt.app.inprocess import InProcessSkillClient

TREES = Path(__file__).resolve().parents[1] / "trees"


def pybullet(name, situations=None, sensors: str = "exact", seed: int = 0, **kw):
    """The pybullet world of ``trees/<name>.yaml`` (or of a task file path) laid out by ``seed``,
    small images unless ``image_size`` says otherwise; with exact depth and localisation, or (``sensors="real"``) the world's default
    sensor models."""
    from vap_bt.sim.depth_noise import DepthNoiseModel
    from vap_bt.sim.localization import LocalizationModel
    from vap_bt.sim.pybullet_world import PybulletWorld
    from vap_bt.taskfile import load

    if sensors not in ("exact", "real"):
        raise ValueError(f"sensors: 'exact' or 'real', not {sensors!r}")
    if sensors == "exact":
        kw.setdefault("depth_noise", DepthNoiseModel.exact())
        kw.setdefault("localization", LocalizationModel.perfect())

    task = load(name if isinstance(name, Path) else TREES / f"{name}.yaml")
    kw.setdefault("image_size", (160, 120))
    return PybulletWorld(task, seed=seed, injection=situations is not None, situations=situations, **kw)


def believed(world, names: tuple[str, ...]) -> tuple[Hint, ...]:
    """The goal's hints from a belief that matches the world: where each thing is (nothing for
    what the hand holds) and, for an item, what it rests on or in."""
    out = []
    for n in names:
        t = world.scene.things.get(n)
        if t is None:
            out.append(Hint(n))
            continue
        point = world.aim_at((n,)).point
        on = inside = None
        if t.item is not None and world.truth.held() != n:
            inside = world.truth.container_of(n)
            on = None if inside else world.truth.support_of(n)
        out.append(Hint(n, point, on, inside))
    return tuple(out)


def parse(call: str) -> tuple[str, tuple[str, ...]]:
    name, args = call.split("(")
    return name, tuple(x.strip() for x in args.rstrip(")").split(",") if x.strip())


def act(world, call: str):
    """Send one action (``"grasp(cup, counter, kitchen)"``) as a goal; its finished handle."""
    name, args = parse(call)
    client = InProcessSkillClient(plugins.instantiate(world))
    return client.send_goal(name, args, believed(world, args))


def run(world, *calls: str) -> None:
    """Send each action in turn; every one must succeed (the skill's own view of its motion)."""
    for call in calls:
        goal = act(world, call)
        assert goal.state() is GoalState.SUCCEEDED, f"{call}: {goal.state().value} {goal.result().message}"


def camera(world) -> ViewService:
    """The camera service the executive would be handed for ``world``."""
    return ViewService(kit_for(world))


def seen(world, names: tuple[str, ...]) -> dict[str, float]:
    """Aim the camera at where ``names`` are, take a frame, and say how much of each it shows
    (the simulated VLM's record of the frame)."""
    frame = camera(world).capture(world.aim_at(names))
    vis = world.captures.get(frame.frame_id).visibility
    return {n: vis.get(n, 0.0) for n in names}


def move_view(world, names: tuple[str, ...], direction: str) -> bool:
    """Move the view ``direction`` relative to where ``names`` are."""
    return camera(world).move_view(world.aim_at(names), direction)


# ------------------------------------------------------------ what the skill tests share


def A(text):
    return Atom.parse(text)


def holds(w, *atoms):
    return all(w.oracle.holds(A(a)) for a in atoms)


def truths(w, *atoms) -> str:
    """What the world's truth says of each atom, for an assertion's message: ``sliced(egg)=False ...``."""
    return " ".join(f"{a}={holds(w, a)}" for a in atoms)


def settle(w, seconds: float = 1.0) -> None:
    """Let the physics run on (the robot holding still): an item that slipped from the hand as
    the goal ended is still falling, and the oracle's ``on`` is support by contact."""
    for _ in range(int(seconds / w.dt)):
        w.step()


forced = SituationModel.forced


class Marks(tuple):
    """Marks that go on a test together: as a decorator, or as ``pytest.param(marks=...)``."""

    def __call__(self, test):
        for mark in self:
            test = mark(test)
        return test


def skills_fail(reason: str, says: str) -> Marks:
    """A behaviour the skills do not reach yet: strict, so the marker goes once a skill does, and
    the test must fail saying ``says`` (its failure's message holds it: tests/conftest.py), so a
    marker cannot go on standing for a failure that changed under it (stop 48: three of eight
    named a failure the test no longer met — a cabinet's close refused at a wrist limit had
    become a handle out of reach)."""
    return Marks((pytest.mark.xfail(strict=True, reason=f"skills: {reason}"), pytest.mark.fails_saying(says)))


def on_both_sensors(real_fails: tuple[str, str] | None = None, exact_fails: tuple[str, str] | None = None):
    """Run a test on exact sensors (the motion) and on the real ones (D435i-like depth, AMCL-like
    localiser: whether the skill copes with what a robot measures); ``real_fails`` and
    ``exact_fails`` name what the skill does not yet reach on each, as ``(reason, says)`` of
    :func:`skills_fail` (strict: the marker goes once it does).

    Every marker is strict: numpy's kernels are pinned (:mod:`vap_bt.numerics`), so the same code
    and packages give the same motion on every x86-64 machine. The markers that let either
    outcome pass while the kernels followed the CPU (up to stop 46) hid that what failed had
    changed under them: a "strike taking the knife out" had become a cut that misses the egg."""
    real = pytest.param("real", marks=skills_fail(f"on real sensors, {real_fails[0]}", real_fails[1])) if real_fails else "real"
    exact = pytest.param("exact", marks=skills_fail(f"on exact sensors, {exact_fails[0]}", exact_fails[1])) if exact_fails else "exact"
    return pytest.mark.parametrize("sensors", [exact, real])


def lay(w, name, at, z, rpy):
    """Test setup: put ``name`` down at ``at`` (x, y; its centre ``z`` high) lying as ``rpy`` says, and let it settle
    (a dropped item, where a situation left one in an earlier run)."""
    import pybullet as pb

    body = w.scene.things[name].body
    pb.resetBasePositionAndOrientation(body, (*at, z), pb.getQuaternionFromEuler(rpy), physicsClientId=w.cid)
    pb.resetBaseVelocity(body, (0, 0, 0), (0, 0, 0), physicsClientId=w.cid)
    for _ in range(60):
        w.step()
    assert abs(w.truth.center(name)[0] - at[0]) < 0.03 and abs(w.truth.center(name)[1] - at[1]) < 0.03  # it stays
