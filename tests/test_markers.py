"""The suite's own markers: a test expected to fail must fail the way its marker says.

A strict ``xfail`` passes the run whenever the test fails, for whatever reason; the skills' markers
(:func:`skill_runs.skills_fail`) also name what the failure says (``fails_saying``), and
tests/conftest.py fails the run when it says something else.
"""

from __future__ import annotations

from pathlib import Path

pytest_plugins = ["pytester"]

CONFTEST = Path(__file__).with_name("conftest.py")


def test_an_expected_failure_fails_the_run_when_it_says_something_else(pytester):
    pytester.makeconftest(CONFTEST.read_text())
    pytester.makepyfile(test_marked='''
import pytest

said = pytest.mark.fails_saying("tap out of reach")


@pytest.mark.xfail(strict=True, reason="the tap")
@said
def test_fails_as_said():
    assert False, "fill(cup, kitchen_sink): aborted kitchen_sink: tap out of reach"


@pytest.mark.xfail(strict=True, reason="the tap")
@said
def test_fails_otherwise():
    assert False, "close(cabinet): aborted cabinet: handle out of reach"


@pytest.mark.xfail(strict=True, reason="the tap")
@said
def test_passes():
    pass


@pytest.mark.xfail(strict=True, reason="no text named")
def test_fails_unnamed():
    assert False, "anything"
''')
    result = pytester.runpytest("-p", "no:cacheprovider", "-W", "ignore::pytest.PytestUnknownMarkWarning")
    result.assert_outcomes(xfailed=2, failed=2)
    result.stdout.fnmatch_lines(["*test_fails_otherwise*", "*not as its marker says*'tap out of reach'*handle out of reach*"])
