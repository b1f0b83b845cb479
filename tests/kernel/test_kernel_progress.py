"""The kernel's progress (issue 38 item 4): ``python3 -m certify_kernel`` and ``certify verify``
said nothing for minutes.  verify_all ticks from 0 (the bar drawn at once), then after each
certificate; the kernel's own line goes to stderr only when stderr is a terminal."""
from __future__ import annotations

import io
import json

import certify_kernel
from certify_kernel import __main__ as kernel_main
from certify_kernel.statements import read
from tests.kernel.kernel_support import honest_file, write_statements
from tests.kernel.test_kernel_verify import TEXT


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def files(tmp_path):
    statements = write_statements(tmp_path / "statements", TEXT)
    path = tmp_path / "certificates.json"
    path.write_text(json.dumps(honest_file(read(statements))), encoding="utf-8")
    return statements, path


def test_verify_all_ticks_from_zero(tmp_path):
    statements, path = files(tmp_path)
    calls = []
    certify_kernel.verify_all(json.loads(path.read_text()), read(statements), 1,
                              tick=lambda k, n, label: calls.append((k, n)))
    assert calls == [(0, 3), (1, 3), (2, 3), (3, 3)]


def test_the_kernel_shows_progress_on_a_terminal_only(tmp_path, monkeypatch, capsys):
    statements, path = files(tmp_path)
    argv = [str(path), "--statements", str(statements), "--jobs", "1"]
    assert kernel_main.main(argv) == 0
    assert capsys.readouterr().err == ""                   # a pipe or a file: nothing
    terminal = Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    assert kernel_main.main(argv) == 0
    drawn = terminal.getvalue()
    assert "\r0/3 certificates decided\x1b[K" in drawn and "2/3 certificates decided (last: " in drawn
    assert drawn.endswith("\r\x1b[K")                       # erased at the end


def test_forked_workers_end_even_where_the_parent_swallows_sigterm(tmp_path):
    """verify_all on 4 forked workers, 40 times, in a process whose SIGTERM handler returns without
    raising (as a test or a tool may leave one): the pool's exit terminates its workers and
    returns.  With the handler inherited by the workers it waited for ever (issue seen under
    pytest-xdist); run in a child process that prints a line after each run, so that a hang (no
    line for STALL seconds) fails, not blocks, while a slow run on a loaded machine passes."""
    import os
    import selectors
    import signal
    import subprocess
    import sys
    from pathlib import Path
    stall = 60
    statements, path = files(tmp_path)
    script = (
        "import json, signal, sys\n"
        "import certify_kernel\n"
        "from certify_kernel.statements import read\n"
        "signal.signal(signal.SIGTERM, lambda *a: None)\n"
        f"data, paper = json.loads(open({str(path)!r}).read()), read({str(statements)!r})\n"
        "for _ in range(40):                     # the exit's race: the parent takes the queue's lock first\n"
        "    res = certify_kernel.verify_all(data, paper, 4)\n"
        "    print(len(res), all(r['ok'] for r in res), flush=True)\n")
    root = Path(__file__).resolve().parents[2]
    child = subprocess.Popen([sys.executable, "-c", script], cwd=root, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, start_new_session=True)
    lines = []
    with selectors.DefaultSelector() as sel:
        sel.register(child.stdout, selectors.EVENT_READ)
        while True:
            if not sel.select(timeout=stall):
                os.killpg(child.pid, signal.SIGKILL)           # the child and its workers (they hold the pipe)
                child.wait()
                raise AssertionError(f"verify_all did not return within {stall} s (after {len(lines)} runs): "
                                     "its workers took SIGTERM without ending")
            line = child.stdout.readline()
            if not line:
                break
            lines.append(line.split())
    err = child.communicate()[1]
    assert child.returncode == 0 and lines == [["3", "True"]] * 40, err
