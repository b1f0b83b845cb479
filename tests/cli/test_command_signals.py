"""`certify census` and `certify atlas` take SIGTERM as Ctrl-C while they run (`kill` stops them, their
workers too) and give the handler before back when they end, normally, on bad input or interrupted
(cli.options.kill_interrupts): a caller of cli.main in-process (a test, a library) keeps its handlers."""
import signal

import pytest

from certify import cli
from certify.cli.options import kill_interrupts

TINY = {
    "census": ["census", "--max-length", "3", "--jobs", "1"],
    "census --particles 5": ["census", "--particles", "5", "--max-length", "4", "--jobs", "1"],
    "atlas": ["atlas", "--resolution", "1", "--data", "0", "--collisions", "200", "--seeds", "none", "--refine", "0",
              "--jobs", "1"],
}


def _mine(signum, frame):          # pragma: no cover - never called: the caller's own handler
    pass


@pytest.fixture
def own_handler():
    before = signal.signal(signal.SIGTERM, _mine)
    yield
    signal.signal(signal.SIGTERM, before)


@pytest.mark.parametrize("name", TINY)
def test_an_in_process_command_gives_back_the_sigterm_handler(name, tmp_path, own_handler):
    assert cli.main([*TINY[name], "--out", str(tmp_path)]) == 0
    assert signal.getsignal(signal.SIGTERM) is _mine
    blocker = tmp_path / "a file"
    blocker.write_text("")
    assert cli.main([*TINY[name], "--out", str(blocker)]) == 2          # bad input, found by the command
    assert signal.getsignal(signal.SIGTERM) is _mine


def test_while_a_command_runs_sigterm_is_ctrl_c(own_handler):
    seen = []

    @kill_interrupts
    def command(args):
        seen.append(signal.getsignal(signal.SIGTERM))
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        command(None)
    assert seen == [signal.default_int_handler] and signal.getsignal(signal.SIGTERM) is _mine
