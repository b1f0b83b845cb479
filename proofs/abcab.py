"""Remark 3.3 (l. 513-515): the pattern abcab has no self-similar datum.

As printed: "for the initial data that are the obvious candidates - that is, the
eigenvector of the corresponding matrix BACBA for the velocities and a fixed point
for the distance map f for the positions - the collision after the first b
collision is a, not c (and these collisions do not take place at the same time, so
that the order really is a and then, after a strictly positive time, c)".

The candidate, with the paper's normalisation for a word that starts with a and
ends with b (l. 270-280): q(0) = (-1, u, v), an eigenvector of M_w = K_b K_a K_c K_b K_a
for a real eigenvalue λ (any real branch), and p(0) = (1, 0, x) with x a fixed point
x₊ or x₋ of f(x) = p_3(t_5)/p_1(t_5) = (ax + b)/(cx + d).  The collisions are
*assumed* (times defined by p_i(t_k) = 0, as in l. 460-463) and then checked:

* the candidate realises a, b as its first two collisions iff u = q_2(0) > 0
  (p_2(0) = 0 right after the last b), x > 0, q_2(t_1) < 0 and p_3(t_2) > 0
  (see :func:`prefix_requirements` for why the other gaps need no condition);
* the claim: q_1(t_2) < 0 (a comes next) and, at the time t_3 of that a,
  p_3(t_3) > 0, i.e. the a collision happens strictly before any c:
  p_3(t_3) = p_3(t_2) + τ_a q_3(t_2) = -q_3(t_2)(τ_c - τ_a) when q_3(t_2) < 0.

Each condition is a rational function of r, λ and x; its sign on each real
eigenvalue branch is certified over whole r-intervals (critical values from
resultants and the discriminant, one exact sample per cell, the branches isolated
by Sturm sequences, signs proven by balls).  :class:`Analysis` imposes the
conditions one at a time and keeps, per branch and fixed point, the exact set of r
where all hold (open intervals with algebraic ends, and points).  At a critical
value the signs are decided by balls, or, where a quantity vanishes or has a pole,
by the engine's exact zero test in Q(r_c)[λ]; where c = 0 the map f is affine and
its fixed point b/(d - a) is used.  The dynamics itself (``certify.dynamics.simulate``,
balls) is run from the candidate at one rational r per piece as a cross-check.

The candidate is built by :func:`certify.dynamics.candidate`, the regions by
:class:`certify.patterns.feasibility.Analysis` (shared with ``proofs/literature.py``).
"""
from __future__ import annotations

import sympy as sp

from certify.algebra import FIELD, Q, Algebraic, lam, show, simplest_between
from certify.dynamics import simulate as sim
from certify.dynamics import INDEX, candidate, collision_matrix, run_word
from certify.patterns import Analysis, BRANCH_NAMES, Requirement, analyse, fmt, prefix_requirements
from certify.run import PASS, Check, certificate, conclude, overridden


def matrix_of_name(name: str) -> sp.Matrix:
    """The product of collision matrices named left to right, e.g. "BACBA" = B·A·C·B·A."""
    out = sp.eye(3)
    for letter in name:
        out = out * collision_matrix(letter.lower())
    return out


# ---------------------------------------------------------------- T27
PRINTED_T27 = dict(word="abcab", matrix="BACBA", after="b", next="a", other="c")


@certificate("T27", "l. 513-515",
             "abcab (matrix BACBA) has no self-similar datum: for the candidate (eigenvector of BACBA, a fixed "
             "point of f), the collision after the first b is a, not c, at a strictly earlier time.",
             printed=PRINTED_T27,
             expect=PASS,
             mutants=[overridden({"matrix": "BACAB"}, "a letter of the matrix name"),
                      overridden({"matrix": "ABCAB"}, "a letter of the matrix name"),
                      overridden({"next": "c", "other": "a"}, "the claimed collision order reversed"),
                      overridden({"word": "acbab"}, "a different word: its matrix BABCA is not BACBA")])
def abcab_has_no_self_similar_datum(word, matrix, after, next, other):
    """On every real branch, for every r in ]0,1[ and both fixed points x±: wherever
    the candidate realises its first collisions up to the first b, the next
    collision is a (q_1 < 0 after b) and it comes strictly before c (p_3 > 0 at
    that a)."""
    cand = candidate(word)
    same = (matrix_of_name(matrix) - cand.M).applyfunc(sp.cancel) == sp.zeros(3, 3)
    checks = [Check(f"the matrix of the word {word} (collisions in time order) is {matrix}", same,
                    [f"M_w = `{show(cand.M.tolist())}`", f"cp(M_w) = `{show(sp.collect(cand.cp, lam))}`"])]
    m = word.index(after) + 1
    feas, steps = prefix_requirements(word, m, cand.q0, cand.steps, cand.q0_other)
    i, o = INDEX[next], INDEX[other]
    tail = run_word(word[:m] + next, cand.q0)[-1]
    claim = [Requirement(f"q_{i + 1}(t_{m})", (steps[-1].q[i], FIELD.zero), -1),
             Requirement(f"p_{o + 1}(t_{m + 1})", tail.p[o], 1)]
    an = Analysis(cand)
    for req in feas:
        an.impose(req)
    bad = [v for req in claim for v in an.violations(req)]
    undecided = [(R, u) for R in an.regions for u in R.undecided]
    feasible = [R for R in an.regions if R.pieces]
    a, b, c, d = cand.abcd
    ev = [f"q(0) = (-1, u, v), u = `{show(sp.factor(cand.q0[1].as_expr()))}`, "
          f"v = `{show(sp.factor(cand.q0[2].as_expr()))}`; p(0) = (1, 0, x)",
          f"f(x) = (ax + b)/(cx + d), a = `{show(sp.factor(a))}`, b = `{show(sp.factor(b))}`, "
          f"c = `{show(sp.factor(c))}`, d = `{show(sp.factor(d))}`; x± = (a - d ± √((a-d)² + 4bc))/(2c)",
          f"the candidate realises {', '.join(word[:m])} iff " + ", ".join(f"{q.name} {'>' if q.sign > 0 else '<'} 0"
                                                                        for q in feas),
          f"claim: {claim[0].name} < 0 ({next} approaches) and {claim[1].name} > 0 (at the time of that {next}, "
          f"the gap {other} is still open: τ_{next} < τ_{other})"]
    for R in an.regions:
        ev.append(f"{BRANCH_NAMES[R.branch]} branch, {R.fixed_point}: candidate realised on {R.describe()}"
                  + (f"; excluded exactly at {', '.join(f'{fmt(rc)} ({why})' for rc, why in R.dropped)}"
                     if R.dropped else ""))
    for key, T in an.tables.items():
        if key[0] in ("x", claim[0].name, claim[1].name):
            ev.append(f"sign of {key[0]} {key[1]} over ]{fmt(Algebraic.rational(T.interval[0]) if not isinstance(T.interval[0], Algebraic) else T.interval[0])}, "
                      f"{fmt(T.interval[1] if isinstance(T.interval[1], Algebraic) else Algebraic.rational(T.interval[1]))}[:\n\n{T.markdown()}")
    q_other = Requirement(f"q_{o + 1}(t_{m})", (steps[-1].q[o], FIELD.zero), -1)
    ev.append(f"{q_other.name} < 0 ({other} approaching after {after}) on the same region: "
              + ("yes" if not an.violations(q_other) else "no (where it is ≥ 0, c does not come next at all)"))
    dynamic = []
    for R in an.regions:
        for p in R.pieces:
            if p.is_point:
                continue
            p.lo.refine(Q(1, 10 ** 6)), p.hi.refine(Q(1, 10 ** 6))
            w = (p.hi.lo - p.lo.hi) / 8
            r0 = simplest_between(p.lo.hi + w, p.hi.lo - w)
            sigma = 1 if R.fixed_point == "x₊" else -1
            run, prec = sim.run_certified(lambda pr: cand.balls(r0, R.branch, sigma, pr), m + 1)
            dynamic.append((R, r0, run.word))
    want = word[:m] + next
    ev.append("the particle dynamics itself (certify.dynamics.simulate, every collision proven in balls) from the candidate "
              "at one rational r per piece: " + "; ".join(f"{BRANCH_NAMES[R.branch]} {R.fixed_point} r = {r0}: "
                                                          f"{w}" for R, r0, w in dynamic))
    checks += [
        Check(f"cross-check on the dynamics: from the candidate, the first {m + 1} collisions are {want}",
              all(w == want for _, _, w in dynamic) and bool(dynamic)),
        Check("every cell and critical value of ]0,1[ decided on every branch, for x₊ and x₋", not undecided,
              [f"undecided: {BRANCH_NAMES[R.branch]} {R.fixed_point} at {fmt(rc)} ({why})" for R, (rc, why) in undecided]),
        Check(f"wherever the candidate realises {', '.join(word[:m])}, the next collision is {next}, "
              f"strictly before {other}", not bad and not undecided,
              [f"fails on {BRANCH_NAMES[R.branch]} {R.fixed_point} {p}: {why}" for R, p, why in bad]),
        Check("and the candidate does realise them somewhere (the remark is not vacuous)", bool(feasible)),
    ]
    # the same conclusion from `certify pattern abcab` (the whole period, every branch, x±)
    res = analyse(word)
    dg = res.diagnosis or {}
    checks.append(Check(f"`certify pattern {word}`: no feasible datum; the first collision that goes wrong is "
                        f"collision {m + 1} ({other}), and {next} comes instead, strictly before, wherever the "
                        f"first {m} are realised",
                        not res.feasible and dg.get("collision") == m + 1 and dg.get("expected") == other
                        and [i["letter"] for i in dg.get("instead", [])] == [next] and dg.get("complete") is True
                        and not res.undecided,
                        [res.verdict, dg.get("text", "no diagnosis")]))
    where = "; ".join(f"{BRANCH_NAMES[R.branch]} branch with {R.fixed_point} on {R.describe()}" for R in feasible)
    return conclude(checks, evidence=ev,
                    note=f"The printed reason is checked wherever it applies: the candidate realises "
                         f"{', '.join(word[:m])} exactly on: {where or 'nowhere'}; elsewhere (other branches, "
                         f"other fixed point, other r) it fails earlier, so there is no self-similar datum either.")
