"""Section 5: the observables of certify.numerics.figures on synthetic data, the
`certify figures` command, and the certificates N1-N7 (OBSERVED; an altered print is
reported as a disagreement: their mutants are in tests/proofs/test_mutants.py)."""
from __future__ import annotations

import math

import numpy as np
import pytest

import certify.numerics as F
from certify.cli import main
from certify.run import load_findings, runner
from certify.run import saving as figures
from certify.run.runner import OBSERVED
from tests.shared import outcome as run

# --- observables on synthetic data ------------------------------------------------------

def synthetic(phi, breaks=None, r=None):
    phi = np.asarray(phi, float)
    r = np.linspace(0.1, 0.2, phi.shape[0]) if r is None else np.asarray(r, float)
    breaks = np.zeros(phi.shape[:2], dtype=np.int8) if breaks is None else np.asarray(breaks)
    return F.FigureData(F.SPECS["5.2"], "preview", r, phi, breaks, 100, phi.shape[2], "float64")


def test_clusters_cut_at_gaps_and_skip_nans():
    v = [0.5, 0.5 + 1e-9, np.nan, 2.0, 2.0005, 3.0]
    assert [(round(lo, 4), round(hi, 4), n) for lo, hi, n in F.clusters(v, gap=1e-3)] == \
        [(0.5, 0.5, 2), (2.0, 2.0005, 2), (3.0, 3.0, 1)]
    assert F.clusters([np.nan]) == []


def test_omega_tells_points_pieces_and_spread():
    rng = np.random.default_rng(0)
    cycle = np.tile([0.1, 0.4, 2.7, 3.0], 50) + rng.normal(0, 1e-9, 200)
    w = F.omega(cycle)
    assert w.kind == "points" and w.clusters == 4 and w.discrete
    two = np.r_[np.linspace(0.5, 0.6, 400), np.linspace(1.5, 1.55, 400)]
    assert F.omega(two).kind == "pieces" and F.omega(two).clusters == 2 and not F.omega(two).discrete
    spread = rng.uniform(0, math.pi, 500)
    assert F.omega(spread).kind == "spread" and F.omega(spread).coverage > 0.3
    assert F.omega([np.nan] * 5).kind == "none"


def test_accumulation_points_and_window_counts():
    phi = np.full((3, 2, 8), np.nan)
    phi[0] = [0.1, 0.4, 2.7, 3.0] * 2                   # 4 points
    phi[1, 0] = np.linspace(0.1, 3.0, 8)                # 8 points, one orbit broken
    phi[2] = np.linspace(0.1, 3.0, 16).reshape(2, 8)    # 16 points
    breaks = np.array([[0, 0], [0, 2], [2, 2]])
    d = synthetic(phi, breaks, r=[0.11, 0.12, 0.13])
    assert [F.accumulation_points(d, k) for k in range(3)] == [4, 8, None]
    assert F.window_counts(d, 0.105, 0.125) == {4: 1, 8: 1}
    assert F.dominant_count({None: 5, 4: 3, 6: 1}) == (4, 3, 9)
    assert F.dominant_count({None: 2}) == (None, 0, 2)
    assert list(d.break_r()) == [0.12, 0.13, 0.13]


def test_rotation_of_a_periodic_word():
    assert F.is_rotation("bcba" * 3 + "b", "abcb")
    assert not F.is_rotation("abab" * 3, "abcb")


def test_the_printed_thresholds_are_the_roots_of_q2():
    """The computed thresholds drawn in the figures are L4's printed radicals (typed here only)."""
    printed = {2: 3 - 2 * math.sqrt(2), 3: 5 - 2 * math.sqrt(6),
               4: 3 + 2 * math.sqrt(2) - 2 * math.sqrt(4 + 3 * math.sqrt(2)),
               5: 4 + math.sqrt(5) - 2 * math.sqrt(5 + 2 * math.sqrt(5)),
               6: 3 + 2 * math.sqrt(3) - 2 * math.sqrt(5 + 3 * math.sqrt(3))}
    for n, value in printed.items():
        assert abs(F.r_max(n) - value) < 1e-12


# --- the figures command ----------------------------------------------------------------

def test_figures_command_preview_only(tmp_path, capsys):
    assert main(["figures", "--only", "5.7", "--out", str(tmp_path), "--jobs", "1"]) == 0
    assert (tmp_path / "figures" / "fig5.7-preview.png").is_file()
    assert not (tmp_path / "figures" / "fig5.2-preview.png").exists()
    assert "figure 5.7" in capsys.readouterr().out


@pytest.mark.parametrize("argv", [["figures", "--only", "9.9"], ["figures", "--resolution", "huge"],
                                  ["figures", "--n4", "0"], ["figures", "--bogus"]])
def test_figures_command_bad_options_exit_2(tmp_path, argv):
    assert main(argv + ["--out", str(tmp_path)]) == 2


def test_prune_keeps_the_paper_figures(tmp_path):
    for name in ("fig5.2-paper.png", "fig5.2-preview.png", "old.png"):
        (tmp_path / name).write_bytes(b"png")
    assert figures.prune(tmp_path, keep={"fig5.2-preview.png"}) == ["old.png"]
    assert (tmp_path / "fig5.2-paper.png").is_file()


def test_section5_figure_draws_breaks(tmp_path):
    from certify.run import section5_figure
    phi = np.full((2, 2, 4), 1.0)
    d = synthetic(phi, breaks=np.array([[0, 2], [0, 0]]), r=[0.1, 0.2])
    with figures.output_dir(tmp_path):
        name = section5_figure(d)
    assert name == "fig5.2-preview.png" and (tmp_path / name).stat().st_size > 1000


# --- the certificates -------------------------------------------------------------------

def test_N2_the_breaks_of_the_paper_do_not_occur_and_a_window_moved_is_seen():
    """Our float64 engine (margin rule, rescaled normals) follows every orbit of Figure 5.1's
    range: the printed breaks near 0.072 are not observed (they occur just below 7 − 4√3),
    so N2 disagrees on that check alone; moving the printed edge of the windows from 0.17
    to 0.9 makes the windows check fail too."""
    outcome = run("N2")
    assert outcome.status == OBSERVED and outcome.note.startswith(runner.DISAGREES)
    failing = [c.statement for c in outcome.printed if not runner.holds(c)]
    assert len(failing) == 1 and failing[0].startswith("l. 1089: a short segment of breaks"), failing
    assert outcome.agrees is False and "no break in the figure's range" in outcome.reason
    assert "None" not in outcome.note and "{" not in outcome.note
    near = [c for c in outcome.printed if c.statement.startswith("l. 1090")]
    assert near and runner.holds(near[0])            # the breaks just below 0.072 are close to it
    moved = run("N2", breaks_near="0.09")
    assert not runner.holds([c for c in moved.printed if c.statement.startswith("l. 1090")][0])
    mutated = run("N2", windows_below="0.9")
    failing = [c.statement for c in mutated.printed if not runner.holds(c)]
    assert any(s.startswith("windows of stability for r ≤ 0.9") for s in failing), failing


def test_n4_reads_the_printed_n():
    """As printed (n ≥ 6) our float64 engine still follows the pattern; beyond the largest n
    that the committed search saw it follow, it does not, and the eigenvector's smallest
    component is below 2^-52 there."""
    printed = run("N4")
    assert printed.status == OBSERVED
    assert not runner.holds(printed.printed[0]) and not runner.holds(printed.printed[1])
    assert printed.agrees is False and "the printed cause does not hold" in printed.reason
    beyond = load_findings("numerics-n4.json")["largest_n_float64"] + 1
    later = run("N4", n_from=str(beyond))
    assert runner.holds(later.printed[0]) and runner.holds(later.printed[1])


def test_observe_fails_only_on_a_consistency_check():
    from certify.run import Check, observe
    assert observe([Check("seen", True)]).status == OBSERVED
    assert observe([Check("seen", False)]).note.startswith(runner.DISAGREES)
    assert observe([Check("seen", True), Check("engine", False, counts=False)]).status == runner.FAIL
    assert observe([]).status == runner.FAIL
