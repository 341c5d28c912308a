"""Work in flight: what a behaviour starts and then polls, instead of waiting for it.

py_trees' rule is that ``update()`` never blocks. A camera capture, a VLM question and a
viewpoint move all take time (a real model answers in hundreds of milliseconds), so behaviours
hand them to an executor and keep the :class:`~concurrent.futures.Future`: each tick they look
whether it is done and return RUNNING meanwhile; ``terminate()`` cancels what has not started
(a question already on the wire is let finish and its answer dropped).

Two executors serve: a bounded thread pool, so that a round's questions are in flight at once
against a remote model, and :class:`InlineExecutor`, which does the work at submission — for the
symbolic world's in-process campaigns, where every answer is immediate and threads would only
cost time (the behaviours are the same; their futures are simply done when they first look).
The robot's state service is never asked inline (:func:`body_executor`): it answers from another
process, in its own time, whatever the rest of the work does.
"""

from __future__ import annotations

import time
from concurrent.futures import Executor, Future, ThreadPoolExecutor
from contextlib import contextmanager
from typing import Any, Callable, Iterator

#: questions to a VLM in flight at once: a round's five paraphrases and its sufficiency question
MAX_IN_FLIGHT = 8


class InlineExecutor(Executor):
    """Runs each submission at once in the caller's thread; the future is done on return."""

    def submit(self, fn: Callable[..., Any], /, *args: Any, **kwargs: Any) -> Future:
        f: Future = Future()
        try:
            f.set_result(fn(*args, **kwargs))
        except BaseException as exc:  # the behaviour reads it from the future, as from a thread
            f.set_exception(exc)
        return f


def make_executor(concurrent: bool) -> Executor:
    """A thread pool for work that takes time, or the inline executor for immediate answers."""
    return ThreadPoolExecutor(MAX_IN_FLIGHT, thread_name_prefix="inflight") if concurrent else InlineExecutor()


@contextmanager
def working(concurrent: bool) -> Iterator[Executor]:
    """:func:`make_executor` for the length of a ``with`` block, and on leaving it — done, failed or
    a Ctrl-C — what has not started is cancelled and nothing is waited for: ``Executor``'s own
    ``with`` waits for every queued question, which after a Ctrl-C in the survey can keep the
    process alive long after its report was written (the likely cause of a flaky interrupt test)."""
    executor = make_executor(concurrent)
    try:
        yield executor
    finally:
        executor.shutdown(wait=False, cancel_futures=True)


def body_executor(executor: Executor) -> Executor:
    """Where the robot's state service is asked: ``executor`` when it is a pool of workers, else a
    worker of its own — an inline executor would ask it on the ticking thread, and a state query
    can take as long as the robot likes (a Zenoh query waits up to its timeout)."""
    if isinstance(executor, InlineExecutor):
        return ThreadPoolExecutor(1, thread_name_prefix="body")
    return executor


def in_flight(f: Future) -> bool:
    """Whether ``f`` is not done yet; if not, the ticking thread lets the interpreter go for a
    moment (``sleep(0)``: a yield, not a wait) so that a worker answering in-process — the
    robot-state service of a simulated robot answers in microseconds — finishes now, instead of
    after the interpreter's switch interval of ticks spent asking whether it has."""
    if f.done():
        return False
    time.sleep(0)
    return not f.done()


def cancel_all(futures) -> None:
    """Cancel every future that has not started; the rest finish unheard."""
    for f in futures:
        if f is not None:
            f.cancel()
