"""Theorem 3.1 (l. 276-285) checked on the dynamics of the four particles.

At a rational restitution coefficient of our choice (r = 1/20 < 5-2√6), the
self-similar datum of Theorem 3.1 is built from the printed formulas:

* λ a real root of cp(M_w) at r (M_w the matrix of the printed word), isolated
  exactly (Sturm) and enclosed in a ball;
* q(0) = (-1, u, v) with u, v as printed (l. 279-281);
* p(0) = (1, 0, x), x = x₊ = (a - d + √((a-d)² + 4bc))/(2c), a, b, c, d as printed
  (l. 291-300).

The particles are then moved by ``certify.dynamics.simulate`` in ball arithmetic: every
collision choice is proven (the smallest collision time strictly below the others),
the precision is raised when a choice cannot be proven.  We check that the orbit
repeats the word for the requested number of periods with q(t_6k) = λ^k q(0) and
p(t_6k) = μ^k p(0) (μ = p_1(t_6)), and that a perturbation of 10^-30 (an exact
rational added to x or to q) leaves the pattern after finitely many periods.
Ball enclosures cannot prove the identities q(t_6) = λ q(0) exactly (T9, T10 do so
algebraically); here they are checked as "the enclosures overlap and are tight"
(relative radius below 2^-TIGHT_BITS, decided exactly on the rational midpoints and
radii, not on floats), which a wrong formula fails by many orders of magnitude.
"""
from __future__ import annotations

from dataclasses import dataclass

import flint

from certify.algebra import (Q, Algebraic, Condition, GUARD, ball_value, from_flint, lam, parse, precision,
    show, tight, to_fmpq)
from certify.dynamics import simulate as sim
from certify.dynamics import candidate, check_word, fixed_point_ball
from certify.run import PASS, Check, certificate, conclude, overridden, replaced
from proofs.ababcb import A_PRINTED, B_PRINTED, C_PRINTED, D_PRINTED, U_PRINTED, V_PRINTED


PRINTED = dict(U=U_PRINTED, V=V_PRINTED, a=A_PRINTED, b=B_PRINTED, c=C_PRINTED, d=D_PRINTED, word="ababcb",
               r="1/20", periods=20, perturbation="1/10^30")
MAX_PERIODS = 200                      # how long a perturbed orbit is followed at most
TIGHT_BITS = 40                        # "tight": relative radius < 2^-40 (decided exactly)


# ---------------------------------------------------------------- exact formulas in balls
def ball_function(text: str):
    """A printed rational function of r, λ as a function of balls (R, L), exact
    rational coefficients (no float ever enters)."""
    cond = Condition.of(text, parse(text))
    return lambda R, L: ball_value(cond, R, L)


@dataclass
class Datum:
    """The self-similar datum on one branch, as a function of the precision."""

    branch: str
    lam: Algebraic
    r0: flint.fmpq
    formulas: dict

    def values(self, R, L) -> dict:
        """u, v, a, b, c, d and x₊ at balls R, L."""
        f = {k: g(R, L) for k, g in self.formulas.items()}
        f["x"] = fixed_point_ball(f["a"], f["b"], f["c"], f["d"])
        return f

    def balls(self, prec: int, dx=Q(0), dq=(Q(0), Q(0), Q(0))):
        """(p(0), q(0), r) as balls at ``prec`` bits, x and q shifted by exact rationals."""
        with precision(prec + GUARD):
            R = flint.arb(self.r0)
            f = self.values(R, self.lam.arb(prec + GUARD))
            p0 = (flint.arb(1), flint.arb(0), f["x"] + flint.arb(dx))
            q0 = (flint.arb(-1) + flint.arb(dq[0]), f["u"] + flint.arb(dq[1]), f["v"] + flint.arb(dq[2]))
            return p0, q0, R

    def mobius(self, prec: int):
        """(f'(x₊), q): the multiplier f'(x₊) = (ad - bc)/(cx₊ + d)² of the fixed point
        and the paper's q = (a + d + √Δ)/(a + d - √Δ) (l. 496-498), computed independently."""
        with precision(prec):
            f = self.values(flint.arb(self.r0), self.lam.arb(prec))
            a, b, c, d, x = f["a"], f["b"], f["c"], f["d"], f["x"]
            sq = ((a - d) ** 2 + 4 * b * c).sqrt()
            return (a * d - b * c) / (c * x + d) ** 2, (a + d + sq) / (a + d - sq)


def rel_radius(z) -> float:
    """rad/|mid| of a ball, a float for printing only: every decision uses :func:`tight`."""
    m = abs(float(z.mid()))
    return float(z.rad()) / m if m else float(z.rad())


# ---------------------------------------------------------------- the checks
def self_similar_run(datum: Datum, word: str, periods: int, prec: int = 512, maxprec: int = 1 << 13):
    """Follow the exact datum for ``periods`` periods; raise the precision until every
    collision is proven and the final enclosures are tight (relative radius < 2^-40,
    decided exactly)."""
    n = len(word) * periods
    while prec <= maxprec:
        run = sim.follow(*datum.balls(prec), n, prec)
        if run.stop in ("free", "multiple"):            # decided: the orbit stops colliding
            return run, prec
        if run.stop == "n":
            last = run.states[-1]
            if all(tight(z, TIGHT_BITS) for z in last.q + (last.p[0], last.p[2])):
                return run, prec
        prec *= 2
    raise sim.Undecided(f"self-similar run not decided at {maxprec} bits")


def scaling_checks(run: sim.Run, datum: Datum, word: str, periods: int, prec: int) -> tuple[bool, bool, list[str]]:
    """q(t_nk) ∋ λ^k q(0) and p(t_nk) ∋ μ^k p(0) (overlapping balls, each of relative radius
    < 2^-TIGHT_BITS, decided exactly), k = 1..periods."""
    n = len(word)
    if len(run.states) <= n * periods:
        return False, False, [f"the orbit stops after {len(run.events)} collisions ({run.stop})"]
    with precision(prec + 30):
        L = datum.lam.arb(prec + 30)
        s0 = run.states[0]
        mu = run.states[n].p[0]
        q_ok, p_ok, worst_q, worst_p = True, True, 0.0, 0.0
        for k in range(1, periods + 1):
            s = run.states[n * k]
            for i in range(3):
                pred_q = L ** k * s0.q[i]
                q_ok &= s.q[i].overlaps(pred_q) and tight(s.q[i], TIGHT_BITS)
                worst_q = max(worst_q, rel_radius(s.q[i]))
                pred_p = mu ** k * s0.p[i]
                p_ok &= (s.p[i].overlaps(pred_p) and tight(s.p[i], TIGHT_BITS)) if i != 1 else s.p[1].is_zero()
                if i != 1:
                    worst_p = max(worst_p, rel_radius(s.p[i]))
    ev = [f"μ = p_1(t_{n}) ∈ {mu.str(12, radius=False)} (λ ∈ {L.str(12, radius=False)})",
          f"largest relative radius of q(t_{n}k): {worst_q:.1e}, of p(t_{n}k): {worst_p:.1e} (k ≤ {periods})"]
    return q_ok, p_ok, ev


def perturbed_run(datum: Datum, word: str, dx, dq, periods: int = MAX_PERIODS, prec: int = 512,
                  maxprec: int = 1 << 14):
    """Follow a perturbed datum until its word leaves the periodic pattern (proven
    collision by collision), at most ``periods`` periods; (run, precision, index of
    the first collision off the pattern or None)."""
    n = len(word) * periods

    def off_pattern(run):
        k = len(run.events) - 1
        return run.events[-1] != word[k % len(word)]
    run, used = sim.run_certified(lambda p: datum.balls(p, dx, dq), n, prec, maxprec, until=off_pattern)
    if run.stop == "until":
        return run, used, len(run.events) - 1
    if run.stop in ("free", "multiple"):          # the next collision of the pattern never comes
        return run, used, len(run.events)
    return run, used, None


def branch_data(word: str, r0: flint.fmpq, formulas: dict) -> dict[str, Datum]:
    """The upper (largest) and lower (smallest) real eigenvalue of M_w at r0."""
    lams = candidate(check_word(word)).spectrum.real_eigenvalues(r0)
    return {"upper": Datum("upper", lams[0], r0, formulas), "lower": Datum("lower", lams[-1], r0, formulas)}


@certificate("T25.2", "l. 276-285",
             "Theorem 3.1 on the dynamics: from the printed self-similar datum (r = 1/20, chosen by us), the particles "
             "repeat ababcb with q(t_6k) = λ^k q(0), p(t_6k) = μ^k p(0); a perturbation of 10^-30 leaves the pattern "
             "(unstable) on the upper and on the lower branch.", printed=PRINTED,
             expect=PASS,
             mutants=[replaced("U", "16*λ", "17*λ", "a coefficient of u"),
                      replaced("V", "64*λ", "65*λ", "a coefficient of v"),
                      replaced("a", "1024*r^6", "1025*r^6", "a coefficient of a"),
                      overridden({"word": "abacbc"}, "another word (its matrix, its eigenvalues)"),
                      overridden({"word": "abcbab"}, "another word (its matrix, its eigenvalues)")])
def ababcb_on_the_dynamics(U, V, a, b, c, d, word, r, periods, perturbation):
    """Certified ball simulation of the printed datum and of perturbed data."""
    r0, eps = to_fmpq(parse(r)), to_fmpq(parse(perturbation))
    formulas = {k: ball_function(text) for k, text in (("u", U), ("v", V), ("a", a), ("b", b), ("c", c), ("d", d))}
    data = branch_data(word, r0, formulas)
    checks, evidence = [], [f"r = {r0} (our choice in ]0, 5-2√6[); perturbation ε = {perturbation}; "
                            f"collision choices proven in ball arithmetic (python-flint arb)"]
    for name, datum in data.items():
        run, prec = self_similar_run(datum, word, periods)
        ok_word = run.word == word * periods
        q_ok, p_ok, ev = scaling_checks(run, datum, word, periods, prec)
        p0, q0, _ = datum.balls(64)
        evidence.append(f"{name} branch: λ ≈ {datum.lam.digits(12)}, a root of {show(from_flint(datum.lam.p, lam))}; u ∈ {q0[1].str(10, radius=False)}, "
                        f"v ∈ {q0[2].str(10, radius=False)}, x₊ ∈ {p0[2].str(10, radius=False)}; "
                        f"{len(run.events)} collisions proven at {prec} bits: "
                        f"{'(' + word + ')^' + str(periods) if ok_word else run.word}; " + "; ".join(ev)
                        + "; multiplier f'(x₊) = (ad-bc)/(cx₊+d)² ∈ {0}, the paper's q (l. 496) ∈ {1} "
                          "(f'(x₊) = 1/q)".format(*(z.str(8, radius=False) for z in datum.mobius(256))))
        checks += [
            Check(f"{name} branch: the printed datum repeats {word} for {periods} periods (every collision proven)",
                  ok_word, [f"word: {run.word[:6 * periods]}"] if not ok_word else []),
            Check(f"{name} branch: q(t_{len(word)}k) = λ^k q(0), k = 1..{periods} (the enclosures overlap and have "
                  f"relative radius < 2^-{TIGHT_BITS}, decided exactly)", q_ok),
            Check(f"{name} branch: p(t_{len(word)}k) = μ^k p(0), k = 1..{periods} (the same)", p_ok),
        ]
    # instability: upper branch through the positions, lower branch through the velocities
    cases = [("upper", "x + ε", eps, (Q(0), Q(0), Q(0)), MAX_PERIODS),
             ("upper", "v + ε", Q(0), (Q(0), Q(0), eps), MAX_PERIODS),
             ("lower", "v + ε", Q(0), (Q(0), Q(0), eps), MAX_PERIODS),
             ("lower", "x + ε", eps, (Q(0), Q(0), Q(0)), 2 * periods)]
    for name, what, dx, dq, most in cases:
        run, prec, first = perturbed_run(data[name], word, dx, dq, most)
        n = len(word)
        if first is None:
            evidence.append(f"{name} branch, {what}: the pattern is kept for all {len(run.events) // n} periods "
                            f"followed ({prec} bits){_x_drift(run, n, dx, prec)}")
        elif first == len(run.events):
            why = ("no further collision: every q_i(t) > 0 is proven, the particles separate"
                   if run.stop == "free" else run.reason)
            evidence.append(f"{name} branch, {what}: leaves the pattern after collision {first} (period "
                            f"{first // n + 1}, {first // n} full periods; expected {word[first % n]}): {why} "
                            f"(proven at {prec} bits)")
        else:
            evidence.append(f"{name} branch, {what}: leaves the pattern at collision {first + 1} (period "
                            f"{first // n + 1}, {first // n} full periods): `{run.word[max(0, first - 11):first + 1]}` "
                            f"ends with {run.events[first]} instead of {word[first % n]} (proven at {prec} bits)")
        if (name, what) in (("upper", "x + ε"), ("lower", "v + ε")):
            checks.append(Check(f"{name} branch: the datum with {what} (ε = {perturbation}) leaves the pattern "
                                f"{word} after a bounded number of periods", first is not None))
    return conclude(checks, evidence=evidence,
                    note="Instability is shown the way the paper argues it: on the upper branch through the positions "
                         "(x perturbed), on the lower branch through the velocities (q perturbed); the other two "
                         "perturbations are reported as evidence.")


def _x_drift(run: sim.Run, n: int, dx, prec: int) -> str:
    """x_k - x₊, x_k = p_3/p_1 after k periods, for k = 1 and the last K (evidence)."""
    def xk(k):
        s = run.states[n * k]
        return s.p[2] / s.p[0]
    K = (len(run.states) - 1) // n
    if K < 2:
        return ""
    with precision(prec):
        x0 = run.states[0].p[2] - flint.arb(dx)
        d1, dK = xk(1) - x0, xk(K) - x0
    return f"; x_k - x₊ after 1 period ∈ {d1.str(3, radius=False)}, after {K} ∈ {dK.str(3, radius=False)}"
