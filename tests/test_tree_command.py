"""``vap-bt tree TASK``: the compiled tree, printed without running anything, in three formats;
and ``--help`` of every command ends with examples."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import py_trees
import pydot
import pytest

from conftest import ROOT, TREES, tree_for

TASK = TREES / "collect_cup.yaml"


@pytest.fixture(scope="module")
def compiled():
    """The tree ``vap-bt tree`` should print: the first plan from the stated initial state."""
    from vap_bt.domain.planner import Planner
    from vap_bt.taskfile import load

    planning = load(TASK).planning
    return tree_for(planning, Planner(planning).plan().actions, "both")


def nodes(root):
    yield root
    for c in root.children:
        yield from nodes(c)


def test_ascii_is_py_trees_own_display_of_the_compiled_tree(cli, compiled):
    code, out, err = cli("tree", TASK)
    assert code == 0 and err == ""
    assert out == py_trees.display.ascii_tree(compiled)
    lines = out.splitlines()
    assert len(lines) == len(list(nodes(compiled)))
    assert lines[0] == "{-} plan"
    actions = [l.strip() for l in lines if l.startswith("    {-} a")]
    assert actions == [f"{{-}} {c.name}" for c in compiled.children if c.name.startswith("a")]
    assert "--> goal check" in out and "-^- look(K=3)" in out


@pytest.mark.filterwarnings("ignore::DeprecationWarning")  # pydot's parser on a newer pyparsing
def test_dot_is_a_graph_of_every_node_that_graphviz_can_read(cli, compiled):
    code, out, _ = cli("tree", TASK, "--format", "dot")
    assert code == 0
    graph = pydot.graph_from_dot_data(out)[0]
    names = {n.get_name().strip('"') for n in graph.get_nodes()} - {"node", "edge", "graph"}
    edges = [(e.get_source().strip('"'), e.get_destination().strip('"')) for e in graph.get_edges()]
    ours = list(nodes(compiled))
    assert len(names) == len(ours) and len(edges) == len(ours) - 1  # a tree: one edge per non-root node
    assert all(a in names and b in names for a, b in edges), "an edge names a node that is not declared"
    actions = [c.name for c in compiled.children if c.name.startswith("a")]
    assert [b for a, b in edges if a == "plan"][:len(actions)] == actions  # ":" survives in the IDs


def test_xml_is_the_btcpp_export(cli, compiled, tmp_path):
    code, out, _ = cli("tree", TASK, "--format", "xml")
    assert code == 0
    _, exported, _ = cli("export", TASK)
    assert out == exported
    doc = ET.fromstring(out)
    assert doc.get("BTCPP_format") == "4" and len(list(doc.find("BehaviorTree")[0].iter())) == len(list(nodes(compiled)))
    dest = tmp_path / "tree.txt"
    assert cli("tree", TASK, "--verify", "eff", "-o", dest)[0] == 0
    text = dest.read_text()
    assert "{-} eff" in text and "{-} pre" not in text


def test_a_missing_task_file_is_one_line_and_exit_2(cli, tmp_path):
    code, out, err = cli("tree", tmp_path / "nope.yaml")
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and "nope.yaml" in err


@pytest.mark.parametrize("command", ["plan", "run", "export", "tree", "skills", "serve"])
def test_every_command_help_ends_with_examples(cli, command):
    code, out, _ = cli(command, "--help")
    assert code == 0
    examples = out.split("examples:\n", 1)[1].splitlines()
    assert examples and all(l.startswith(f"  vap-bt {command}") for l in examples), out


def help_examples(argv: list[str]) -> list[str]:
    """The example lines of ``vap-bt ARGV --help``."""
    import contextlib
    import io

    from vap_bt.app.cli import main

    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main([*argv, "--help"]) == 0
    return [l.strip() for l in out.getvalue().split("examples:\n", 1)[1].splitlines() if l.strip()]


@pytest.mark.parametrize("command", ["plan", "run", "export", "tree", "skills", "serve"])
def test_every_help_example_is_a_real_command_line(command):
    """Each example parses as written (comments and shell redirections aside), and the task files
    and PDDL files it names are in the checkout, so it runs from a fresh clone."""
    import shlex

    from vap_bt.app.cli import build_parser

    for line in help_examples([command]):
        words = shlex.split(line.split("#")[0].split(">")[0].split("|")[0])
        assert words[:2] == ["vap-bt", command], line
        build_parser().parse_args(words[1:])  # argparse exits on a word it does not take
        named = [w for w in words if w.endswith((".yaml", ".pddl"))]
        assert all((ROOT / w).is_file() for w in named), line


@pytest.mark.parametrize("command", ["plan", "run", "export", "tree", "skills", "serve", "sim"])
def test_every_argument_of_every_command_is_explained_in_plain_text(command):
    """``--help`` gives each positional and option a line of text, and shows no reStructuredText
    (``sim --help`` printed its module docstring's double back-quotes)."""
    from vap_bt.app.cli import build_parser

    parser = build_parser()
    command_parser = parser._subparsers._group_actions[0].choices[command]
    assert [a.dest for a in command_parser._actions if not a.help] == []
    assert "``" not in command_parser.format_help()


def test_top_level_help_shows_examples(cli):
    code, out, _ = cli("--help")
    assert code == 0 and "examples:\n  vap-bt run trees/collect_cup.yaml" in out
