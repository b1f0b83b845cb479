"""The spherical reduction map (l. 852-987) on its six cones of states, and the collision words of
its orbits: the predicates ``windows(F)``, ``concatenation(B, ...)`` and ``endless()`` of
statements/4_dynamics.txt (Remark 4.2, Proposition 4.4, Corollary 4.5, Remark 4.6).

A state is a contact i (a, b, c: p_i = 0) and u = (n1, n2, n3), the normal of its plane up to a
positive factor, oriented by u_t > 0 (t = y, z, x for a, b, c: l. 949-950); its position is
p = e_i ∧ u (l. 969), its velocity w = u ∧ p (l. 971).  p is in the open face when u_k < 0 (k the
third index), off the corners when moreover u_i ≠ 0: six cones (i, sign of u_i).  :func:`graph`
proves the step lemma on each cone (S11.1-S11.6): p in the open face, w_i > 0, exactly one other gap
j closes (w_j < 0 < w_k), and u' = [u ∧ e_j] ∧ [K_j w] (l. 976-980) lies in a cone of j (u'_t > 0 >
u'_k), of the sign of u'_j when that is one on the whole cone, else in either; each sign read off
the terms of a polynomial in n1, n2, n3, r (:func:`certify_kernel.signs._form_sign`).  So every
orbit off the corners follows a path of this graph: a property of every window of every path holds
for every orbit; a path that violates it is decided false only on an exact orbit with that window.
"""
from __future__ import annotations

from fractions import Fraction
from itertools import product

from .evaluate import PREDICATES, NotVerified, collision, collisions_at, cross
from .signs import _form_sign
from .values import RF, VARS, Undefined

LETTERS = "abc"
ORIENTED = (1, 2, 0)                      # t with u_t > 0 for the contacts a, b, c (l. 949-950)
E = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
_GRAPH: dict = {}                         # (i, sign of u_i) -> (j, the signs u'_j may have)


def _third(i: int) -> int:
    return 3 - i - ORIENTED[i]


def _sign(e: RF, hyp: dict) -> int:
    return _form_sign(e.num, hyp) * _form_sign(e.den, hyp)


def graph() -> dict:
    """The step lemma on each cone: {(i, s): (j, signs of u'_j)} (NotVerified where one fails)."""
    if _GRAPH:
        return _GRAPH
    if any(f"n{k}" not in VARS for k in (1, 2, 3)):
        raise Undefined("the normal's coordinates are not declared (vars n1, n2, n3)")
    u = tuple(RF.var(f"n{k}") for k in (1, 2, 3))
    unit = [tuple(RF.const(x) for x in e) for e in E]
    for i, s in product(range(3), (1, -1)):
        hyp = {VARS.index("r"): 1, VARS.index(f"n{ORIENTED[i] + 1}"): 1, VARS.index(f"n{_third(i) + 1}"): -1,
               VARS.index(f"n{i + 1}"): s}
        p = cross(unit[i], u)
        w = cross(u, p)
        closing = [m for m in range(3) if m != i and _sign(w[m], hyp) == -1]
        if any(_sign(p[m], hyp) != 1 for m in range(3) if m != i) or _sign(w[i], hyp) != 1 or len(closing) != 1 \
                or _sign(w[3 - i - closing[0]], hyp) != 1:
            raise NotVerified(f"the step lemma on the cone ({LETTERS[i]}, {s:+d}) fails")
        j = closing[0]
        nxt = cross(cross(u, unit[j]), collision(j) * w)
        if _sign(nxt[ORIENTED[j]], hyp) != 1 or _sign(nxt[_third(j)], hyp) != -1:
            raise NotVerified(f"from the cone ({LETTERS[i]}, {s:+d}) the next normal leaves the cones of {LETTERS[j]}")
        cos = _sign(nxt[j], hyp)
        _GRAPH[(i, s)] = (j, (cos,) if cos else (1, -1))
    return _GRAPH


def words(n: int) -> set:
    """The words of the paths of n states."""
    paths = [[c] for c in graph()]
    for _ in range(n - 1):
        paths = [P + [(graph()[P[-1]][0], s)] for P in paths for s in graph()[P[-1]][1]]
    return {"".join(LETTERS[i] for i, _ in P) for P in paths}


def orbit(i: int, u: tuple, r: Fraction, n: int) -> str | None:
    """The contacts of the first n states of the exact orbit from (i, u) at r; None at a corner."""
    out = LETTERS[i]
    while u[ORIENTED[i]] > 0 > u[_third(i)] and u[i]:
        if len(out) == n:
            return out
        w = cross(u, cross(E[i], u))
        j = next(m for m in range(3) if m != i and w[m] < 0)
        u = cross(cross(u, E[j]), tuple(sum(a * b for a, b in zip(row, w)) for row in collisions_at(r)[j]))
        u, i = tuple(x / max(abs(y) for y in u) for x in u), j          # a positive factor: the same state
        out += LETTERS[i]
    return None


def exhibited(w: str, skip: int) -> bool:
    """An exact orbit whose contacts c_skip, c_(skip+1), ... spell w (u in {±1, ±2, ±3}³, a few r)."""
    rs = (Fraction(1, 2), Fraction(1, 5), Fraction(4, 5))
    for i, s, r, a, b, c in product(range(3), (1, -1), rs, range(1, 4), range(1, 4), range(1, 4)):
        u = [0, 0, 0]
        u[i], u[ORIENTED[i]], u[_third(i)] = s * a, b, -c
        found = orbit(i, tuple(u), r, skip + len(w))
        if found is not None and found[skip:] == w:
            return True
    return False


def _holds(F, w: str) -> bool:
    """A formula of patterns (words of a, b, c and _, any letter) on the window w."""
    if F[0] == "name":
        if len(F[1]) != len(w) or set(F[1]) - set("abc_"):
            raise Undefined(f"{F[1]}: not a pattern of {len(w)} letters a, b, c, _")
        return all(x in ("_", y) for x, y in zip(F[1], w))
    if F[0] == "not":
        return not _holds(F[1], w)
    if F[0] in ("and", "or", "implies", "iff"):
        a, b = _holds(F[1], w), _holds(F[2], w)
        return {"and": a and b, "or": a or b, "implies": not a or b, "iff": a == b}[F[0]]
    raise Undefined("windows(F): F is made of patterns, not, and, or, implies, iff")


def windows(ctx, F) -> bool:
    """Every window c_k ... c_(k+n-1) (k ≥ 1) of every orbit off the corners satisfies F (n letters)."""
    first = F
    while first[0] != "name":
        first = first[1]
    bad = sorted(w for w in words(len(first[1])) if not _holds(F, w))
    if not bad:
        return True
    if any(exhibited(w, 1) for w in bad):
        return False
    raise NotVerified(f"the step lemmas allow the window {bad[0]}, and no exact orbit was found with it")


def concatenation(ctx, *blocks) -> bool:
    """The pattern c_1 c_2 ... of every orbit off the corners (c_0 the contact of its initial state) is
    a concatenation of the blocks: every path's word parsed, the block begun kept with the state."""
    B = [b[1] for b in blocks if b[0] == "name" and b[1] and not set(b[1]) - set("abc")]
    if len(B) != len(blocks) or any(x != y and y.startswith(x) for x in B for y in B):
        raise Undefined("concatenation(B, ...): words of a, b, c, none the beginning of another")
    seen: set = set()
    todo = [(c, "", LETTERS[c[0]]) for c in graph()]          # (state, block begun, c_0 c_1 ... so far)
    while todo:
        cone, begun, spelt = todo.pop(0)
        j, signs = graph()[cone]
        spelt, begun = spelt + LETTERS[j], begun + LETTERS[j]
        if not any(b.startswith(begun) for b in B):
            if exhibited(spelt, 0):
                return False
            raise NotVerified(f"the step lemmas allow the pattern {spelt[1:]}…, and no exact orbit was found")
        for s in signs:
            key = ((j, s), "" if begun in B else begun)
            if key not in seen:
                seen.add(key)
                todo.append((*key, spelt))
    return True


def endless(ctx) -> bool:
    """Every step lemma holds: each cone is mapped into the cones of the next contact (or a corner)."""
    return len(graph()) == 6


PREDICATES.update(windows=windows, concatenation=concatenation, endless=endless)
