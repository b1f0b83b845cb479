"""Where many independent jobs run: one small choice, shared by the census and sweeps.

:func:`executor` is a context manager that yields a :class:`concurrent.futures.Executor`:

* ``scheduler`` given: the executor of a Dask cluster (``dask.distributed``, the
  optional extra ``certify[distributed]``) at that address, e.g. ``tcp://host:8786``;
  an address that cannot be reached within ``timeout`` seconds, or a missing
  ``distributed``, is a :class:`~certify.errors.UsageError` (one line, exit code 2);
* else ``jobs`` > 1 (default: every core): local worker processes
  (:class:`~concurrent.futures.ProcessPoolExecutor`, forked where possible, so that a
  worker inherits what the parent already computed);
* ``jobs`` = 1: :class:`Serial`, every job run in this process when it is submitted
  (no pickling; what a test or a certificate wants).

Jobs must be module-level functions of picklable arguments returning plain data.

A Dask worker must run one thread per process (``dask worker --nthreads 1``): python-flint's
working precision (``flint.ctx.prec``) is global to a process, so two threads that set it at
once would leave each other's balls at a precision neither asked for (still rigorous, but
possibly undecided, and not the same bytes).  With ``one_thread`` (the census) a cluster
whose workers run more threads is refused when the command connects (a worker that joins
later is not checked).

Interruption (Ctrl-C, ``kill -INT``, ``kill``): :func:`process_pool` is the one way this
package runs local worker processes (the census, the sweeps, ``certify all``).  While it
runs, SIGINT and SIGTERM raise :class:`KeyboardInterrupt` in the parent only outside the
pool's own locks: inside :meth:`Pool.submit` and :func:`wait_first` the signal is held and
raised as soon as they return (a :class:`KeyboardInterrupt` raised inside
``concurrent.futures.wait`` could leave a future's lock held, and the pool's manager thread
then waited on it for good).  The workers ignore SIGINT and die of SIGTERM (no Python
handler, so no traceback); on the way out the parent terminates them, kills any that a
signal missed (one sent while the worker was being forked is lost), and only then shuts the
pool down, so the command ends at once with every worker gone.  On a Dask cluster the signals
are held the same way, and an interrupted run cancels its jobs instead of waiting for them.
"""
from __future__ import annotations

import multiprocessing
import signal
import threading
from concurrent.futures import FIRST_COMPLETED, Executor, Future, ProcessPoolExecutor, wait
from contextlib import contextmanager

from certify.cores import default_jobs  # noqa: F401  (executors.default_jobs, as before)
from certify.errors import UsageError

CONNECT_TIMEOUT = 10          # seconds to reach a scheduler
GRACE = 2.0                   # seconds a terminated worker has to die before it is killed


class Serial(Executor):
    """An executor that runs each job at once, in this process."""

    def submit(self, fn, /, *args, **kwargs):
        future = Future()
        try:
            future.set_result(fn(*args, **kwargs))
        except BaseException as exc:      # a KeyboardInterrupt too: the caller decides
            if isinstance(exc, (KeyboardInterrupt, SystemExit)):
                raise
            future.set_exception(exc)
        return future


def _worker_start(initializer=None, *initargs) -> None:
    """In a local worker: Ctrl-C is the parent's to handle, SIGTERM (the parent's
    terminate) ends the worker at once, without a Python handler (the parent's, inherited
    by the fork, would raise in the worker and print a traceback); then ``initializer``."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    if initializer is not None:
        initializer(*initargs)


_held = 0                     # > 0 while the parent is inside the pool's locks (submit, wait)
_signalled: list[int] = []    # a signal received meanwhile, raised when they return


def _interrupt(signum, frame) -> None:
    """The parent's SIGINT and SIGTERM while a pool runs: KeyboardInterrupt now, or when
    the pool's locks are released (:func:`_holding`)."""
    if _held:
        _signalled.append(signum)
        return
    raise KeyboardInterrupt


@contextmanager
def _holding():
    """Hold SIGINT and SIGTERM while the pool's locks may be taken; raise
    KeyboardInterrupt after, if one came."""
    global _held
    _held += 1
    try:
        yield
    finally:
        _held -= 1
        if not _held and _signalled:
            _signalled.clear()
            raise KeyboardInterrupt


def wait_first(futures, timeout: float):
    """``concurrent.futures.wait(futures, timeout, FIRST_COMPLETED)`` (done, not done), a
    signal held until it returns: the way to wait on a :func:`process_pool` (or any
    executor) from a loop that Ctrl-C must stop."""
    with _holding():
        return wait(futures, timeout=timeout, return_when=FIRST_COMPLETED)


class Pool(ProcessPoolExecutor):
    """Local worker processes (:func:`process_pool`): submit holds a signal until it returns."""

    def submit(self, fn, /, *args, **kwargs):
        with _holding():
            return super().submit(fn, *args, **kwargs)


def _stop_workers(pool: Pool) -> None:
    """Terminate the pool's workers, kill those still alive after :data:`GRACE` seconds,
    and close the parent's end of their result pipe (a worker stopped in the middle of a
    result would leave the pool's manager thread reading it for good)."""
    workers = list((pool._processes or {}).values())
    for p in workers:
        p.terminate()
    for p in workers:
        p.join(GRACE)
        if p.is_alive():
            p.kill()
            p.join()
    queue = pool._result_queue
    if queue is not None:
        queue._writer.close()


@contextmanager
def _signals_held():
    """SIGINT and SIGTERM handled by :func:`_interrupt` (in the main thread; elsewhere
    nothing changes) while a pool runs; the handlers before restored after.  Yields the
    signals it handles."""
    main = threading.current_thread() is threading.main_thread()
    old = {s: signal.signal(s, _interrupt) for s in (signal.SIGINT, signal.SIGTERM)} if main else {}
    try:
        yield list(old)
    finally:
        for s, handler in old.items():
            signal.signal(s, handler)
        _signalled.clear()


@contextmanager
def process_pool(jobs: int, initializer=None, initargs=(), context=None):
    """``jobs`` local worker processes (forked where possible) as a :class:`Pool`; on any
    exception (Ctrl-C, SIGTERM, an error) the workers are stopped at once, then the pool is
    shut down, pending jobs cancelled."""
    if context is None:
        context = multiprocessing.get_context("fork" if "fork" in multiprocessing.get_all_start_methods() else None)
    with _signals_held() as handled:
        pool = Pool(jobs, mp_context=context, initializer=_worker_start, initargs=(initializer, *initargs))
        try:
            yield pool
        except BaseException:
            for s in handled:                     # a second Ctrl-C must not cut the cleanup short
                signal.signal(s, signal.SIG_IGN)
            _stop_workers(pool)
            raise
        finally:
            pool.shutdown(wait=True, cancel_futures=True)


@contextmanager
def executor(jobs: int | None = None, scheduler: str | None = None, timeout: float | None = None,
             one_thread: bool = False):
    """Yield the executor for ``jobs`` local processes or the Dask ``scheduler``
    (see the module's docstring); shut it down (pending jobs cancelled) on exit.
    ``one_thread``: refuse a cluster whose workers run several threads (jobs that set
    python-flint's precision, such as the census's)."""
    if scheduler:
        with _dask(scheduler, CONNECT_TIMEOUT if timeout is None else timeout, one_thread) as ex:
            yield ex
        return
    jobs = default_jobs() if jobs is None else jobs
    if jobs < 1:
        raise UsageError(f"--jobs must be a positive integer, not {jobs}")
    if jobs == 1:
        yield Serial()
        return
    with process_pool(jobs) as pool:
        yield pool


@contextmanager
def _dask(address: str, timeout: float, one_thread: bool = False):
    try:
        from distributed import Client
    except ImportError:
        raise UsageError("--scheduler needs dask.distributed: pip install 'certify[distributed]'") from None
    try:
        client = Client(address, timeout=timeout, set_as_default=False)
    except (OSError, TimeoutError, ValueError, TypeError) as exc:
        reason = " ".join(str(exc).split()) or type(exc).__name__
        raise UsageError(f"cannot reach the scheduler {address!r}: {reason}") from None
    threads = set(client.nthreads().values())
    if one_thread and threads - {1}:
        client.close()
        raise UsageError(f"the workers of {address!r} run {max(threads)} threads each: run them with one "
                         "(dask worker --nthreads 1), python-flint's precision is global to a process")
    ex = client.get_executor(pure=False)
    try:
        with _signals_held():
            yield ex
    except BaseException:
        ex.shutdown(wait=False)          # Ctrl-C, an error: cancel the jobs on the cluster, do not wait for them
        raise
    finally:
        ex.shutdown(wait=True)           # (nothing left to wait for after a cancel)
        client.close()
