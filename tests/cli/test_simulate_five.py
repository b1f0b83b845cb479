"""``certify simulate --particles 5``: the npz it writes, its one-line refusals, and four
particles unchanged by the new options."""
import numpy as np
import pytest

from certify import cli
from certify.numerics import five_reduction as five


def run(capsys, *argv):
    code = cli.main(list(argv))
    return code, capsys.readouterr()


def test_five_particles_npz_holds_the_engine_run(tmp_path, capsys):
    """The file holds what five.iterate gives for the same data (seeded), words included."""
    out = tmp_path / "five.npz"
    code, printed = run(capsys, "simulate", "--particles", "5", "--r", "0.26", "1/5", "--orbits", "3",
                        "--seed", "7", "--collisions", "500", "--words", "--out", str(out))
    assert code == 0 and "five particles" in printed.out and "certified:" in printed.out
    p0, q0 = five.random_data(3, 7)
    again = five.iterate([0.26, 0.2], p0, q0, collisions=500, words=True)
    with np.load(out) as data:
        assert set(data.files) == set(five.KEYS) | {"word"}
        assert (data["word"] == again.word).all() and (data["certified"] == again.certified).all()
        assert np.array_equal(data["omega"], again.omega) and data["angles"].shape == (2, 3, 4)


@pytest.mark.parametrize("extra, message", [
    (["--theta0", "1", "--phi0", "1"], "--theta0 is for four particles"),
    (["--engine", "mp"], "float64 engine only"),
    (["--keep", "10"], "--keep is for four particles"),
    (["--jobs", "1"], "--jobs is for four particles"),
    (["--words"], "give --out"),
])
def test_five_particles_refusals_are_one_line(capsys, extra, message):
    code, printed = run(capsys, "simulate", "--particles", "5", "--r", "0.3", *extra)
    assert code == 2 and message in printed.err and len(printed.err.strip().splitlines()) == 1


def test_four_particles_refuse_a_seed_and_are_unchanged(tmp_path, capsys):
    """--seed is for five particles; --particles 4 is the default run, byte for byte."""
    code, printed = run(capsys, "simulate", "--r", "0.3", "--seed", "1")
    assert code == 2 and "--seed" in printed.err
    a, b = tmp_path / "a.npz", tmp_path / "b.npz"
    run(capsys, "simulate", "--r", "0.3", "--orbits", "2", "--collisions", "300", "--out", str(a))
    code, printed = run(capsys, "simulate", "--particles", "4", "--r", "0.3", "--orbits", "2", "--collisions", "300",
                        "--out", str(b))
    assert code == 0
    with np.load(a) as x, np.load(b) as y:
        assert x.files == y.files and all(np.array_equal(x[k], y[k], equal_nan=True) for k in x.files)


def test_the_example_of_the_docs_is_the_command(tmp_path, capsys):
    """docs/particles.md's example of ``simulate --particles 5`` is what the command prints."""
    from pathlib import Path
    text = (Path(__file__).resolve().parents[2] / "docs" / "particles.md").read_text(encoding="utf-8")
    block = text.split("$ python -m certify simulate --particles 5 ", 1)[1].split("```", 1)[0]
    argv, printed = block.split("\n", 1)
    argv = argv.split()
    argv[argv.index("--out") + 1] = str(tmp_path / "five.npz")
    code, out = run(capsys, "simulate", "--particles", "5", *argv)
    assert code == 0 and out.out.replace(str(tmp_path / "five.npz"), "five.npz") == printed
