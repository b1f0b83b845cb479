"""Ctrl-C, ``kill -INT`` and ``kill`` on a run with local worker processes
(certify/run/executors.py, issue 38 item 1): exit 130 within seconds, every worker gone,
no traceback.  The race it guards against: a signal that reached the parent while it forked
its workers, or inside the pool's locks, left it waiting for good on a worker that nobody
stopped (3 runs in 12 of `timeout -s INT 6 certify census --max-length 12`)."""
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from certify.run import executors

ROOT = Path(__file__).resolve().parents[2]


def _sleep(seconds):
    time.sleep(seconds)
    return seconds


def test_a_signal_inside_the_pool_locks_is_raised_when_they_are_released():
    reached = False
    with pytest.raises(KeyboardInterrupt):
        with executors.process_pool(2):
            with executors._holding():
                os.kill(os.getpid(), signal.SIGINT)        # held: the section goes on to its end
                time.sleep(0.05)
                reached = True
            pytest.fail("the signal was not raised after the section")       # pragma: no cover
    assert reached


def test_an_interrupted_pool_leaves_no_worker_and_restores_the_handlers():
    before = signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)
    with pytest.raises(KeyboardInterrupt):
        with executors.process_pool(2) as pool:
            pool.submit(_sleep, 30)
            workers = list(pool._processes.values())
            executors.wait_first({pool.submit(_sleep, 30)}, 0.2)
            os.kill(os.getpid(), signal.SIGTERM)            # kill: like Ctrl-C
            executors.wait_first({pool.submit(_sleep, 30)}, 5)
    assert workers and not any(p.is_alive() for p in workers)
    assert all(p.exitcode == -signal.SIGTERM for p in workers)     # SIGTERM ends them: no Python handler
    assert (signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)) == before


def _session(sid: int) -> list[int]:
    """The processes of a session (Linux /proc)."""
    out = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[3]) == sid and fields[0] != "Z":
                out.append(int(entry.name))
    return out


def _children(pid: int) -> list[int]:
    try:
        return [int(x) for x in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
    except OSError:
        return []


def interrupt_once(tmp_path, signum, delay: float, argv) -> tuple[int | None, str, list[int]]:
    """Start ``certify ARGV`` in a session of its own, send ``signum`` to its main process
    ``delay`` seconds after its first worker appeared; return its exit code (None if it
    did not exit within 10 s), its stderr and the processes of its session still there."""
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    env.pop("CERTIFY_DEBUG", None)
    with open(tmp_path / "err", "w+") as err:
        proc = subprocess.Popen([sys.executable, "-m", "certify", *argv], cwd=ROOT, env=env, stdout=subprocess.DEVNULL,
                                stderr=err, start_new_session=True)
        try:
            start = time.monotonic()
            while not _children(proc.pid) and proc.poll() is None and time.monotonic() - start < 120:
                time.sleep(0.001)
            time.sleep(delay)
            proc.send_signal(signum)
            try:
                code = proc.wait(10)
            except subprocess.TimeoutExpired:
                code = None
            time.sleep(0.2)
            left = _session(proc.pid)
        finally:
            for pid in _session(proc.pid):
                os.kill(pid, signal.SIGKILL)
            proc.wait()
        err.seek(0)
        return code, err.read(), left


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads the processes from /proc (Linux)")
@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_census_ends_at_once_on_a_signal_to_its_main_process(tmp_path, signum):
    """`timeout -s INT`, a scheduler's kill: the signal at the parent only, at moments
    from the workers' fork on; 12 runs, each must exit 130 within 10 s, nothing left."""
    for k in range(12 if signum == signal.SIGINT else 4):
        out = tmp_path / str(k)
        out.mkdir()
        code, err, left = interrupt_once(out, signum, [0, 0, 0.002, 0.01, 0.05, 0.2][k % 6] * (1 + k // 6),
                                         ["census", "--max-length", "12", "--jobs", "2", "--out", str(out)])
        assert (code, left) == (130, []), (k, code, left, err)
        assert err == "certify: interrupted\n", (k, err)


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads the processes from /proc (Linux)")
def test_certify_all_ends_at_once_on_sigint_to_its_main_process(tmp_path):
    """The runner's pool (certify all, certify bench) is the same process_pool: 4 runs."""
    for k in range(4):
        out = tmp_path / str(k)
        out.mkdir()
        code, err, left = interrupt_once(out, signal.SIGINT, [0, 0.01, 0.1, 0.5][k],
                                         ["all", "--jobs", "2", "--out", str(out)])
        assert (code, left) == (130, []), (k, code, left, err)
        assert err.splitlines()[-1] == "certify: interrupted" and "Traceback" not in err, (k, err)


@pytest.mark.slow
def test_an_interrupted_run_on_a_dask_cluster_cancels_its_jobs_instead_of_waiting():
    """Ctrl-C with --scheduler: the jobs in flight are cancelled, not waited for (before,
    the executor's shutdown waited for them: minutes for the words of a long census)."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(processes=False, n_workers=1, threads_per_worker=1, dashboard_address=None,
                                  silence_logs=40) as cluster:
        start = time.monotonic()
        with pytest.raises(KeyboardInterrupt):
            with executors.executor(scheduler=cluster.scheduler_address) as ex:
                future = ex.submit(_sleep, 6)
                executors.wait_first({future}, 0.5)
                raise KeyboardInterrupt
        assert time.monotonic() - start < 4
