"""Section 4: one step of the reduction map on a whole cone of states, in exact symbolic
arithmetic.  These are the lemmas, for every orbit and not on samples, behind Remark 4.2
(S11: infinitely many collisions off the corners; the particles realise a prefix),
Proposition 4.4 (S9.2: no aca, no cac) and Corollary 4.5 (S10), whose certificates are in
proofs/section4_1_reduction_theorem.py and proofs/section4_3_impossible_sequences.py.

A state of the projective map (``certify.dynamics.reduction``) is a contact i and a normal n of
the plane P, any non-zero real vector up to a positive factor, oriented by n_t > 0
(t = ORIENTATION[i], the paper's e_t · u ≥ 0, l. 949).  Its position is p = ±(n ∧ e_i),
its tangential velocity w = |n|² e_i − n_i n, and cos φ = n_i/|n| (l. 943-949).  The
plane meets the open face {p_i = 0, p_m > 0 (m ≠ i)} exactly when the third component
of n has one strict sign (:func:`cone`), so a state off the corners (n_i ≠ 0) lies in one
of six cones (contact, sign of n_i), on each of which every component of n has a strict
sign.  On a cone every claim is an identity in n1, n2, n3, r (both routes of
certify.algebra.trig) or a sign read from the factors under those signs and 0 < r < 1; the
collision matrices are the printed ones.

:func:`step` proves the step lemma on one cone: exactly one other gap j closes, at a
time t > 0; the new position lies in the open face j, the pair j separates, the new
plane's normal p' ∧ K_j w is a positive multiple of cof(K_j) n (the projective map) and
lies in a cone of the contact j, with n'_j = |n'| cos φ' of a sign that is either proven
or free (n'_j = 0: a corner).  :func:`physical` proves that the particles, whatever the
radial part of their velocity, collide next at j or never, and then span the same plane.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import sympy as sp

from certify.algebra import trig as T
from certify.algebra.poly import r
from certify.witnesses import captured, recording

from . import reduction as R
from .model import INDEX, LETTERS

N = sp.Matrix(sp.symbols("n1:4", real=True))          # a normal of P(k): any real vector
UNIT = [sp.eye(3).col(k) for k in range(3)]
TAU, U = sp.symbols("τ u", real=True)                   # a time > 0, and u = 1 + τλ (λ: the radial part)
SIGN = {1: "> 0", -1: "< 0", None: "of either sign"}


@dataclass
class Lemma:
    """One proven or refuted statement about a cone, with the evidence a referee can
    re-check (the proofs read it as a check: :func:`certify.run.check_of`)."""

    statement: str
    holds: bool
    evidence: list[str] = field(default_factory=list)
    witnesses: list[dict] = field(default_factory=list)    # the witnesses its verdict rests on (signs), as data


def name(k: int) -> str:
    return f"n_{k + 1}"


def combined(statement: str, build: Callable[[], list[T.Result]]) -> Lemma:
    """A lemma that holds when every part holds; the parts are computed by ``build``, and the
    witnesses they record are kept with the lemma (:func:`certify.witnesses.captured`)."""
    with captured() as got:
        parts = build()
    return Lemma(statement, all(parts), [e for p in parts for e in p.evidence], list(got))


def labelled(statement: str, build: Callable[[], list[tuple[str, T.Result]]]) -> Lemma:
    """A check made of named parts (computed by ``build``, their witnesses kept); each part's
    evidence under its name."""
    with captured() as got:
        parts = build()
    ev = []
    for what, res in parts:
        ev.append(f"{'✓' if res.holds else '✗'} {what}: " + (res.evidence[0] if res.evidence else ""))
        ev += res.evidence[1:]
    return Lemma(statement, all(res.holds for _, res in parts), ev, list(got))


def base(contact: str) -> T.Signs:
    """0 < r < 1 and the orientation n_t > 0 of the contact."""
    return T.Signs(atoms=((r, 1),)).assume(N[R.ORIENTATION[contact]], 1)


def third(contact: str) -> int:
    """The index m of n that is neither the contact i nor the orientation t."""
    return 3 - INDEX[contact] - R.ORIENTATION[contact]


@dataclass
class Cone:
    """The states of one contact: n_t > 0, n_m of sign ``sigma``; p = ``eps``·(n ∧ e_i)."""

    contact: str
    sigma: int | None
    eps: int | None
    check: Lemma

    def hypotheses(self, sign_i: int) -> T.Signs:
        H = base(self.contact).assume(N[third(self.contact)], self.sigma)
        return H.assume(N[INDEX[self.contact]], sign_i)


def cone(contact: str) -> Cone:
    """With n_t > 0, the sign of n_m for which p = ±(n ∧ e_i) has both free components of
    one strict sign (the plane meets the open face), proven for one sign and refuted for
    the other; with the witnesses of the lemma."""
    with captured() as got:
        C = _cone(contact)
    C.check.witnesses = list(got)
    return C


def _cone(contact: str) -> Cone:
    i, t, m = INDEX[contact], R.ORIENTATION[contact], third(contact)
    ne = N.cross(UNIT[i])
    # the free components of n ∧ e_i are ±n_m and ±n_t: n_t = 0 puts p on an edge's end (a
    # corner), so a state in the open face has n_t ≠ 0, made > 0 by the choice of n's sign
    free = T.equal(sp.Matrix([ne[t] ** 2, ne[m] ** 2, ne[i]]), sp.Matrix([N[m] ** 2, N[t] ** 2, 0]))
    found, ev = [], [f"n ∧ e_{i + 1} = `{T.show(ne)}`: its free components are ±{name(m)}, ±{name(t)} "
                     f"({'identity, both routes' if free.holds else 'FAILS'}), so {name(t)} ≠ 0 in the open face"]
    if not free.holds:
        return Cone(contact, None, None, Lemma(f"contact {contact}: the cone", False, ev))
    for sg in (1, -1):
        H = base(contact).assume(N[m], sg)
        a, b = T.sign(ne[t], H)[0], T.sign(ne[m], H)[0]
        ev.append(f"{name(t)} > 0, {name(m)} {SIGN[sg]}: the free components of n ∧ e_{i + 1} = "
                  f"`{T.show(ne)}` are {SIGN[a]} and {SIGN[b]}")
        if a is None or b is None:
            return Cone(contact, None, None, Lemma(f"contact {contact}: the cone", False, ev))
        if a == b:
            found.append((sg, a))
    ok = len(found) == 1
    sigma, eps = found[0] if ok else (None, None)
    return Cone(contact, sigma, eps, Lemma(
        f"contact {contact}: with {name(t)} > 0 the plane meets the open face {{p_{i + 1} = 0, other p_m > 0}} "
        f"exactly when {name(m)} {SIGN[sigma]}; then p = {'' if eps == 1 else '−'}(n ∧ e_{i + 1})", ok, ev))


@dataclass
class Step:
    """One step of the reduction on the cone (contact, sign of n_i); ``following`` is the
    next contact j when proven, ``normal`` the next normal u = p' ∧ K_j w (a positive
    multiple of cof(K_j) n), ``cos_next`` the proven sign of u_j (None: free)."""

    contact: str
    sign: int
    H: T.Signs
    checks: list[Lemma] = field(default_factory=list)
    following: str | None = None
    p: sp.Matrix | None = None
    w: sp.Matrix | None = None
    t: sp.Expr | None = None
    p1: sp.Matrix | None = None
    normal: sp.Matrix | None = None
    cos_next: int | None = None
    motion: Lemma | None = None          # :func:`physical`, once the step is proven

    @property
    def label(self) -> str:
        return f"contact {self.contact}, {name(INDEX[self.contact])} {SIGN[self.sign]}"

    @property
    def holds(self) -> bool:
        return self.following is not None and all(c.holds for c in self.checks)

    def excludes(self, z: str) -> T.Result:
        """z cannot come after the next contact j: n'_j n'_z < 0 (the collision after j is
        the gap m ≠ j with n'_j n'_m > 0, :func:`certify.dynamics.reduction.next_letter`)."""
        j = INDEX[self.following]
        if z == self.following:
            return T.Result(True, [f"{z} cannot follow itself: the next gap is another one"])
        return T.has_sign(self.normal[j] * self.normal[INDEX[z]], -1, self.H)


def step(contact: str, sign: int, K: dict) -> Step:
    """The step lemma on the cone (contact i, sign of n_i), K the printed collision matrices
    {letter: matrix}."""
    i, C = INDEX[contact], cone(contact)
    if C.sigma is None:
        return Step(contact, sign, base(contact), [C.check])
    H = C.hypotheses(sign)
    out = Step(contact, sign, H, [C.check])
    lab = out.label
    p = C.eps * N.cross(UNIT[i])
    w = N.dot(N) * UNIT[i] - N[i] * N
    others = [k for k in range(3) if k != i]
    out.checks += [
        combined(f"{lab}: the position p = `{T.show(p)}` lies in the open face: p_{i + 1} = 0, the others > 0",
                 lambda: [T.is_zero(p[i])] + [T.has_sign(p[k], 1, H) for k in others]),
        combined(f"{lab}: the tangent w = |n|² e_{i + 1} − n_{i + 1} n is ⊥ n and ⊥ p, and w_{i + 1} > 0 "
                 "(the pair in contact separates)",
                 lambda: [T.is_zero(w.dot(N)), T.is_zero(w.dot(p)), T.has_sign(w[i], 1, H)])]
    with captured() as got:
        signs = {k: T.sign(w[k], H) for k in others}
    closing = [k for k in others if signs[k][0] == -1]
    opening = [k for k in others if signs[k][0] == 1]
    one = len(closing) == 1 and len(opening) == 1
    out.checks.append(Lemma(f"{lab}: exactly one other gap closes (w_j < 0 < w_k)", one,
                            [f"w_{k + 1} = `{T.show(w[k])}`: " + "; ".join(signs[k][1]) for k in others], list(got)))
    if not one:
        return out
    j, k = closing[0], opening[0]
    t = p[j] / -w[j]
    p1 = (p + t * w).applyfunc(T.cancel)            # T.cancel: sp.cancel's expressions
    Kj = K[LETTERS[j]]
    q1 = Kj * w
    rho = T.cancel(p.cross(w).dot(N) / N.dot(N))
    u = p1.cross(q1).applyfunc(T.cancel)
    cof = Kj.adjugate().T
    Cj = cone(LETTERS[j])
    tj, mj = R.ORIENTATION[LETTERS[j]], third(LETTERS[j])
    out.checks += [
        combined(f"{lab}: gap {j + 1} ({LETTERS[j]}) closes at t = p_{j + 1}/(−w_{j + 1}) > 0, at p' = p + t w with "
                 f"p'_{j + 1} = 0 and p'_{i + 1}, p'_{k + 1} > 0: the open face {LETTERS[j]}",
                 lambda: [T.has_sign(t, 1, H), T.is_zero(p1[j]), T.has_sign(p1[i], 1, H), T.has_sign(p1[k], 1, H)]),
        combined(f"{lab}: after it the velocity is {LETTERS[j].upper()} w, whose component {j + 1} "
                 f"(−r w_{j + 1}) is > 0: the pair {LETTERS[j]} separates (sin φ' > 0)",
                 lambda: [T.has_sign(q1[j], 1, H)]),
        combined(f"{lab}: {LETTERS[j].upper()} p' = p' and p ∧ w = ρ n with ρ = `{T.show(rho)}` > 0, so the next "
                 f"plane has the normal p' ∧ {LETTERS[j].upper()} w = ρ cof({LETTERS[j].upper()}) n: "
                 "the projective map",
                 lambda: [T.equal(Kj * p1, p1), T.equal(p.cross(w), rho * N), T.has_sign(rho, 1, H),
                          T.equal(u, rho * cof * N)]),
        Cj.check,
        combined(f"{lab}: the next state lies in a cone of the contact {LETTERS[j]}: n' = p' ∧ {LETTERS[j].upper()} w "
                 f"has n'_{tj + 1} n'_{mj + 1} {SIGN[Cj.sigma]}",
                 lambda: [T.has_sign(u[tj] * u[mj], Cj.sigma, H)] if Cj.sigma is not None else [T.Result(False)])]
    out.following, out.p, out.w, out.t, out.p1, out.normal = LETTERS[j], p, w, t, p1, u
    with captured() as got:
        out.cos_next, why = T.sign(u[j], H)
    if out.cos_next is not None:      # a sign the step lemma states (cos φ' = n'_j/|n'|)
        out.checks.append(Lemma(f"{lab}: cos φ' = n'_{j + 1}/|n'| {SIGN[out.cos_next]}", True, why, list(got)))
    return out


def physical(s: Step, K: dict) -> Lemma:
    """The particles from a state of the cone, with the velocity q = α w + λ p (α > 0 since
    q_i = α w_i > 0 right after the collision i; λ, the radial part, of any sign): at the
    time τ > 0 the gaps are x = u p + s w, u = 1 + τλ, s = τα > 0.  Gap i never closes;
    while u ≥ 0 gap k stays open, and at u = 0 gap j is already closed: the next collision,
    if any, is j, at a time with u > 0, where x = u p'.  When the gap j closes at τ,
    α = t u/τ and λ = (u − 1)/τ: the velocity after it, K_j q, has component j > 0, and
    x ∧ K_j q is the positive multiple (u t/τ) of the reduction's next normal."""
    i, j = INDEX[s.contact], INDEX[s.following]
    k = 3 - i - j
    Kj, Lj = K[s.following], s.following.upper()
    S = sp.Symbol("s", real=True)                     # τα > 0
    x = U * s.p + S * s.w
    H0 = s.H.assume(S, 1)
    H = H0.assume(U, 1).assume(TAU, 1)
    alpha, lam = s.t * U / TAU, (U - 1) / TAU          # the gap j closes at τ
    q = alpha * s.w + lam * s.p
    after = Kj * q
    ratio = U * s.t / TAU
    def parts() -> list[tuple[str, T.Result]]:
        below = T.has_sign(x[j].subs(U, 0), -1, H0)
        spans = T.equal((U * s.p1).cross(after), ratio * s.normal)
        return [(f"x_{i + 1} = s w_{i + 1} > 0: the gap {s.contact} stays open", T.has_sign(x[i], 1, H0)),
                (f"x_{k + 1} > 0 while u > 0", T.has_sign(x[k], 1, H)),
                (f"at u = 0, x_{k + 1} = s w_{k + 1} > 0 and x_{j + 1} = s w_{j + 1} < 0: the gap {s.following} has "
                 "closed before", T.Result(T.has_sign(x[k].subs(U, 0), 1, H0).holds and below.holds, below.evidence)),
                (f"with α = t u/τ, λ = (u − 1)/τ the gap {s.following} closes at τ: p_{j + 1} + τ q_{j + 1} = 0",
                 T.equal((s.p + TAU * q)[j], 0)),
                ("there x = u p + τα w = u p'", T.equal(U * s.p + TAU * alpha * s.w, U * s.p1)),
                (f"({Lj} q)_{j + 1} > 0: the pair {s.following} separates", T.has_sign(after[j], 1, H)),
                (f"x ∧ {Lj} q = (u t/τ) n' with u t/τ > 0: the reduction's next plane, same orientation",
                 T.Result(T.has_sign(ratio, 1, H).holds and spans.holds, spans.evidence))]
    return labelled(f"{s.label}: the particles (velocity q = α w + λ p, α > 0, any radial part λ; gaps x = u p + s w "
                    f"at the time τ, u = 1 + τλ, s = τα) collide next at {s.following} or never, and then span the "
                    "reduction's next plane", parts)


def steps(K: dict) -> dict[tuple[str, int], Step]:
    """The step lemma on the six cones, each with the particles' motion (:func:`physical`);
    each lemma keeps the witnesses of its signs (recorded here apart from any certificate's:
    a certificate that reads a lemma records them again, :func:`witnesses`)."""
    with recording("cones"):
        out = {(c, s): step(c, s, K) for c in LETTERS for s in (1, -1)}
        for st in out.values():
            st.motion = physical(st, K) if st.holds else Lemma(f"{st.label}: the step lemma fails", False)
    return out


def witnesses(cones, motion: bool = False) -> list[dict]:
    """The witnesses of the step lemmas on ``cones`` (Steps), and of the particle lemmas with ``motion``."""
    out = [ob for st in cones for c in st.checks for ob in c.witnesses]
    return out + ([ob for st in cones if st.motion for ob in st.motion.witnesses] if motion else [])


def map_is_proven(cones: dict) -> bool:
    """Every step lemma holds: the map is defined on every state off the corners."""
    return all(st.holds for st in cones.values())


def dynamics_is_proven(cones: dict) -> bool:
    """Every step lemma and every particle lemma holds: the particles follow the map."""
    return map_is_proven(cones) and all(st.motion.holds for st in cones.values())


def transitions(cones: dict[tuple[str, int], Step]) -> dict[tuple[str, str], set[str]]:
    """What the proofs allow: for each proven step x → y, the letters that may come after y
    (those the sign of n'_y n'_z does not exclude)."""
    out = {}
    for s in cones.values():
        if s.holds:
            out.setdefault((s.contact, s.following), set()).update(
                z for z in LETTERS if z != s.following and not s.excludes(z).holds)
    return out


def admissible(n: int, allowed: dict[tuple[str, str], set[str]]) -> list[str]:
    """Every word of length n whose consecutive pairs are proven steps and whose triples
    are allowed: every window of length n of every orbit's word is one of them."""
    words = [L for L in LETTERS]
    pairs = {x + y for x, y in allowed}
    for _ in range(n - 1):
        words = [w + z for w in words for z in LETTERS
                 if (len(w) < 1 or w[-1] + z in pairs) and (len(w) < 2 or z in allowed.get((w[-2], w[-1]), set()))]
    return words


def representative(s: Step) -> tuple[int, int, int]:
    """An integer normal in the cone of ``s`` (components ±1, ±1, ±1 with its signs)."""
    n = [0, 0, 0]
    for atom, sg in s.H.atoms:
        if atom in N:
            n[list(N).index(atom)] = sg
    return tuple(n)
