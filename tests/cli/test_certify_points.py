"""``certify figures --certify-points EVERY``: the certified fraction printed and in the caption."""
from certify import cli
from certify.numerics import figures


def test_figures_certify_points_prints_the_fraction(tmp_path, capsys):
    figures.forget()
    assert cli.main(["figures", "--only", "5.7", "--certify-points", "10", "--out", str(tmp_path),
                     "--jobs", "1"]) == 0
    out = capsys.readouterr().out
    assert "certified points: " in out and "on 3 values of r (every 10)" in out
    assert (tmp_path / "figures" / "fig5.7-preview.png").is_file()


def test_certify_points_needs_a_positive_integer(tmp_path, capsys):
    assert cli.main(["figures", "--only", "5.7", "--certify-points", "0", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "certify-points" in err and len(err.strip().splitlines()) == 1, err
