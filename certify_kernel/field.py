"""The real roots of a polynomial P(r0, λ) and the sign of another polynomial at each, for a
real algebraic r0: exact arithmetic in Q[r]/(m), m the polynomial of r0 (m(r0) = 0, so
reducing a coefficient modulo m keeps its value at r0), with no inverse needed.  Polynomials
in λ are lists of polynomials in r (lowest degree first, both ways)."""
from __future__ import annotations

from fractions import Fraction

from .poly import add, bderiv, bmul, divmod_, integer_primitive, mul, scale, sub
from .sturm import Algebraic, changes


class AtR0:
    """Signs at r0 of polynomials in r, and Sturm–Tarski queries in λ over Q(r0)."""

    def __init__(self, r0: Algebraic):
        self.r0 = r0
        while not r0.rational and r0.hi - r0.lo > Fraction(1, 2 ** 60):   # cheap enclosures decide most signs
            r0.bisect()

    def reduce(self, c: list) -> list:
        """c mod m: the same value at r0 (m(r0) = 0)."""
        return c if self.r0.rational or len(c) < len(self.r0.p) else divmod_(c, self.r0.p)[1]

    def sign(self, c: list) -> int:
        """sign c(r0) (:meth:`Algebraic.sign_of`)."""
        return self.r0.sign_of(self.reduce(c))

    def trim(self, P: list) -> list:
        """P without its leading coefficients that vanish at r0 (the same P(r0, λ))."""
        P = [self.reduce(c) for c in P]
        while P and self.sign(P[-1]) == 0:
            P.pop()
        return P

    def mul(self, P: list, Q: list) -> list:
        """P·Q in Q[r][λ], coefficients reduced modulo m."""
        return [self.reduce(c) for c in bmul(P, Q)]

    def remainder(self, A: list, B: list) -> list:
        """A positive multiple at r0 of −rem(A, B) in Q(r0)[λ] (B trimmed, lc B(r0) ≠ 0): the
        pseudo-division lc(B)^k·A = Q·B + R, so −rem = −R / lc(B)^k, of the sign of −R·sign(lc B)^k."""
        R, lb, k = list(A), B[-1], 0
        while len(R) >= len(B):
            c, shift = R[-1], len(R) - len(B)
            R = [mul(x, lb) for x in R]
            for j, y in enumerate(B):
                R[shift + j] = sub(R[shift + j], mul(c, y))
            R, k = self.trim(R[:-1]), k + 1
        s = -(self.sign(lb) ** k)
        return _positive_content_free([scale(x, s) for x in R])

    def sequence(self, P: list, Q: list) -> list:
        """The signed remainder sequence SRemS(P, Q) over Q(r0), each term up to a positive factor."""
        seq = [_positive_content_free(self.trim(P)), _positive_content_free(self.trim(Q))]
        while seq[-1]:
            seq.append(self.remainder(seq[-2], seq[-1]))
        return seq[:-1]

    def variations(self, seq: list, x) -> int:
        """Sign changes of the sequence at λ = x (rational), or at ±∞ ("+inf", "-inf": the signs
        of the leading terms), zeros dropped."""
        return changes(self.sign(P[-1]) * (-1 if x == "-inf" and len(P) % 2 == 0 else 1) if isinstance(x, str)
                       else self.at(P, x) for P in seq)

    def taq(self, Q: list, P: list, a, b, seq=None) -> int:
        """Σ sign Q(r0, λ) over the distinct roots λ of P(r0, λ) in ]a, b[ (a, b rational or
        ±∞, not roots): the Sturm–Tarski theorem, Var(SRemS(P, P'·Q); a) − Var(...; b), over
        the real closed field R ⊃ Q(r0) (Basu–Pollack–Roy, Thm 2.73; P need not be square-free).
        Q = 1 (``seq`` given: SRemS(P, P')) is Sturm's theorem, the number of distinct roots."""
        if seq is None:
            seq = self.sequence(P, self.mul(bderiv(P), Q))
        return self.variations(seq, a) - self.variations(seq, b)

    def roots(self, P: list) -> tuple[list, list]:
        """SRemS(P, P') and the distinct real roots of P(r0, λ), largest first, as intervals
        [a, b] holding one each in ]a, b[: the count on ]−∞, ∞[ (Sturm), a power of 2 B with all
        of them in ]−B, B[, then bisection at rationals that are not roots."""
        P = self.trim(P)
        if not P:
            raise ValueError("the polynomial vanishes identically at r0")
        seq = self.sequence(P, bderiv(P))
        total, B = self.taq([], P, "-inf", "+inf", seq), Fraction(1)
        while self.at(P, B) == 0 or self.at(P, -B) == 0 or self.taq([], P, -B, B, seq) != total:
            B *= 2
        out, todo = [], [(-B, B, total)]
        while todo:
            lo, hi, n = todo.pop()
            if n == 1:
                out.append([lo, hi])
            elif n > 1:
                mid = (lo + hi) / 2
                while self.at(P, mid) == 0:      # a rational in ]lo, hi[ that is not a root
                    mid = (mid + hi) / 2
                left = self.taq([], P, lo, mid, seq)
                todo += [(lo, mid, left), (mid, hi, n - left)]
        return seq, sorted(out, reverse=True)

    def at(self, P: list, x) -> int:
        """sign P(r0, x) for a rational x (Horner's rule in λ gives P(r, x) ∈ Q[r])."""
        out: list = []
        for c in reversed(P):
            out = add(scale(out, Fraction(x)), c)
        return self.sign(out)

    def branches(self, P: list) -> list:
        """The real roots of P(r0, λ), largest first, each repeated by its multiplicity: 1 when
        the last term of SRemS(P, P') (gcd(P, P') at r0) is constant in λ, else the least k
        with P^(k) ≠ 0 there, each tested by a Tarski query on the root's interval."""
        seq, out = self.roots(P)
        if len(seq[-1]) == 1:
            return out
        mult = []
        for iv in out:
            D, k = bderiv(P), 1
            while self.taq(D, P, *iv) == 0:
                D, k = bderiv(D), k + 1
            mult += [iv] * k
        return mult


def _positive_content_free(P: list) -> list:
    """P divided by the positive rational content of its coefficients (a positive factor
    changes no sign)."""
    flat = integer_primitive([x for c in P for x in c])     # a positive multiple: igcd ≥ 0
    it = iter(Fraction(x) for x in flat)
    return [[next(it) for _ in c] for c in P]

