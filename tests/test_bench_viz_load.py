"""The loading bench's own arithmetic (tools/bench/viz_load.py): its command line, the order of
its runs and its table. The browser part is the live-view test's (tests/web_viewer.py)."""

from __future__ import annotations

import pytest

pytest.importorskip("rerun")

from tools.bench.viz_load import Recording, Run, Summary, parse, schedule, table  # noqa: E402


@pytest.fixture
def files(tmp_path):
    before, after = tmp_path / "before.rrd", tmp_path / "after.rrd"
    before.write_bytes(b"x" * 4_000_000)
    after.write_bytes(b"x" * 1_000_000)
    return before, after


def test_labels_default_to_the_file_names_and_must_match_the_files(files, capsys):
    before, after = files
    assert parse(["--rrd", str(before), "--rrd", str(after)]).label == ["before", "after"]
    assert parse(["--rrd", str(before), "--label", "a", "--rrd", str(after), "--label", "b"]).label == ["a", "b"]
    for argv in (["--rrd", str(before), "--rrd", str(after), "--label", "only one"],
                 ["--rrd", str(before), "--rrd", str(before)],  # the same label twice
                 ["--rrd", str(before.with_name("missing.rrd"))],
                 ["--rrd", str(before), "--runs", "0"]):
        with pytest.raises(SystemExit):
            parse(argv)
    assert "one per file" in capsys.readouterr().err


def test_rounds_alternate_the_order_of_the_files():
    assert schedule(2, 4) == [[0, 1], [1, 0], [0, 1], [1, 0]]
    assert schedule(1, 3) == [[0], [0], [0]]


def test_a_summary_is_the_median_and_range_and_counts_the_runs_that_missed():
    assert Summary([3.0, 1.0, 2.0]).cell() == "2.0 [1.0-3.0]"
    assert Summary([5.0]).cell() == "5.0"
    assert Summary([4.0, None, 2.0]).cell() == "3.0 [2.0-4.0] (1 missed)"
    assert Summary([None, None]).cell() == "-"


def test_the_ratios_are_taken_within_each_round(files):
    before, after = files
    recs = [Recording(before, "before"), Recording(after, "after")]
    rounds = [{"before": Run("before", 3.0, 40.0, 80.0, 600), "after": Run("after", 3.0, 10.0, 20.0, 590)},
              {"before": Run("before", 3.0, 60.0, 100.0, 600), "after": Run("after", 3.0, 30.0, 50.0, 600)},
              {"before": Run("before", 3.0, 50.0, None, None), "after": Run("after", 3.0, 20.0, 30.0, 600)}]
    lines = table(recs, rounds).splitlines()
    assert lines[0].split() == ["recording", "MB", "viewer", "up", "s", "first", "tree", "s", "whole",
                                "recording", "s", "end", "px"]
    cells = lambda k: [c.strip() for c in lines[k].split("  ") if c.strip()]  # noqa: E731
    assert cells(2) == ["before", "4.00", "3.0 [3.0-3.0]", "50.0 [40.0-60.0]", "90.0 [80.0-100.0] (1 missed)",
                        "600 [600-600] (1 missed)"]
    assert cells(3) == ["after", "1.00", "3.0 [3.0-3.0]", "20.0 [10.0-30.0]", "30.0 [20.0-50.0]", "600 [590-600]"]
    # first tree: 10/40, 30/60, 20/50 -> median 0.40; whole recording: 20/80, 50/100 (the third missed)
    assert cells(4) == ["after/before", "0.25", "1.00 [1.00-1.00]", "0.40 [0.25-0.50]", "0.38 [0.25-0.50] (1 missed)"]
