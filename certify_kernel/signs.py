"""Strict signs over several real variables (angles θ, φ, r, λ, ...) by inspection of a
factorisation: the route of ``forall θ in ]0, π/2[, ...: E > 0``.

The binders give sign hypotheses (θ ∈ ]0, π/2[: cos θ > 0, sin θ > 0; θ ∈ ]π/2, π[: cos θ < 0,
sin θ > 0; r ∈ ]0, 1[: r > 0; a variable in ]0, ∞[: > 0).  The certificate supplies, per atom, a
witness: a fraction n/d equal to the kernel's own expression (checked as an identity modulo the
circles) and for n and d a form congruent to it modulo the circles, factored as c·Π fᵐ (the
product expanded and compared exactly), each factor's strict sign shown either by its having
no root in ]0, 1[ (a polynomial in r alone; Sturm) or by all the terms of a congruent form having
one strict sign under the hypotheses.  Nothing of the witness is trusted but what is checked.
"""
from __future__ import annotations

from fractions import Fraction

from .evaluate import NEG, POS, QUANTIFIERS, NotVerified, arith, order, value
from .poly import madd, mmul, reduce_circles, sign
from .poly import value as at
from .sturm import count
from .values import CIRCLES, RF, VARS, Undefined, _to_list

QUADRANTS = {(Fraction(0), Fraction(1, 2)): (1, 1), (Fraction(1, 2), Fraction(1)): (-1, 1),     # (cos, sin)
             (Fraction(0), Fraction(1)): (None, 1)}


def hypotheses(B) -> dict:
    """Variable index -> strict sign, from the binders' intervals (angles by their quadrant: the
    signs of cos and sin)."""
    hyp: dict = {}
    for name, iv in B.angles.items():
        if not iv.angular:
            if iv.lo != NEG and order(iv.lo, 0) >= 0:
                hyp[VARS.index(name)] = 1
            elif iv.hi != POS and order(iv.hi, 0) <= 0:
                hyp[VARS.index(name)] = -1
            continue
        lo = iv.lo if isinstance(iv.lo, Fraction) else Fraction(0) if _zero(iv.lo) else None   # the end 0, a number
        if (lo, iv.hi) not in QUADRANTS:
            raise Undefined(f"an angle in ]{lo}π, {iv.hi}π[: only the quadrants ]0, π/2[, ]π/2, π[, ]0, π[")
        for fn, s in zip((f"cos {name}", f"sin {name}"), QUADRANTS[(lo, iv.hi)]):
            if s is not None:
                hyp[VARS.index(fn)] = s
    if _in_unit(B):
        hyp[VARS.index("r")] = 1
    return hyp


def _in_unit(B) -> bool:
    """r's binder is an interval inside [0, 1]: r > 0 there, and a polynomial in r without root in
    ]0, 1[ keeps its sign there."""
    iv = B.interval
    return iv is not None and iv.lo not in (NEG, POS) and iv.hi not in (NEG, POS) and order(iv.lo, 0) >= 0 \
        and order(iv.hi, 1) <= 0


def _zero(x) -> bool:
    return x is not None and not isinstance(x, str) and order(x, 0) == 0


def _kernel_name(name: str) -> str:
    """The kernel's name of a witness's variable: the engine writes cos θ as ``cosθ``."""
    if name not in VARS and name[:3] in ("cos", "sin") and f"{name[:3]} {name[3:]}" in VARS:
        return f"{name[:3]} {name[3:]}"
    return name


def _terms(data, names: list) -> dict:
    """Witness terms [[coef, [exps]], ...] over ``names`` as a polynomial over VARS."""
    idx = [VARS.index(_kernel_name(n)) for n in names]
    out: dict = {}
    for coef, exps in data:
        key = [0] * len(VARS)
        for i, e in zip(idx, exps):
            key[i] = int(e)
        k = tuple(key)
        out[k] = out.get(k, Fraction(0)) + Fraction(coef)
    return {k: v for k, v in out.items() if v}


def _form_sign(form: dict, hyp: dict) -> int:
    """The strict sign of a form whose terms all have one sign under the hypotheses (a variable of
    unknown sign only to even powers, one term strict), else 0."""
    signs, strict = set(), False
    for k, v in form.items():
        s, st = sign(v), True
        for i, e in enumerate(k):
            if e and i not in hyp:
                if e % 2:
                    return 0
                st = False
            elif e:
                s *= hyp[i] ** e
        signs.add(s)
        strict |= st
    return signs.pop() if len(signs) == 1 and strict else 0


def _factor_sign(f: dict, names: list, hyp: dict, r_in_unit: bool) -> int:
    poly = _terms(f["poly"], names)
    if f.get("how") == "r":
        k = VARS.index("r")
        if not r_in_unit or any(e for key in poly for i, e in enumerate(key) if i != k):
            raise Undefined("a factor read as a polynomial in r on ]0, 1[ is not one")
        u = _to_list(poly, k)
        if not u or count(u, Fraction(0), Fraction(1)) - (1 if not sum(u) else 0):
            raise Undefined("a factor in r has a root in ]0, 1[")
        return sign(at(u, Fraction(1, 2)))
    form = _terms(f["form"], names)
    if reduce_circles(madd(poly, form, -1), CIRCLES):
        raise Undefined("a factor's form differs from it modulo the circles")
    s = _form_sign(form, hyp)
    if not s:
        raise Undefined("a factor's terms do not all have one strict sign")
    return s


def _part_sign(part: dict, given: dict, names: list, hyp: dict, r_in_unit: bool) -> int:
    """The sign of ``given`` from a congruent form c·Π fᵐ."""
    form = _terms(part["form"], names)
    if reduce_circles(madd(given, form, -1), CIRCLES):
        raise Undefined("the form differs from the expression modulo the circles")
    c = Fraction(part["constant"])
    product = {(0,) * len(VARS): c} if c else {}
    s = sign(c)
    for f in part["factors"]:
        poly = _terms(f["poly"], names)
        for _ in range(int(f["mult"])):
            product = mmul(product, poly)
        s *= _factor_sign(f, names, hyp, r_in_unit) ** int(f["mult"])
    if madd(product, form, -1):
        raise Undefined("the factors do not multiply to the form")
    return s


def sign_by_witness(E: RF, witnesses: list, hyp: dict, r_in_unit: bool) -> int | None:
    """The strict sign of E from the first witness n/d ≡ E whose factorisations check, or None."""
    for w in witnesses or []:
        if not isinstance(w, dict) or "num" not in w:
            continue
        try:
            names = list(w["vars"])
            n, d = _terms(w["expr"]["num"], names), _terms(w["expr"]["den"], names)
            if not d or reduce_circles(madd(mmul(n, E.den), mmul(d, E.num), -1), CIRCLES):
                continue                                   # another atom's witness
            return _part_sign(w["num"], n, names, hyp, r_in_unit) * _part_sign(w["den"], d, names, hyp, r_in_unit)
        except (Undefined, KeyError, TypeError, ValueError):
            continue
    form = [_form_sign(p, hyp) or _form_sign(reduce_circles(p, CIRCLES), hyp) for p in (E.num, E.den)]
    return form[0] * form[1] or None


def by_inspection(B, body, ctx) -> bool:
    """forall over several variables: the body a conjunction of strict signs E > 0, E < 0 (and
    identities E = F), each sign shown by a witness (or by E's own terms)."""
    hyp, unit = hypotheses(B), _in_unit(B)
    if B.interval is not None and not unit:
        raise Undefined("over several variables, r ranges in an interval inside [0, 1]")
    if any(iv.lo_closed or iv.hi_closed for iv in [*B.angles.values(), B.interval] if iv is not None):
        raise Undefined("over several variables, every variable ranges in an open interval (strict signs)")
    atoms, todo = [], [body]
    while todo:
        t = todo.pop()
        if t[0] == "and":
            todo += [t[1], t[2]]
        elif t[0] == "cmp" and len(t[1]) == 1:
            atoms.append(t)
        else:
            raise Undefined("over several variables a statement is a conjunction of signs and identities")
    for t in atoms:
        (op,), (a, b) = t[1], t[2]
        g = arith("-", value(a, ctx), value(b, ctx))
        if op == "=":
            if not g.is_zero():
                return False
            continue
        if op not in ("<", ">"):
            raise Undefined(f"{op}: over several variables only strict signs")
        s = sign_by_witness(g, ctx.witnesses, hyp, unit)
        if s is None:
            raise NotVerified("no witness shows the sign of " + (a[1] if a[0] == "name" else "an atom"))
        if s != (1 if op == ">" else -1):
            return False
    return True


QUANTIFIERS["angles"] = by_inspection     # evaluate.forall's route over angles (evaluate does not import this module)
