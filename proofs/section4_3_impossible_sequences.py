"""Section 4.3 (l. 989-1051): impossible collision sequences for the spherical reduction mapping.

S9.1 Proposition 4.4, the printed proof: after a contact a (or c) and a collision c (or a)
     the sign of cos φ' excludes the collision a (or c) next (l. 997-1035);
S9.2 Proposition 4.4 for every orbit: no aca, no cac, proven on the six cones of states;
S10  Corollary 4.5: b recurs, and every pattern is a concatenation of ab, cb, acb, cab
     (Remark 4.6, l. 1037-1051; false for a pattern that starts with b).

The printed texts are read as in proofs/section4_1_reduction_theorem.py; the cones of
states are :mod:`certify.dynamics.cones`.
"""
from __future__ import annotations

import re

import sympy as sp

from certify.algebra import statements
from certify.algebra import trig as T
from certify.dynamics import INDEX, LETTERS
from certify.dynamics import cones as RC
from certify.dynamics import reduction as R
from certify.run import (
    ERRATUM,
    FALSE_STATEMENT,
    PASS,
    Check,
    captured,
    certificate,
    combined,
    conclude,
    concluded,
    identity,
    kept_witnesses,
    overridden,
    replaced,
    result_check,
    reworded,
    unread,
    witnesses_of,
)
from proofs.section4_1_reduction_theorem import (
    SECTION2,
    cone_witnesses,
    cθ,
    cφ,
    hit_point,
    lemma_check,
    links,
    matrices_are,
    occurrences,
    recording_matrices,
    supporting,
    sθ,
    sφ,
    vec,
)
from proofs.section4_2_final_expressions import CONTACT_P0, CONTACT_Q0, RANGE, next_gap

# ================================================================ as printed (l. 997-1035)
# ---------------------------------------------------------------- as printed: Proposition 4.4 (l. 1005-1034)
P_NEXT_AC = "(sin(θ)*sin(φ), -cos(φ), 0)"                                       # l. 1012


Q_NEXT_AC = "Cq - dot(Cq, pk)*pk"                                               # l. 1016


C_TIMES_QK = """
M([[1, 0, 0], [0, 1, (1+r)/2], [0, 0, -r]])*V(sin(φ), -sin(θ)*cos(φ), cos(θ)*cos(φ))
= V(sin(φ), -sin(θ)*cos(φ) + (1+r)/2*cos(θ)*cos(φ), -r*cos(θ)*cos(φ))"""        # l. 1020


PROJECTION_CHAIN = """
V(sin(φ), -sin(θ)*cos(φ) + (1+r)/2*cos(θ)*cos(φ), -r*cos(θ)*cos(φ))
  - (-cos(θ)*sin(θ)*cos(φ) + (1+r)/2*cos(θ)^2*cos(φ) - r*cos(θ)*sin(θ)*cos(φ))*V(0, cos(θ), sin(θ))
= V(sin(φ),
    -sin(θ)*cos(φ) + (1+r)/2*cos(θ)*cos(φ) + (1+r)*cos(θ)^2*sin(θ)*cos(φ) - (1+r)/2*cos(θ)^3*cos(φ),
    -r*cos(θ)*cos(φ) + (1+r)*cos(θ)*sin(θ)^2*cos(φ) - (1+r)/2*cos(θ)^2*sin(θ)*cos(φ))"""  # l. 1024-1031


FORM_C = "(-sin(θ)*cos(φ), cos(θ)*cos(φ), sin(φ))"                             # l. 1033 (θ', φ')


COS_NEXT, SIN_NEXT = sp.symbols("cos_φ' sin_φ'")                              # what the conclusion is about


READ_COMPONENT = 1                                                              # l. 1033: the first component


CONCLUSION = "cos(φ') < 0"                                                      # l. 1033


# ================================================================ Proposition 4.4 (l. 997-1035): no aca, no cac; S9.1 the printed proof, S9.2 for every orbit
# ================================================================ S9.1
FRAME_AXIS = {"a": T.E_X, "c": T.E_Z}          # e_θ = e_axis ∧ p for the printed frames of contacts a and c


SIGN_C = "sin(φ)*cos(φ)*(cos(θ)^2 + (1+r)/2*sin(θ)*cos(θ))"     # (p(k+1) ∧ C q(k))_z, ours


SIGN_A = "sin(φ)*cos(φ)*(sin(θ)^2 + (1+r)/2*sin(θ)*cos(θ))"     # (p(k+1) ∧ A q(k))_x, ours


def frame_lemma(contact: str, p0_text: str, q0_text: str) -> Check:
    """In the frame of ``contact``, q(0) = cos φ e_θ + sin φ e_axis with e_θ = e_axis ∧ p(0), and
    every representative q' = q(0) + μ p(0) of the velocity in the plane has q'·e_θ = cos φ."""
    mu = sp.Symbol("μ")
    p0, q0, axis = vec(p0_text), vec(q0_text), FRAME_AXIS[contact]
    e_theta = axis.cross(p0)
    res = T.equal(sp.Matrix.vstack(q0, sp.Matrix([(q0 + mu * p0).dot(e_theta)])),
                  sp.Matrix.vstack(cφ * e_theta + sφ * axis, sp.Matrix([cφ])))
    return Check(f"contact {contact}: e_θ = e_{'x' if contact == 'a' else 'z'} ∧ p(0), q(0) = cos φ e_θ + sin φ "
                 "e_axis, and (q(0) + μ p(0))·e_θ = cos φ for every μ: cos φ' is read on any representative",
                 res.holds, res.evidence)


def next_angle_sign(contact: str, letter: str, cos_phi: int, axis_index: int, formula: str) -> list[Check]:
    """After ``contact`` then ``letter`` (cos φ of sign ``cos_phi``): with P the printed-form
    hit point and K q(k) the velocity after the collision, sign(cos φ') = sign((P ∧ K q(k))_axis)
    (as K q(k)·e_θ' = (P ∧ K q(k))_axis / |P|); the factored formula and its sign."""
    H = T.hypotheses(cos_phi)
    p0, q0 = vec(CONTACT_P0[contact]), vec(CONTACT_Q0[contact])
    k, ev, _signs = next_gap(contact, p0, q0, H)
    P = hit_point(p0, q0, k)
    Kq = SECTION2[letter] * q0
    axis = FRAME_AXIS[LETTERS[k]]
    s = T.parse(formula)
    triple = T.equal(Kq.dot(axis.cross(P)), P.cross(Kq)[axis_index])
    value = T.positively_proportional(P.cross(Kq)[axis_index] * sp.ones(1, 1), s * sp.ones(1, 1), H)
    sign = T.has_sign(s, cos_phi, H)
    return [Check(f"{contact} then {LETTERS[k]} ({RANGE[cos_phi]}): the collision is {letter.lower()}", LETTERS[k] == letter.lower(), ev),
            combined(f"K q(k)·(e_axis ∧ p(k+1)) = (p(k+1) ∧ K q(k))_axis, a positive multiple of `{formula}`, which is "
                     f"{'>' if cos_phi > 0 else '<'} 0: cos φ' {'>' if cos_phi > 0 else '<'} 0", [triple, value, sign])]


def referring(ref: str, *checks: Check) -> list[Check]:
    """The checks, each deciding the formal statement ``ref`` (statements/4_dynamics.txt)."""
    for c in checks:
        c.ref = ref
    return list(checks)


@certificate("S9.1", printed=dict(p_k=CONTACT_P0["a"], q_k=CONTACT_Q0["a"], p_next=P_NEXT_AC, q_next=Q_NEXT_AC,
                          C_times_qk=C_TIMES_QK, projection=PROJECTION_CHAIN, form_c=FORM_C,
                          read_component=READ_COMPONENT, conclusion=CONCLUSION),
             expect=ERRATUM,
             mutants=[replaced("projection", "+ (1+r)*cos(θ)^2*sin(θ)", "+ (1-r)*cos(θ)^2*sin(θ)", "a sign in the projection"),
                      overridden({"conclusion": "cos(φ') > 0"}, "the conclusion reversed"),
                      reworded("conclusion", "cos(φ')", "sin(φ')", "sin φ' > 0 by definition"),
                      reworded("conclusion", "<", ">"),
                      reworded("conclusion", "<", "≥"),
                      unread("conclusion", "cos(φ'') < 0", "an unknown name")])
def no_aca_no_cac(p_k, q_k, p_next, q_next, C_times_qk, projection, form_c, read_component, conclusion):
    """The printed algebra as printed; whether its vector is q(k+1); the corrected argument.
    The printed conclusion (cos φ' < 0) is read and evaluated on the certified signs of
    cos φ' (< 0, by the sign of (p(k+1) ∧ C q(k))_z) and sin φ' (> 0, φ' ∈ ]0,π[)."""
    pk, qk, Pn = vec(p_k), vec(q_k), vec(p_next)
    neg = T.hypotheses(-1)
    C = SECTION2["C"]
    M, seen = recording_matrices()
    CQ, PR = T.chain(C_times_qk, M=M), T.chain(projection)
    w = T.parse(q_next, Cq=C * qk, pk=pk)
    n = Pn.cross(C * qk)                                   # normal of P(k+1) = Span(p(k+1), C q(k))
    j = int(read_component) - 1
    algebra = referring("S9.1.1", identity("l. 1020: C q(k) (C of Section 2) is member 1", C * qk, CQ[0])) + \
        referring("S9.1.2", *links("C q(k)", CQ, "1020")) + \
        referring("S9.1.3", matrices_are("c", seen, "1020")) + \
        referring("S9.1.4", identity("l. 1016, 1024: the printed Cq(k) - (Cq(k)·p(k))p(k) is member 1 of l. 1024-1031",
                                     w, PR[0])) + \
        referring("S9.1.5", *links("the projection", PR, "1024-1031")) + \
        referring("S9.1.6", result_check("l. 1012: p(k+1) ∝ the printed (sinθ sinφ, -cosφ, 0), a positive multiple of "
                                         "the hit point", T.positively_proportional(hit_point(pk, qk, 2), Pn, neg))) + \
        referring("S9.1.7", identity(f"l. 1033: component {j + 1} of the printed vector is sin φ, and component {j + 1} "
                                     f"of the form `{form_c}` of q(k+1) is -sinθ' cosφ' (frame of contact c)",
                                     sp.Matrix([w[j], vec(form_c)[j]]), sp.Matrix([sφ, -sθ * cφ])))
    in_plane = [T.is_zero(w.dot(Pn)), T.is_zero(w.dot(n))]
    pt = T.point("1/2", "2", r="1/3")
    vector_claim = Check("l. 1014-1016: q(k+1) is a positive multiple of the printed Cq(k) - (Cq(k)·p(k))p(k): it should "
                         "be orthogonal to p(k+1) and lie in P(k+1)", all(in_plane),
                         [f"·p(k+1): {'; '.join(in_plane[0].evidence)}", f"·(p(k+1) ∧ Cq(k)): {'; '.join(in_plane[1].evidence)}",
                          f"at cos θ = {pt[cθ]}, cos φ = {pt[cφ]}, r = 1/3: ·p(k+1) = {T.at(w.dot(Pn), pt)}, "
                          f"·(p(k+1) ∧ Cq(k)) = {T.at(w.dot(n), pt)}"], ref="S9.1.8")
    w_true = C * qk - (C * qk).dot(Pn) / Pn.dot(Pn) * Pn
    true_first = T.has_sign(w_true[0], 1, neg)
    aca = next_angle_sign("a", "C", -1, 2, SIGN_C)
    cac = next_angle_sign("c", "A", 1, 0, SIGN_A)
    gaps = {c: next_gap(c, vec(CONTACT_P0[c]), vec(CONTACT_Q0[c]), T.hypotheses(s)) for c, s in (("c", -1), ("a", 1))}
    then_b = [Check(f"after a contact {c} with cos φ' {'<' if s < 0 else '>'} 0 the next collision is b",
                    gaps[c][0] == INDEX["b"], witnesses=kept_witnesses(gaps[c][2]))
              for c, s in (("c", -1), ("a", 1))]
    # certified: cos φ' < 0 (aca[1]) and sin φ' > 0 (φ' ∈ ]0,π[ by definition); the printed conclusion read on them
    read = statements.relation(conclusion, {"cos(φ')": COS_NEXT, "sin(φ')": SIN_NEXT}).holds({COS_NEXT: -1, SIN_NEXT: 1})
    concl = Check(f"l. 1033-1034: {conclusion}, so c_(k+2) = b (no aca)", aca[1].holds and read and then_b[0].holds,
                  aca[1].evidence, ref="S9.1.9")
    projection = combined("corrected: q(k+1) ∝ Cq(k) - (Cq(k)·p(k+1))p(k+1)/|p(k+1)|², the projection on p(k+1)^⊥: "
                          "orthogonal to p(k+1), in P(k+1)", [T.is_zero(w_true.dot(Pn)), T.is_zero(w_true.dot(n))])
    projection.corrects, projection.ref = vector_claim, "S9.1.10"
    corrected = algebra + [
        projection,
        frame_lemma("c", CONTACT_P0["c"], CONTACT_Q0["c"]),
        *aca, then_b[0], concl,
        *referring("S9.1.10", result_check("its first component is > 0 as well (the printed reading of the sign gives the "
                                           "right answer for the right vector)", true_first)),
        frame_lemma("a", CONTACT_P0["a"], CONTACT_Q0["a"]),
        *cac, then_b[1],
        Check("no cac: after c then a, cos φ' > 0 and the next collision is b", all(cac) and then_b[1].holds,
              witnesses=[i for x in [*cac, then_b[1]] for i in x.witnesses or []])]
    return concluded(algebra + [vector_claim, concl], corrected, kind=FALSE_STATEMENT,
                     misprint="l. 1014-1016: q(k+1) projected on p(k)^⊥, not p(k+1)^⊥ (a step of the proof of "
                              "Proposition 4.4; the proposition holds)",
                    note="The printed proof projects C q(k) on p(k)^⊥ instead of p(k+1)^⊥; the proposition holds, "
                         "by the sign of (p(k+1) ∧ C q(k))_z read on any representative of the velocity.  The cac case "
                         "is done directly (the paper: 'by symmetry').")


# ---------------------------------------------------------------- S9.2
PRINTED_S9 = dict(aca="c_k = a, c_{k+1} = c ⇒ c_{k+2} ≠ a", cac="c_k = c, c_{k+1} = a ⇒ c_{k+2} ≠ c")


def implication(text: str) -> tuple[str, str]:
    """"c_k = a, c_{k+1} = c ⇒ c_{k+2} ≠ a" as (the pair "ac", the excluded letter "a"),
    read whole (statements.word_rule): a rule of another shape (other offsets, = for ≠,
    more premises) is not what this certificate counts, and is a StatementError."""
    rule = statements.word_rule(text)
    premises, conclusions = rule.premises, rule.conclusions
    if [(o, eq) for o, _, eq in premises] != [(0, True), (1, True)] or \
            [(o, eq) for o, _, eq in conclusions] != [(2, False)]:
        raise statements.StatementError(f"cannot evaluate {text!r}: S9.2 counts the rules c_k = x, c_{{k+1}} = y "
                                        "⇒ c_{k+2} ≠ z")
    (_, x, _), (_, y, _) = premises
    return x + y, conclusions[0][1]


@certificate("S9.2", needs=["reduction_cones", "reduction_scan", "section4_data"], printed=PRINTED_S9,
             expect=PASS,
             mutants=[replaced("aca", "c_{k+1} = c", "c_{k+1} = b", "after ab both a and c may come"),
                      replaced("aca", "≠ a", "≠ b", "after ac the next is b"),
                      replaced("cac", "c_k = c", "c_k = b", "after ba both b and c may come"),
                      reworded("aca", "c_{k+2}", "c_{k+3}", "false (acba… occurs); the index was not read"),
                      reworded("cac", "≠", "="),
                      unread("aca", "c_k = a, c_{k+1} = c ⇒ c_{k+2} ≠ d", "not a letter")])
def no_aca_cac_for_every_orbit(reduction_cones, reduction_scan, section4_data, aca, cac):
    """A proof independent of S9.1's (which is in θ, φ): the states right after a
    collision x whose next collision is y form one cone (contact x, sign of n_x); on it
    the step lemma gives the next normal n' ∝ p' ∧ K_y w = ρ cof(K_y) n, and the collision
    after y is the gap m ≠ y with n'_y n'_m > 0.  So z cannot follow when n'_y n'_z < 0 is
    proven from the factors on the whole cone.  The counts on the exact orbits are
    supporting evidence."""
    scan = [o.word for o in reduction_scan]
    physical = [run.word for d in section4_data for run in d.runs]
    checks, evidence = [], []
    for ref, text in (("S9.2.1", aca), ("S9.2.2", cac)):
        pair, excluded = implication(text)
        x, y = (pair + "??")[:2]
        cases = [c for c in reduction_cones.values() if c.contact == x and c.following == y]
        pattern = pair + excluded
        if len(cases) != 1:
            checks.append(Check(f"{text}: no state of contact {x} has the next collision {y}", False, ref=ref))
            continue
        c = cases[0]
        res = c.excludes(excluded)
        checks.append(Check(f"{text}: every state with c_k = {x}, c_(k+1) = {y} lies in the cone {c.label}; there "
                            f"the next normal n' has n'_{INDEX[y] + 1} n'_{INDEX[excluded] + 1} < 0, so the collision "
                            f"after {y} is not {excluded} (for every orbit)", c.holds and res.holds,
                            [f"n' ∝ p' ∧ {y.upper()} w = `{T.show(c.normal)}`"] + res.evidence
                            + ([] if c.holds else lemma_check(c).evidence), witnesses=witnesses_of(res), ref=ref))
        evidence.append(supporting(
            f"{pattern} occurs {occurrences(scan, pattern)} times in {sum(map(len, scan))} collisions of {len(scan)} "
            f"exact reduction orbits and {occurrences(physical, pattern)} times in {sum(map(len, physical))} "
            f"collisions of {len(physical)} exact particle runs (which realise prefixes of the reduction's words, "
            f"S11); {pair} occurs {occurrences(scan, pair)} times in the orbits."))
    return conclude(checks, evidence=evidence)


# ================================================================ Corollary 4.5 and Remark 4.6 (l. 1037-1051): S10
# ---------------------------------------------------------------- S10
PRINTED_S10 = dict(window="c_k = b ⇒ c_{k+2} = b or c_{k+3} = b", blocks="ab, cb, acb, cab")


def offsets(text: str) -> set[int]:
    """"c_k = b ⇒ c_{k+2} = b or c_{k+3} = b" as {2, 3}, read whole (statements.word_rule):
    a rule of another shape (another letter, ≠, more premises) is not what this
    certificate evaluates, and is a StatementError."""
    rule = statements.word_rule(text)
    if rule.premises != ((0, "b", True),) or any(c[1:] != ("b", True) or c[0] == 0 for c in rule.conclusions):
        raise statements.StatementError(f"cannot evaluate {text!r}: S10 evaluates rules c_k = b ⇒ c_{{k+m}} = b or …")
    return {c[0] for c in rule.conclusions}


def window_holds(words, ks: set[int]) -> tuple[int, int]:
    """(b's with a full look-ahead, those followed by b at one of the offsets ks)."""
    seen = good = 0
    top = max(ks)
    for w in words:
        end = len(w) - top                 # the b's at k with k + max(ks) < len(w)
        k = w.find("b", 0, end) if end > 0 else -1
        while k >= 0:
            seen += 1
            good += any(w[k + m] == "b" for m in ks)
            k = w.find("b", k + 1, end)
    return seen, good


def parses(word: str, blocks: list[str]) -> bool:
    """word is a concatenation of blocks, the last one possibly cut short (blocks
    end with b and contain one b, so the cut is unique)."""
    # from k = 0, the first block (in the order given) that starts at k, again and again: an
    # atomic alternation repeated possessively (no other choice is ever tried)
    found = re.match("(?>" + "|".join(map(re.escape, blocks)) + ")*+", word) if blocks else None
    k = found.end() if found else 0         # (the repetition matches, at worst the empty text)
    return k == len(word) or any(B.startswith(word[k:]) for B in blocks)


@certificate("S10", needs=["reduction_cones", "reduction_scan"], printed=PRINTED_S10,
             expect=ERRATUM,
             mutants=[replaced("window", " or c_{k+3} = b", "", "the window shortened to c_{k+2}"),
                      replaced("blocks", ", cab", "", "a block dropped"),
                      reworded("window", "c_{k+3} = b", "c_{k+3} = a", "false; the letters were not read"),
                      reworded("window", "c_k = b", "c_k = a"),
                      unread("window", "c_k = b ⇒ c_{k+2} = b and c_{k+3} = b", "a conjunction in the conclusion")])
def b_recurs(reduction_cones, reduction_scan, window, blocks):
    """For every orbit: every window of an orbit's word is admissible, that is its pairs
    are proven steps (the step lemma on the six cones: the next contact is another one)
    and its triples are not excluded by the sign of the next normal (Proposition 4.4 as
    in S9.2: no aca, no cac).  The statements follow by exhausting the admissible
    windows.  The block decomposition fails for every orbit whose first collision is b
    (no block starts with b), as for every state of a cone whose next contact is b; it
    holds once that leading b is removed, by induction along the word.  The scan's 10^5
    exact collisions are supporting evidence."""
    ks, blks = offsets(window), [B.strip() for B in blocks.split(",")]
    cones = reduction_cones.values()
    lemma = all(c.holds for c in cones)
    # a letter whose exclusion is not proven stays allowed (the admissible windows are a superset of those that
    # occur): the verdicts rest on the step lemmas and on the exclusions proven (S9.2, their witnesses)
    with captured() as proven:
        allowed = RC.transitions(reduction_cones)

    def grounds() -> list[str]:
        return cone_witnesses(cones) + kept_witnesses(proven)
    rules = "; ".join(f"{x}{y} → {'/'.join(sorted(z))}" for (x, y), z in sorted(allowed.items()))
    starts_b = [w for w in RC.admissible(max(ks) + 1, allowed) if w[0] == "b"]
    seen, good = window_holds(starts_b, ks)
    three = RC.admissible(3, allowed)
    scan = [o.word for o in reduction_scan]
    s_seen, s_good = window_holds(scan, ks)
    printed = [Check(f"{window}: every admissible window b… of length {max(ks) + 1} has b at the stated places (for "
                     "every orbit)", lemma and seen == good > 0,
                     [f"allowed after each proven step: {rules}", f"{good} of {seen}: {', '.join(starts_b)}"],
                     witnesses=grounds(), ref="S10.1"),
               Check("b occurs infinitely often: every admissible window of length 3 contains b, and every orbit off "
                     "the corners has infinitely many collisions (the step lemma on the six cones, S11)",
                     lemma and all("b" in w for w in three), [f"{len(three)} windows: {', '.join(three)}"],
                     witnesses=grounds(), ref="S10.2")]
    width = max(len(B) for B in blks)
    uncovered = [w for w in RC.admissible(width, allowed) if w[0] != "b" and not any(w.startswith(B) for B in blks)]
    induction = lemma and not uncovered and all(B.endswith("b") for B in blks)
    first_b = [c for c in cones if c.holds and c.following == "b"]
    witness = []
    for c in first_b:
        P = R.canonical(c.contact, RC.representative(c))
        witness.append(f"every state of the cone {c.label} (e.g. n = {P.n}, whose first collision is "
                       f"{R.next_letter(P)} by the engine) has c_1 = b")
    induction_ev = [f"admissible windows of length {width} not starting with b and not starting with a block: "
                    f"{', '.join(uncovered) or 'none'}; every block ends with b, and no letter follows itself"]
    leading_b = [w for w in scan if w.startswith("b")]
    printed.append(Check(f"every pattern is a concatenation of {', '.join(blks)}", induction and not first_b,
                         witness + induction_ev, witnesses=grounds(), ref="S10.3"))
    corrected = printed[:2] + [
        Check(f"c_1 c_2 …, without its first letter when that is b, is a concatenation of {', '.join(blks)}: each "
              "admissible window that does not start with b starts with a block, which ends with b, so the next "
              "letter is not b again (induction along the word)", induction, induction_ev, corrects=printed[2],
              witnesses=grounds(), ref="S10.4")]
    evidence = [supporting(f"{window} at {s_good} of {s_seen} collisions b of the scan ({len(scan)} exact orbits, "
                           f"{sum(map(len, scan))} collisions); {sum(parses(w, blks) for w in scan)} of {len(scan)} "
                           f"orbit words parse as printed, {len(leading_b)} start with b, e.g. "
                           f"`{(leading_b or [''])[0][:24]}…`; without that b, "
                           + ("all parse." if all(parses(w[1:] if w.startswith('b') else w, blks) for w in scan)
                              else "some still do not parse."))]
    return conclude(printed, corrected, evidence=evidence, kind=FALSE_STATEMENT,
                    misprint="l. 1049-1051, Remark 4.6: every pattern 'is obtained by the concatenation of only four "
                             "elementary \"blocks\" of collisions, namely ab, cb, acb and cab': false for a pattern that starts with b (Corollary 4.5 holds)")
