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
possibly undecided, and not the same bytes).
"""
from __future__ import annotations

import multiprocessing
from concurrent.futures import Executor, Future, ProcessPoolExecutor
from contextlib import contextmanager

from certify.cores import default_jobs  # noqa: F401  (executors.default_jobs, as before)
from certify.errors import UsageError

CONNECT_TIMEOUT = 10          # seconds to reach a scheduler


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


def _worker_start() -> None:
    """In a local worker: Ctrl-C is the parent's to handle (it shuts the pool down)."""
    import signal
    signal.signal(signal.SIGINT, signal.SIG_IGN)


@contextmanager
def executor(jobs: int | None = None, scheduler: str | None = None, timeout: float | None = None):
    """Yield the executor for ``jobs`` local processes or the Dask ``scheduler``
    (see the module's docstring); shut it down (pending jobs cancelled) on exit."""
    if scheduler:
        with _dask(scheduler, CONNECT_TIMEOUT if timeout is None else timeout) as ex:
            yield ex
        return
    jobs = default_jobs() if jobs is None else jobs
    if jobs < 1:
        raise UsageError(f"--jobs must be a positive integer, not {jobs}")
    if jobs == 1:
        yield Serial()
        return
    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if "fork" in methods else None)
    pool = ProcessPoolExecutor(jobs, mp_context=context, initializer=_worker_start)
    try:
        yield pool
    except BaseException:
        for child in multiprocessing.active_children():   # stop the workers now (Ctrl-C)
            child.terminate()
        raise
    finally:
        pool.shutdown(wait=True, cancel_futures=True)


@contextmanager
def _dask(address: str, timeout: float):
    try:
        from distributed import Client
    except ImportError:
        raise UsageError("--scheduler needs dask.distributed: pip install 'certify[distributed]'") from None
    try:
        client = Client(address, timeout=timeout, set_as_default=False)
    except (OSError, TimeoutError, ValueError, TypeError) as exc:
        reason = " ".join(str(exc).split()) or type(exc).__name__
        raise UsageError(f"cannot reach the scheduler {address!r}: {reason}") from None
    try:
        with client.get_executor(pure=False) as ex:
            yield ex
    finally:
        client.close()
