"""A run's settings are declared once (:mod:`vap_bt.settings`) and reach everything from there.

Every setting a command takes is a flag of that command's parser, with the field's help text and
choices; every setting a task file may state is a field of the task file's model, with the
field's default and bounds; every setting is a field of the run's config. A setting given on the
command line wins over the task file's word, which wins over the default. A new setting is one
field: a model with one more field has the flag, the task file key and the config field.
"""

from __future__ import annotations

import argparse
import dataclasses
import subprocess
import sys
import typing
from types import SimpleNamespace
from typing import Annotated

import pytest
from pydantic import Field, ValidationError

from vap_bt import taskfile
from vap_bt.app.arguments import add_settings
from vap_bt.app.cli import build_parser, main
from vap_bt.errors import EXIT_BAD_INPUT
from vap_bt.settings import (OPTIONS, TOP_LEVEL, Commands, Hosting, Option, RunConfig, RunOutput, TaskOptions,
                             TaskSource, TreeOutput, Zenoh, settings_fields, settings_model, task_options)

from conftest import DOMAINS, ROOT, TREES

MODELS = (RunConfig, TaskSource, RunOutput, TreeOutput, Zenoh, Hosting, Commands)


def commands(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    """Every command's parser by name, ``vap-bt`` itself included."""
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return {"vap-bt": parser, **sub.choices}


def subparser(parser: argparse.ArgumentParser, command: str) -> argparse.ArgumentParser:
    return commands(parser)[command]


def action_for(parser: argparse.ArgumentParser, dest: str) -> argparse.Action | None:
    return next((a for a in parser._actions if a.dest == dest), None)


def declared(models=MODELS):
    return [(model, name, info, option) for model in models for name, info, option in settings_fields(model)
            if option is not None]


@pytest.mark.parametrize("model,name,info,option", declared(), ids=[f"{m.__name__}.{n}" for m, n, _, _ in declared()])
def test_every_setting_reaches_the_parsers_of_its_commands_with_its_help_and_choices(model, name, info, option):
    parser = build_parser()
    assert option.commands or option.in_task, f"{name}: declared for neither a command nor a task file"
    for command in option.commands:
        action = action_for(subparser(parser, command), name)
        assert action is not None, f"{command} has no argument for {model.__name__}.{name}"
        assert option.flag in action.option_strings or action.option_strings == []
        assert action.help == option.help(command, info.description) and action.help
        literal = typing.get_args(info.annotation)
        if typing.get_origin(info.annotation) is typing.Literal:
            assert action.choices == list(literal)


def test_every_argument_of_every_command_is_a_declared_setting():
    """No flag is written by hand beside the declarations: each command's arguments are exactly
    the fields declared for it."""
    for command, parser in commands(build_parser()).items():
        dests = {a.dest for a in parser._actions if not isinstance(a, (argparse._HelpAction, argparse._SubParsersAction))}
        assert dests == {name for _, name, _, option in declared() if command in option.commands}, command


@pytest.mark.parametrize("name,info,option", [(n, i, o) for _, n, i, o in declared((RunConfig,)) if o.in_task],
                         ids=[n for _, n, _, o in declared((RunConfig,)) if o.in_task])
def test_every_setting_a_task_file_may_state_is_its_model_with_the_same_default(name, info, option):
    model = TaskOptions if option.in_task == OPTIONS else taskfile.TaskFile
    assert option.in_task in (OPTIONS, TOP_LEVEL)
    field = model.model_fields[name]
    assert field.annotation == info.annotation and field.default == info.default


def test_the_task_files_options_are_the_settings_declared_for_it_and_nothing_else():
    assert set(TaskOptions.model_fields) == {n for _, n, _, o in declared((RunConfig,)) if o.in_task == OPTIONS}
    with pytest.raises(ValidationError):
        TaskOptions(budget=-1)  # the bound declared on the setting
    with pytest.raises(ValidationError):
        TaskOptions(seed=3)  # a setting no task file may state


def test_every_setting_reaches_the_run_config_and_its_report():
    task = taskfile.load(TREES / "collect_cup.yaml")
    args = build_parser().parse_args(["run", str(TREES / "collect_cup.yaml")])
    config = dataclasses.asdict(RunConfig.from_task(task, **RunConfig.given(args, "run")))
    assert set(config) == set(RunConfig.__pydantic_fields__)
    assert all(config[name] is not None or info.default is None for name, info, _ in settings_fields(RunConfig))


def gripper_task(**options) -> taskfile.Task:
    spec = taskfile.TaskFile(name="p", domain=str(DOMAINS / "gripper-domain.pddl"),
                             problem=str(DOMAINS / "gripper-p4.pddl"), options=options)
    return taskfile.from_spec(spec, base=ROOT, where="p.yaml")


def test_a_flag_wins_over_the_task_files_option_which_wins_over_the_default():
    task = gripper_task(budget=5, verify="eff", injection=False, max_replans=7)

    def config(*flags: str) -> RunConfig:
        return RunConfig.from_task(task, **RunConfig.given(build_parser().parse_args(["run", *flags]), "run"))

    stated = config()
    assert (stated.budget, stated.verify, stated.injection, stated.max_replans) == (5, "eff", False, 7)
    assert stated.paraphrases == 5 and stated.seed == 0  # neither stated nor given: the default
    flags = config("--budget", "2", "--verify", "both", "--max-replans", "0")
    assert (flags.budget, flags.verify, flags.max_replans) == (2, "both", 0)  # 0 given is given
    assert flags.injection is False  # no flag: the task file's word stands
    assert config("--no-injection").injection is False
    assert RunConfig.from_task(gripper_task()).injection is True
    assert config("--transport", "inproc").transport == "inproc" and config().transport == "zenoh"
    assert RunConfig.from_task(task).transport == "inproc"  # the library's default, for campaigns


@pytest.mark.parametrize("argv,flag", [
    (["--claim-risk", "0.7"], "--claim-risk"),
    (["--budget", "-1"], "--budget"),
    (["--vlm-latency", "-1"], "--vlm-latency"),
    (["--max-replans", "many"], "--max-replans"),
    (["--protocol", "fast"], "--protocol"),
    (["--verify", "magic"], "--verify"),
    (["--viewpoints", "sideways"], "--viewpoints"),
])
def test_a_bad_flag_is_one_line_naming_it_and_exit_2(argv, flag, capsys):
    assert main(["run", str(TREES / "collect_cup.yaml"), *argv]) == EXIT_BAD_INPUT
    err = capsys.readouterr().err.strip().splitlines()
    assert flag in err[-1] and "Traceback" not in "\n".join(err)


@pytest.mark.parametrize("options,field", [("{budget: -1}", "options.budget"), ("{claim_risk: 0.1}", "options.claim_risk")])
def test_a_bad_task_file_option_is_one_line_naming_the_file_and_field(options, field, tmp_path, capsys):
    (tmp_path / "t.yaml").write_text(f"name: p\ndomain: {DOMAINS / 'gripper-domain.pddl'}\n"
                                     f"problem: {DOMAINS / 'gripper-p4.pddl'}\noptions: {options}\n")
    assert main(["run", str(tmp_path / "t.yaml")]) == EXIT_BAD_INPUT
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and f"t.yaml: field {field}" in err


def test_a_new_setting_is_one_field_and_reaches_the_flag_the_task_file_and_the_config():
    @settings_model
    class Extended(RunConfig):
        patience: Annotated[int, Option("--patience", ("run",), in_task=OPTIONS)] = Field(
            2, ge=0, description="how long to wait for a slow thing")

    parser = argparse.ArgumentParser()
    add_settings(parser, "run", Extended)
    action = action_for(parser, "patience")
    assert action.option_strings == ["--patience"] and action.help == "how long to wait for a slow thing"
    options = task_options(Extended)
    assert options().patience == 2 and options(patience=4).patience == 4
    with pytest.raises(ValidationError):
        options(patience=-1)
    stated = SimpleNamespace(options=options(patience=4), spec=SimpleNamespace(world="symbolic"))
    assert Extended.from_task(stated, **Extended.given(parser.parse_args([]), "run")).patience == 4
    assert Extended.from_task(stated, **Extended.given(parser.parse_args(["--patience", "9"]), "run")).patience == 9
    with pytest.raises(SystemExit):
        parser.parse_args(["--patience", "-3"])  # the field's bound, said by argparse


def test_the_viewpoints_choices_are_the_strategies_and_greedy_all_reaches_the_config():
    from vap_bt.perception.viewpoints import STRATEGIES

    info = next(i for n, i, _ in settings_fields(RunConfig) if n == "viewpoints")
    assert typing.get_args(info.annotation) == STRATEGIES
    task = taskfile.load(TREES / "collect_cup.yaml")
    args = build_parser().parse_args(["run", str(TREES / "collect_cup.yaml"), "--viewpoints", "greedy-all"])
    assert RunConfig.from_task(task, **RunConfig.given(args, "run")).viewpoints == "greedy-all"


def test_the_vlm_choices_are_the_backends_the_runner_builds():
    from vap_bt.app.runner import VLMS
    from vap_bt.perception.backends import BACKENDS

    assert set(VLMS) == {"sim", "sim-http", *BACKENDS}


def test_the_settings_and_their_arguments_import_nothing_heavy():
    heavy = ("py_trees", "numpy", "unified_planning", "zenoh", "pybullet", "open3d", "rerun", "cv2")
    code = ("import sys, vap_bt.settings, vap_bt.app.arguments; "
            f"print(sorted({{m.split('.')[0] for m in sys.modules}} & set({heavy!r})))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    assert out.stdout.strip() == "[]"
