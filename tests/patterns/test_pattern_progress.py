"""Progress of a long analysis (issue 38 item 4): ``certify pattern`` on a long word said nothing
for minutes.  ``analyse`` reports each collision's conditions and then stability, k of n, from
k = 0 (the bar is drawn at once); the command draws it on a terminal only."""
import io

from certify import cli
from certify.patterns import analyse
from certify.patterns.periodic import read


def test_analyse_reports_every_collision_then_stability():
    calls = []
    res = analyse("abacbcb", progress=lambda k, n, label="": calls.append((k, n, label)))
    n = len(read("abacbcb")[0]) + 2                    # existence, seven collisions, stability
    assert [c[:2] for c in calls] == [(k, n) for k in range(n + 1)]
    assert [c[2] for c in calls[1:3]] == ["exists", "collision 1 of 7"] and calls[-1][2] == "stable"
    assert res.to_json() == analyse("abacbcb").to_json()       # the same analysis, with or without


def test_the_family_route_jumps_to_stability():
    """(ab)^n(cb)^n: feasibility from the family's reduced conditions, at once (no collision steps)."""
    calls = []
    analyse("(ab)^2(cb)^2", progress=lambda k, n, label="": calls.append((k, n)))
    assert calls == [(0, 10), (1, 10), (10, 10)]


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_the_command_draws_progress_on_a_terminal_only(monkeypatch, capsys):
    assert cli.main(["pattern", "abcb"]) == 0
    quiet = capsys.readouterr()
    assert quiet.err == "" and quiet.out.startswith("# Pattern abcb")
    terminal = Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    assert cli.main(["pattern", "abcb"]) == 0
    assert "collision 1 of 4" in terminal.getvalue() and capsys.readouterr().out == quiet.out
