"""Section 4.2 (l. 877-987): the final expressions of the spherical reduction.

4.2.1 the trigonometric version (l. 881-929): S7.1 the six printed cases, as identities;
      S7.2 the printed cases are the projective map's step, and agree with the dynamics;
4.2.2 the vectorial version (l. 931-987): S8.1 the printed vectors and the trilinear
      formula, as identities; S8.2 the trilinear formula is the map, on every cone.

The printed texts are read as in proofs/section4_1_reduction_theorem.py (its helpers
and shared quantities are used here: the data, the cones of states).
"""
from __future__ import annotations

import sympy as sp

from certify.algebra import lam, r, statements
from certify.algebra import trig as T
from certify.dynamics import INDEX, LETTERS
from certify.dynamics import cones as RC
from certify.dynamics import reduction as R
from certify.run import (
    ERRATUM,
    MISPRINT,
    PASS,
    Check,
    captured,
    certificate,
    combined,
    conclude,
    concluded,
    identity,
    kept_witnesses,
    named,
    overridden,
    replaced,
    result_check,
    witnesses_of,
)
from proofs.section4_1_reduction_theorem import (
    PAIR,
    SECTION2,
    UNIT,
    cone_witnesses,
    cθ,
    cφ,
    hit_point,
    supporting,
    sφ,
    vec,
)

# ================================================================ as printed (l. 877-987)
# One misprint, false in S8.1 (the formula) and S8.2 (the reduction it gives): counted once.
E_Y_FOR_E_Z = "l. 980: e_y printed for e_z in the trilinear formula for ũ(1) after a contact a and a collision c"


# ---------------------------------------------------------------- as printed: the trigonometric version (l. 888-926)
CONTACT_P0 = {"a": "(0, cos(θ), sin(θ))", "b": "(sin(θ), 0, cos(θ))", "c": "(cos(θ), sin(θ), 0)"}


CONTACT_Q0 = {"a": "(sin(φ), -sin(θ)*cos(φ), cos(θ)*cos(φ))", "b": "(cos(θ)*cos(φ), sin(φ), -sin(θ)*cos(φ))",
              "c": "(-sin(θ)*cos(φ), cos(θ)*cos(φ), sin(φ))"}


# contact, sign of cos φ: "next pair | matrix | p(t1) before normalisation | radicand"
SIX_CASES = {
    "a, φ ∈ ]0,π/2[": "2-3 | B | (cos(θ)*sin(φ), 0, cos(φ)) | cos(θ)^2*sin(φ)^2 + cos(φ)^2",      # l. 891-893
    "a, φ ∈ ]π/2,π[": "3-4 | C | (sin(θ)*sin(φ), -cos(φ), 0) | sin(θ)^2*sin(φ)^2 + cos(φ)^2",     # l. 896-898
    "b, φ ∈ ]0,π/2[": "3-4 | C | (cos(φ), cos(θ)*sin(φ), 0) | cos(φ)^2 + cos(θ)^2*sin(φ)^2",      # l. 905-907
    "b, φ ∈ ]π/2,π[": "1-2 | A | (0, sin(θ)*sin(φ), -cos(φ)) | sin(θ)^2*sin(φ)^2 + cos(φ)^2",     # l. 910-912
    "c, φ ∈ ]0,π/2[": "1-2 | A | (0, cos(φ), cos(θ)*sin(φ)) | cos(φ)^2 + cos(θ)^2*sin(φ)^2",      # l. 919-921
    "c, φ ∈ ]π/2,π[": "2-3 | B | (-cos(φ), 0, sin(θ)*sin(φ)) | cos(φ)^2 + sin(θ)^2*sin(φ)^2",     # l. 924-926
}


Q_T1 = "K*q0 - dot(K*q0, p)*p"      # l. 893, 898, ...: the numerator of q(t1), p = p(t1) normalised


# ---------------------------------------------------------------- as printed: the vectorial version (l. 937-982)
U0 = "(cos(φ), sin(θ)*sin(φ), -cos(θ)*sin(φ))"                                  # l. 947


EY_DOT_U0 = "sin(θ)*sin(φ)"                                                     # l. 949


ORIENTATION = "a: y, b: z, c: x"           # l. 949: t = y, z, x for contacts k = 1, 2, 3


U0_WEDGE = {"ey": "(cos(θ)*sin(φ), 0, cos(φ))",                                 # l. 958
            "ez": "(sin(θ)*sin(φ), -cos(φ), 0)",                                # l. 962
            "ex": "(0, -cos(θ)*sin(φ), -sin(θ)*sin(φ))",                        # l. 967
            "p0": "(sin(φ), -sin(θ)*cos(φ), cos(θ)*cos(φ))"}                    # l. 971


TRILINEAR_B = "cross(cross(u0, ey), B*cross(u0, cross(ex, u0)))"                # l. 976


TRILINEAR_C = "cross(cross(u0, ey), C*cross(u0, cross(ex, u0)))"                # l. 980


TRILINEAR_C_CORRECTION = ("(u0, ey)", "(u0, ez)")     # stated: for a collision c, p(1) ∝ u(0) ∧ e_z (l. 962)


TRILINEAR_C_CORRECTED = statements.corrected(TRILINEAR_C, *TRILINEAR_C_CORRECTION)


# ================================================================ 4.2.1 Spherical reduction, trigonometric version (l. 881-929): S7.1, S7.2
# ================================================================ S7.1
CASE_KEYS = {"a_pos": ("a", 1), "a_neg": ("a", -1), "b_pos": ("b", 1), "b_neg": ("b", -1),
             "c_pos": ("c", 1), "c_neg": ("c", -1)}


RANGE = {1: "φ ∈ ]0,π/2[", -1: "φ ∈ ]π/2,π[", None: "φ ∈ ]0,π["}


def contact_frame(contact: str, p0, q0) -> Check:
    """p(0), q(0) unit and orthogonal, q_i(0) = sin φ > 0 for the gap i in contact."""
    i = INDEX[contact]
    res = T.equal(sp.Matrix([p0.dot(p0), q0.dot(q0), p0.dot(q0), q0[i], p0[i]]), sp.Matrix([1, 1, 0, sφ, 0]))
    return result_check(f"contact {contact}: |p(0)| = |q(0)| = 1, p(0)·q(0) = 0, p_{i + 1}(0) = 0, "
                        f"q_{i + 1}(0) = sin φ > 0", res)


def next_gap(contact: str, p0, q0, H: T.Signs) -> tuple[int | None, list[str], list[dict]]:
    """The one other gap k that closes on the ray p(0) + t q(0) (p_k(0) > 0, q_k(0) < 0)
    while the third one opens (q_l(0) > 0), all signs read from the factors under H; the
    evidence, and the witnesses of those signs, for :func:`certify.run.kept_witnesses`."""
    others = [j for j in range(3) if j != INDEX[contact]]
    with captured() as got:
        sp_ = {j: T.sign(p0[j], H)[0] for j in others}
        sq = {j: T.sign(q0[j], H)[0] for j in others}
    ev = [f"gap {j + 1}: p = `{T.show(p0[j])}` {'> 0' if sp_[j] == 1 else '?'}, "
          f"q = `{T.show(q0[j])}` {'> 0' if sq[j] == 1 else '< 0' if sq[j] == -1 else '?'}" for j in others]
    closing = [j for j in others if sq[j] == -1 and sp_[j] == 1]
    ok = len(closing) == 1 and all(sq[j] == 1 for j in others if j not in closing)
    return (closing[0] if ok else None), ev, list(got)


def six_case(key: str, spec: str, p0, q0, q_t1: str) -> list[Check]:
    """One printed case of l. 886-929: the next collision, p(t1), its norm, q(t1)."""
    contact, cos_phi = CASE_KEYS[key]
    H, label = T.hypotheses(cos_phi), f"contact {contact}, {RANGE[cos_phi]}"
    pair, letter, V_text, R_text = (x.strip() for x in spec.split("|"))
    k, ev, signs = next_gap(contact, p0, q0, H)
    first = Check(f"{label}: the next collision is the printed {pair} with matrix {letter}: the only gap the ray "
                  "p(0) + t q(0) closes", k is not None and PAIR.get(pair) == LETTERS[k] and letter == LETTERS[k].upper(),
                  ev, witnesses=kept_witnesses(signs))
    if k is None:
        return [first]
    V, R = vec(V_text), T.parse(R_text)
    hit = hit_point(p0, q0, k)
    inside = [T.has_sign(V[j], 1, H) for j in range(3) if j != k]
    w = T.parse(q_t1, K=SECTION2[letter], q0=q0, p=V / sp.sqrt(R)).applyfunc(sp.expand)
    if w.has(sp.sqrt):
        raise ValueError("the normalisation of p(t1) did not cancel")
    return [first,
            combined(f"{label}: the printed p(t1) ∝ `{V_text}` is a positive multiple of the point p(0) + t q(0) "
                     f"where gap {k + 1} closes", [T.positively_proportional(hit, V, H), T.has_sign(V.dot(hit), 1, H)]),
            combined(f"{label}: p(t1) lies on p_{k + 1} = 0 with its two other components > 0 (θ' ∈ ]0,π/2[)",
                     [T.is_zero(V[k])] + inside),
            combined(f"{label}: the printed radicand `{R_text}` is |p(t1)|², and it is > 0",
                     [T.equal(R, V.dot(V)), T.has_sign(R, 1, H)]),
            combined(f"{label}: q(t1) = {letter}q(0) - ({letter}q(0)·p(t1))p(t1), normalised, is orthogonal to p(t1) "
                     f"and its component {k + 1} is > 0 (φ' ∈ ]0,π[)", [T.is_zero(w.dot(V)), T.has_sign(w[k], 1, H)])]


@certificate("S7.1", printed=dict(p0_a=CONTACT_P0["a"], q0_a=CONTACT_Q0["a"], p0_b=CONTACT_P0["b"], q0_b=CONTACT_Q0["b"],
                          p0_c=CONTACT_P0["c"], q0_c=CONTACT_Q0["c"], q_t1=Q_T1,
                          **{key: SIX_CASES[f"{c}, {RANGE[s]}"] for key, (c, s) in CASE_KEYS.items()}),
             expect=PASS,
             mutants=[replaced("c_neg", "(-cos(φ), 0", "(cos(φ), 0", "a sign of p(t1)"),
                      replaced("a_pos", "2-3 | B", "3-4 | C", "another pair and matrix for a, cos φ > 0"),
                      replaced("b_neg", "sin(θ)^2*sin(φ)^2", "sin(θ)^2*sin(φ)", "an exponent of the radicand")])
def trigonometric_version(p0_a, q0_a, p0_b, q0_b, p0_c, q0_c, q_t1, **cases):
    """Signs from the factors under θ ∈ ]0,π/2[, sin φ > 0, 0 < r < 1 and the sign of cos φ."""
    frames = {"a": (vec(p0_a), vec(q0_a)), "b": (vec(p0_b), vec(q0_b)), "c": (vec(p0_c), vec(q0_c))}
    checks = [named(f"S7.1.{k + 1}", contact_frame(c, *frames[c])) for k, c in enumerate(LETTERS)]
    for n, key in enumerate(CASE_KEYS):       # five statements per case, S7.1.4-8 for the first
        checks += [named(f"S7.1.{4 + 5 * n + m}", c)
                   for m, c in enumerate(six_case(key, cases[key], *frames[CASE_KEYS[key][0]], q_t1))]
    return conclude(checks, note="The normalisation of q(t1) divides by a positive norm and changes no sign; it is "
                    "not expanded.  p(t1) is checked up to its normalisation, which is the printed square root.")


# ---------------------------------------------------------------- S7.2
# The six printed cases (l. 881-929), transcribed once above (S7.1).
PRINTED_S7 = {**{f"p0_{c}": CONTACT_P0[c] for c in LETTERS}, **{f"q0_{c}": CONTACT_Q0[c] for c in LETTERS},
              **{key: SIX_CASES[f"{c}, {RANGE[s]}"] for key, (c, s) in CASE_KEYS.items()}}


def engine_is_printed(printed: dict) -> list[Check]:
    """The engine's six cases (certify.dynamics.reduction.P0, Q0, CASES) are the printed ones:
    the same p(0), q(0), next pair and p(t1), as polynomials in cos, sin of θ, φ."""
    args = (T.cθ, T.sθ, T.cφ, T.sφ)
    checks = []

    def same(text, engine) -> bool:
        return (T.vector(text) - sp.Matrix(engine)).applyfunc(sp.expand) == sp.zeros(3, 1)
    for c in LETTERS:
        ok = same(printed[f"p0_{c}"], R.P0[c](*args[:2])) and same(printed[f"q0_{c}"], R.Q0[c](*args))
        for key, (c2, s) in CASE_KEYS.items():
            if c2 != c:
                continue
            pair, _K, vec, _radicand = (x.strip() for x in printed[key].split("|"))
            j, p1 = R.CASES[(c, s)]
            ok = same(vec, p1(*args)) and ok and PAIR.get(pair) == j
        checks.append(Check(f"contact {c}: the map steps with the printed p(0), q(0), next pair and p(t1)", ok,
                            [f"`{printed[k]}`" for k in (f"p0_{c}", f"q0_{c}", f"{c}_pos", f"{c}_neg")]))
    return checks


def case_is_the_map(key: str, spec: str, p0, q0) -> Check:
    """One printed case (contact i, sign of cos φ) for every θ ∈ ]0,π/2[ and φ in its range:
    the printed step of S7.1 (next pair = the gap the ray closes, p(t1) its hit point in
    the open face, q(t1) ⊥ p(t1) with q_j(t1) > 0), and it is the projective map's step:
    with u = p(0) ∧ q(0), u_i u_j > 0 (the map's rule for the next contact j) and
    p(t1) ∧ K q(0), the normal of Span(p(t1), q(t1)), is a positive multiple of cof(K) u.
    The same contact and plane give the same θ', φ' (p(t1) is the position in the open
    face, q(t1) the unit tangent with q_j > 0)."""
    contact, s = CASE_KEYS[key]
    label = f"contact {contact}, {RANGE[s]}"
    steps = six_case(key, spec, p0, q0, Q_T1)
    pair, letter, V_text, _radicand = (x.strip() for x in spec.split("|"))
    j = PAIR.get(pair)
    if j is None or letter not in SECTION2 or not all(c.holds for c in steps):
        return Check(f"{label}: the printed step (as in S7.1)", False,
                     [f"{'✓' if c.holds else '✗'} {c.statement}" for c in steps])
    H, K, i = T.hypotheses(s), SECTION2[letter], INDEX[contact]
    u0 = p0.cross(q0)
    rule = T.has_sign(u0[i] * u0[INDEX[j]], 1, H)
    normal, image = vec(V_text).cross(K * q0), K.adjugate().T * u0
    plane = T.positively_proportional(normal, image, H)
    t = R.ORIENTATION[j]                                     # the positive multiple, as the formal statement reads it:
    sides = [T.has_sign(normal[t], 1, H), T.has_sign(image[t], 1, H)]     # parallel, with e_t components > 0
    return Check(f"{label}: the printed step (S7.1) is the projective map's step for every θ, φ in the case: the "
                 f"next contact {j} (u_{i + 1} u_{INDEX[j] + 1} > 0, u = p(0) ∧ q(0)) and the plane, p(t1) ∧ "
                 f"{letter}q(0) being a positive multiple of cof({letter}) u", rule.holds and plane.holds and all(sides),
                 [f"✓ {c.statement}" for c in steps] + [f"u = `{T.show(u0)}`"] + rule.evidence + plane.evidence,
                 witnesses=witnesses_of(rule, plane, *sides))


def case_for_every_radial_part(key: str, spec: str, p0, q0) -> Check:
    """One printed case for every radial part λ of the velocity (q_λ = q(0) + λ p(0)): the gap j
    closes at t_j = 1/(λ_j - λ), λ_j = -q_j(0)/p_j(0); the printed gap k and the other one m have
    λ_m < λ_k, and where both close (λ = λ_m - ν, ν > 0) t_k > 0 and t_m > t_k: the particles
    collide next at k or never; after it they span K·P(0), p_λ(t_k) ∧ K q_λ ∥ cof(K) u."""
    contact, s = CASE_KEYS[key]
    pair, letter, _V, _R = (x.strip() for x in spec.split("|"))
    j = PAIR.get(pair)
    if j is None or letter not in SECTION2:
        return Check(f"contact {contact}, {RANGE[s]}: the printed pair {pair} and matrix {letter}", False)
    H, K, k = T.hypotheses(s), SECTION2[letter], INDEX[j]
    m = 3 - INDEX[contact] - k
    nu = sp.Symbol("ν")
    q = q0 + lam * p0
    t_, l_ = {g: -p0[g] / q[g] for g in (k, m)}, {g: -q0[g] / p0[g] for g in (k, m)}
    at = {lam: l_[m] - nu}
    parts = [T.equal(1 / t_[k], l_[k] - lam), T.equal(1 / t_[m], l_[m] - lam),
             T.parallel((p0 + t_[k] * q).cross(K * q), K.adjugate().T * p0.cross(q0)),
             T.has_sign(l_[k] - l_[m], 1, H), T.has_sign(t_[k].subs(at), 1, H.assume(nu, 1)),
             T.has_sign((t_[m] - t_[k]).subs(at), 1, H.assume(nu, 1))]
    return combined(f"contact {contact}, {RANGE[s]}, any radial part λ of the velocity: the gaps {k + 1}, {m + 1} close "
                    f"at t = 1/(λ_j - λ), λ_{m + 1} < λ_{k + 1}, and where both close t_{k + 1} < t_{m + 1}: the particles "
                    f"collide next at the printed {pair}, or never, and then span {letter}·P(0)", parts)


@certificate("S7.2", needs=["section4_data", "reduction_cones"], printed=PRINTED_S7,
             expect=PASS,
             mutants=[replaced("a_pos", "2-3", "3-4", "another pair for a, cos φ > 0"),
                      replaced("c_neg", "sin(θ)*sin(φ)", "cos(θ)*sin(φ)", "a factor of the c, cos φ < 0 case"),
                      replaced("q0_b", "-sin(θ)*cos(φ)", "sin(θ)*cos(φ)", "a sign of q(0) for contact b")])
def trigonometric_map_agrees_with_dynamics(section4_data, reduction_cones, **printed):
    """For every collision: each printed case is, for every θ, φ in its range, the step of
    the projective map (:func:`case_is_the_map`), and the particles follow the projective
    map (the step and particle lemmas on the six cones, certify.dynamics.cones).  The
    engine's trigonometric map is the printed one.  Supporting evidence: at each collision
    of the exact runs, one step of the six cases from θ, φ of the exact state as certified
    balls (128 bits) against θ, φ of the exact state k+1."""
    checks = engine_is_printed(printed)
    frames = {c: (T.vector(printed[f"p0_{c}"]), T.vector(printed[f"q0_{c}"])) for c in LETTERS}
    checks += [named(f"S7.2.{n + 1}", case_is_the_map(key, printed[key], *frames[c]))
               for n, (key, (c, _s)) in enumerate(CASE_KEYS.items())]
    checks += [named(f"S7.2.{n + 7}", case_for_every_radial_part(key, printed[key], *frames[c]))
               for n, (key, (c, _s)) in enumerate(CASE_KEYS.items())]
    checks.append(Check("the particles follow the projective map: on each of the six cones of states they collide "
                        "next at its contact, or never, and then span its plane (step and particle lemmas, S11)",
                        RC.dynamics_is_proven(reduction_cones), witnesses=cone_witnesses(reduction_cones.values(), True)))
    compared = agree = undecided = 0
    if all(c.holds for c in checks[:3]):
        for d in section4_data:
            steps = R.trig_agreement(d.planes[0], d.r)      # (agree, undecided) along the run
            compared += len(d.planes[0]) - 1
            agree, undecided = agree + steps[0], undecided + steps[1]
    evidence = [supporting(f"at {compared} collisions of {len(section4_data)} exact runs the six cases give the next "
                           f"contact and (θ, φ) (balls overlapping): {agree} agree, {undecided} undecided.")]
    return conclude(checks, evidence=evidence)


# ================================================================ 4.2.2 Spherical reduction mapping, vectorial version (l. 931-987): S8.1, S8.2
# ================================================================ S8.1
def orientation_axes(text: str) -> dict:
    """'a: y, b: z, c: x' as {contact: e_t}."""
    pairs = dict(item.split(":") for item in text.replace(" ", "").split(","))
    return {c: UNIT[f"e{pairs[c]}"] for c in pairs}


def not_normal(u, p, H: T.Signs, tφ: str) -> list[str]:
    """Evidence that u is not normal to p: u·p ≢ 0, with its value at a rational point of H."""
    d = u.dot(p)
    pt = T.point("1/2", tφ, r="1/3")
    return T.is_zero(d).evidence + [f"at cos θ = {pt[cθ]}, cos φ = {pt[cφ]}, r = 1/3: ũ(1)·p(1) = {T.at(d, pt)}"
                                    f" (hypotheses hold there: {'yes' if T.satisfied(H, pt) else 'no'})"]


def trilinear(text: str, letter: str, u0, p1, q0, H: T.Signs, axis, tφ: str) -> Check:
    """The printed ũ(1) is a positive multiple of p(1) ∧ K q(0) (the normal of P(1) oriented
    as p ∧ q), and that normal has e_t·u > 0 for the new contact."""
    K = SECTION2[letter]
    u1 = T.parse(text, u0=u0, **UNIT, **SECTION2)
    normal = p1.cross(K * q0)
    prop = T.positively_proportional(u1, normal, H)
    orient = T.has_sign(axis.dot(normal), 1, H)
    own = T.has_sign(axis.dot(u1), 1, H)       # with orient: parallel vectors with e_t components > 0 (the formal reading)
    ev = prop.evidence + orient.evidence + ([] if prop.holds else not_normal(u1, p1, H, tφ))
    return Check(f"l. 976-980: ũ(1) = `{text}` is a positive multiple of p(1) ∧ {letter}q(0), "
                 f"the normal of P(1) with e_t·u(1) > 0 ({RANGE[H.sign(cφ)]})", prop.holds and orient.holds and own.holds,
                 ev, witnesses=witnesses_of(prop, orient, own))


@certificate("S8.1", printed=dict(p0=CONTACT_P0["a"], q0=CONTACT_Q0["a"], u0=U0, ey_dot_u0=EY_DOT_U0, orientation=ORIENTATION,
                          u0_wedge_ey=U0_WEDGE["ey"], u0_wedge_ez=U0_WEDGE["ez"], u0_wedge_ex=U0_WEDGE["ex"],
                          u0_wedge_p0=U0_WEDGE["p0"], trilinear_b=TRILINEAR_B, trilinear_c=TRILINEAR_C),
             expect=ERRATUM,
             mutants=[replaced("u0", "-cos(θ)*sin(φ)", "cos(θ)*sin(φ)", "a sign of u(0)"),
                      overridden({"orientation": "a: y, b: x, c: z"}, "another orientation convention")])
def vectorial_version(p0, q0, u0, ey_dot_u0, orientation, u0_wedge_ey, u0_wedge_ez, u0_wedge_ex, u0_wedge_p0,
                      trilinear_b, trilinear_c):
    """Cross products as identities; orientations as positive ratios; a wrong plane by a rational witness."""
    p0, q0, u0 = vec(p0), vec(q0), vec(u0)
    pos, neg, H = T.hypotheses(1), T.hypotheses(-1), T.hypotheses()
    p1b, p1c = hit_point(p0, q0, 1), hit_point(p0, q0, 2)
    Wy, Wz, Wx, Wp = (vec(x) for x in (u0_wedge_ey, u0_wedge_ez, u0_wedge_ex, u0_wedge_p0))
    axes = orientation_axes(orientation)
    ey_u = T.parse(ey_dot_u0)
    checks = [
        identity("l. 943-947: p(0) ∧ q(0) is the printed u(0)", p0.cross(q0), u0),
        combined(f"l. 949: e_y·u(0) = `{ey_dot_u0}` ≥ 0, and e_t·u(0) ≥ 0 with the printed convention t = ({orientation})",
                 [T.equal(T.E_Y.dot(u0), ey_u), T.has_sign(ey_u, 1, H), T.has_sign(axes["a"].dot(u0), 1, H)]),
        combined("l. 958-960: u(0) ∧ e_y is the printed vector, a positive multiple of p(1) when the next collision is b",
                 [T.equal(u0.cross(T.E_Y), Wy), T.positively_proportional(Wy, p1b, pos), T.has_sign(Wy.dot(p1b), 1, pos)]
                 + [T.has_sign(w, 1, pos) for w in Wy if w != 0]),
        combined("l. 962-963: u(0) ∧ e_z is the printed vector, a positive multiple of p(1) when the next collision is c",
                 [T.equal(u0.cross(T.E_Z), Wz), T.positively_proportional(Wz, p1c, neg), T.has_sign(Wz.dot(p1c), 1, neg)]
                 + [T.has_sign(w, 1, neg) for w in Wz if w != 0]),
        combined("l. 967-969: u(0) ∧ e_x is the printed vector, of orientation opposite to p(0); e_x ∧ u(0) ∝ p(0) > 0",
                 [T.equal(u0.cross(T.E_X), Wx), T.positively_proportional(-Wx, p0, H),
                  T.positively_proportional(T.E_X.cross(u0), p0, H)]),
        combined("l. 971: u(0) ∧ p(0) is the printed vector, which is q(0)", [T.equal(u0.cross(p0), Wp), T.equal(Wp, q0)]),
        trilinear(trilinear_b, "B", u0, p1b, q0, pos, axes["b"], "1/2"),
    ]
    checks = [named(f"S8.1.{k + 1}", c) for k, c in enumerate(checks)]
    printed_c = named("S8.1.8", trilinear(trilinear_c, "C", u0, p1c, q0, neg, axes["c"], "2"))
    fixed_c = statements.corrected(trilinear_c, *TRILINEAR_C_CORRECTION)
    corrected_c = (named("S8.1.9", trilinear(fixed_c, "C", u0, p1c, q0, neg, axes["c"], "2")) if fixed_c else
                   Check(f"the stated correction `{TRILINEAR_C_CORRECTION[0]}` → `{TRILINEAR_C_CORRECTION[1]}` "
                         f"applies to the printed `{trilinear_c}`", False))
    return concluded(checks + [printed_c], checks + [corrected_c], kind=MISPRINT, misprint=E_Y_FOR_E_Z,
                    note="Contacts: the paper writes k = 1, 2, 3 for the contacts a, b, c in the orientation convention "
                         "(l. 949), where k also indexes the collisions.  For a collision c, p(1) ∝ u(0) ∧ e_z "
                         "(l. 962), so the factor [u(0) ∧ e_y] of l. 980 must be [u(0) ∧ e_z].")


# ---------------------------------------------------------------- S8.2
# transcribed once above (S8.1)
PRINTED_S8 = dict(orientation=ORIENTATION, to_b=TRILINEAR_B, to_c=TRILINEAR_C)


def trilinear_on_cone(text: str | None, st: RC.Step) -> T.Result:
    """The formula ``text`` (the relabelled one when None) at u = n is a positive multiple
    of the next normal n' = p' ∧ K_j w of the cone's step, for every state of the cone."""
    u = tuple(RC.N)
    ut = R.formula(text)(u, r) if text else R.trilinear(st.contact, st.following, u, r)
    return T.positively_proportional(sp.Matrix(ut), st.normal, st.H)


def trig_trilinear(text: str | None, contact: str, following: str, s: int, axes: dict) -> list[T.Result]:
    """The formula ``text`` (the relabelled one when None) at u = p(0) ∧ q(0) of the contact's
    printed frame (S7.1), for every radial part λ of the velocity (q_λ = q(0) + λ p(0)): parallel
    to p_λ(t_j) ∧ K_j q_λ (t_j the time the gap j closes), and where the collision happens
    (λ = λ_j - 1/τ, λ_j = -q_j(0)/p_j(0), τ = t_j > 0) both have a positive component t, the axis of
    the contact j (``axes``, the printed convention)."""
    p0, q0 = T.vector(CONTACT_P0[contact]), T.vector(CONTACT_Q0[contact])
    q, u = q0 + lam * p0, p0.cross(q0)
    i, j, K = INDEX[contact], INDEX[following], SECTION2[following.upper()]
    if text:
        ut = T.parse(text, u0=u, **UNIT, **SECTION2)
    else:
        ut = u.cross(sp.eye(3).col(j)).cross(K * u.cross(sp.eye(3).col(i).cross(u)))
    tau = sp.Symbol("τ")
    normal = (p0 + tau * q).cross(K * q).subs(lam, -q0[j] / p0[j] - 1 / tau)
    t = [k for k in range(3) if axes[following][k]][0]
    H = T.hypotheses(s).assume(tau, 1)
    return [T.parallel(ut, (p0 - p0[j] / q[j] * q).cross(K * q)), T.has_sign(ut[t], 1, H), T.has_sign(normal[t], 1, H)]


def not_normal_at(text: str, st: RC.Step) -> tuple[bool, str]:
    """An exact state of the cone (integer normal, r = 1/3) where the formula is not
    parallel to the next normal: a counterexample."""
    n = RC.representative(st)
    at = {**dict(zip(RC.N, n)), r: sp.Rational(1, 3)}
    ut = sp.Matrix(R.formula(text)(n, sp.Rational(1, 3)))
    n1 = st.normal.xreplace(at)
    wedge = ut.cross(n1)
    return (not wedge.is_zero_matrix, f"at n = {n} (a state of the cone {st.label}), r = 1/3: ũ(1) = "
                                      f"{T.show(ut)}, the next normal {T.show(n1)}, their cross product {T.show(wedge)}")


@certificate("S8.2", needs=["section4_data", "reduction_cones"], printed=PRINTED_S8,
             expect=ERRATUM,
             mutants=[replaced("to_b", "ey", "ez", "another axis in the b formula"),
                      replaced("orientation", "a: y", "a: z", "another orientation for a"),
                      replaced("to_b", "cross(ex, u0)", "cross(u0, ex)", "the cross product reversed")])
def vectorial_map_agrees_with_dynamics(section4_data, reduction_cones, orientation, to_b, to_c):
    """For every state, on the six cones of states (certify.dynamics.cones): right
    after a collision, p ∧ q = α p ∧ w = αρ n (α, ρ > 0), so the orientation holds when
    n_t > 0 on every cone; the trilinear formula at u = n is a positive multiple of the
    next normal n' = p' ∧ K_j w, which is p(1) ∧ q(1) up to a positive factor whatever
    the radial part (the particle lemma).  The printed formulas are for the contact a;
    the other contacts use the relabelled formula (:func:`certify.dynamics.reduction.trilinear`,
    "in a similar manner", l. 987).  A printed formula that fails is refuted at an exact
    state of its cone.  The exact runs are supporting evidence."""
    unit = orientation_axes(orientation)
    axes = {c: [k for k in range(3) if e[k]][0] for c, e in unit.items()}
    cones = reduction_cones
    lemmas = RC.dynamics_is_proven(cones)
    orient = [T.has_sign(RC.N[axes[c]], 1, st.H) for (c, _s), st in cones.items()]
    # the formal statements read the same in the printed frames (S7.1), for every radial part λ:
    # e_t·(p(0) ∧ q_λ(0)) = sin θ sin φ > 0, and the formulas by trig_trilinear
    frames = {c: (T.vector(CONTACT_P0[c]), T.vector(CONTACT_Q0[c])) for c in LETTERS}
    trig_orient = [T.equal(unit[c].dot(p0.cross(q0 + lam * p0)), T.sθ * sφ) for c, (p0, q0) in frames.items()]
    trig_orient.append(T.has_sign(T.sθ * sφ, 1, T.hypotheses()))
    a_b, a_c = cones[("a", 1)], cones[("a", -1)]
    on_b, on_c = trilinear_on_cone(to_b, a_b), trilinear_on_cone(to_c, a_c)
    trig_b, trig_c = trig_trilinear(to_b, "a", "b", 1, unit), trig_trilinear(to_c, "a", "c", -1, unit)
    relabelled = [trilinear_on_cone(None, st) for st in cones.values()]
    trig_relabelled = [x for c, f, s in (("b", "c", 1), ("b", "a", -1), ("c", "a", 1), ("c", "b", -1))
                       for x in trig_trilinear(None, c, f, s, unit)]
    premise = "; with the step and particle lemmas on the six cones (S11)"

    def grounds(*results) -> list[str]:      # the lemmas on the cones, and the results read on them
        return cone_witnesses(cones.values(), motion=True) + witnesses_of(*results)

    def evidence(results) -> list[str]:
        return [e for x in results for e in x.evidence[:1]]
    printed = [Check(f"u(k) = p(k) ∧ q(k) = αρ n satisfies the orientation e_t · u(k) > 0 (t = {orientation}) on every "
                     "cone of states", lemmas and all(orient) and all(trig_orient), evidence(orient + trig_orient),
                     witnesses=witnesses_of(*orient, *trig_orient), ref="S8.2.1"),
               Check(f"contact a, next b: `{to_b}` ∝ p(1) ∧ q(1), positively, for every state{premise}",
                     lemmas and a_b.following == "b" and on_b.holds and all(trig_b), on_b.evidence + evidence(trig_b),
                     witnesses=grounds(on_b, *trig_b), ref="S8.2.2"),
               Check(f"contact a, next c: `{to_c}` ∝ p(1) ∧ q(1), positively, for every state{premise}",
                     lemmas and a_c.following == "c" and on_c.holds and all(trig_c),
                     on_c.evidence + evidence(trig_c) + ([] if on_c.holds else [not_normal_at(to_c, a_c)[1]]),
                     witnesses=grounds(on_c, *trig_c), ref="S8.2.3"),
               Check(f"every contact: the relabelled formula [u ∧ e_j] ∧ [K_j(u ∧ [e_i ∧ u])] ∝ p(1) ∧ q(1), "
                     f"positively, for every state{premise}", lemmas and all(relabelled) and all(trig_relabelled),
                     evidence(relabelled + trig_relabelled), witnesses=grounds(*relabelled, *trig_relabelled),
                     ref="S8.2.5")]
    corrected = []
    fixed = statements.corrected(to_c, *TRILINEAR_C_CORRECTION)     # the correction stated once, for S8.1 too
    if not printed[2].holds and fixed:
        on_fixed = trilinear_on_cone(fixed, a_c)
        trig_fixed = trig_trilinear(fixed, "a", "c", -1, unit)
        refuted, witness = not_normal_at(to_c, a_c)
        corrected = [printed[0], printed[1],
                     Check(f"contact a, next c, with p(1) ∝ u(0) ∧ e_z (as in l. 962): `{fixed}` ∝ p(1) ∧ q(1), "
                           f"positively, for every state{premise}; the printed one is refuted at an exact state",
                           lemmas and a_c.following == "c" and on_fixed.holds and all(trig_fixed) and refuted,
                           on_fixed.evidence + evidence(trig_fixed) + [witness], corrects=printed[2],
                           witnesses=grounds(on_fixed, *trig_fixed), ref="S8.2.4"), printed[3]]
    evidence_runs = [supporting(tally_runs(section4_data, orientation, to_b, to_c))]
    return conclude(printed, corrected, evidence=evidence_runs, kind=MISPRINT, misprint=E_Y_FOR_E_Z)


def tally_runs(section4_data, orientation, to_b, to_c) -> str:
    """At each collision k of the exact runs: ũ(k+1) from u(k) = p(k) ∧ q(k) against
    p(k+1) ∧ q(k+1), and the orientation of u(k)."""
    t = {c: [k for k in range(3) if e[k]][0] for c, e in orientation_axes(orientation).items()}
    formulas = {"b": R.formula(to_b, integral=True), "c": R.formula(to_c, integral=True)}    # up to a factor > 0
    tally = {"a→b": [0, 0], "a→c": [0, 0], "relabelled": [0, 0]}
    oriented = [0, 0]
    for d in section4_data:
        contacts = [d.letter] + d.runs[0].events
        for L, L1, u, u1 in zip(contacts, contacts[1:], d.normals, d.normals[1:]):
            oriented[0] += 1
            oriented[1] += u[t[L]] > 0
            key = f"a→{L1}" if L == "a" else "relabelled"
            ut = formulas[L1](u, d.r) if L == "a" else R.vectorial_ray(L, u, d.r)[1]     # up to a factor > 0
            tally[key][0] += 1
            tally[key][1] += R.same_ray(ut, u1)
    return (f"on the exact runs, the orientation holds at {oriented[1]} of {oriented[0]} states, and the printed or "
            "relabelled formula gives a positive multiple of p(k+1) ∧ q(k+1) at " +
            ", ".join(f"{v[1]} of {v[0]} collisions {k}" for k, v in tally.items()) + ".")
