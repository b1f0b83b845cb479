"""The paper's printed conditions, read whole: relations, ranges of r and the few
phrases the paper uses, into SymPy relations and small structured results.

A certificate that checks a printed condition reads it here and evaluates what it
reads against what it has certified (a sign, a sign table, an algebraic number); it
never tests a printed text for one character or one word.  A text this grammar does
not read raises :class:`StatementError`, which makes the certificate FAIL with that
reason: a text is never guessed at.  Exact arithmetic only (SymPy rationals and
surds, :class:`~certify.algebra.algebraic.Algebraic` numbers).

The grammar, after normalisation (``≤ ≥ ≠ − ^ √n |x|`` to ``<= >= != - ** sqrt(n) Abs(x)``)::

    statement   := claim [ "for" range ]
    claim       := chain
                 | [subject ("is" | "lies")] ["then"] comparative
                 | [subject "is"] sign-word
    chain       := expr op expr {op expr}              op: <  >  ≤  ≥  =  ≠
    comparative := ("larger" | "greater" | "smaller" | "less") "than" expr
                 | ("above" | "below") expr
    sign-word   := positive | negative | non-negative | non-positive | zero | non-zero
    range       := a chain in r whose other members are constants, strict:
                   "r < r*", "r > 5-2√6", "0 < r < 5-2√6"  (within the domain ]0, 1[)
    expr        := r, integers, + - * / ** ( ), sqrt(n), Abs(...), and the names the
                   caller declares ("Δ_cp", "cos(φ')", "r*", "q", ...): nothing else

    count       := ("infinitely" | "finitely") "many" noun
    extent      := "a prefix" | "the beginning" | "the whole"
    product-eq  := word ("=" | "≠") word, words over the caller's capitals   ("AC = CA")
    word-rule   := atom {"," atom} "⇒" atom {"or" atom}
    atom        := ("c_k" | "c_{k+m}") ("=" | "≠") letter   ("c_k = b ⇒ c_{k+2} = b or c_{k+3} = b")
    branch      := "upper" | "middle" | "lower" | "lowest"

A relation is evaluated on certified signs (:meth:`Relation.holds`): each of its
inequalities ``lhs op rhs`` must have ``lhs - rhs`` a non-zero constant multiple of
one quantity whose sign is known; or on certified algebraic numbers
(:meth:`Relation.compare`), when every member is a constant.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

import sympy as sp
from sympy.core.function import AppliedUndef

from certify import caches
from certify.errors import StatementError  # raised here, caught by the runner: the ground floor's

from .algebraic import Algebraic
from .poly import r as R_SYMBOL

OPS = ("<=", ">=", "!=", "<", ">", "=")
_OP_RE = re.compile(r"(<=|>=|!=|==|<|>|=)")
_HOLDS = {"<": lambda s: s < 0, ">": lambda s: s > 0, "<=": lambda s: s <= 0, ">=": lambda s: s >= 0,
          "=": lambda s: s == 0, "!=": lambda s: s != 0}
SHOW = {"<": "<", ">": ">", "<=": "≤", ">=": "≥", "=": "=", "!=": "≠"}
SIGN_WORDS = {"positive": ">", "negative": "<", "non-negative": ">=", "nonnegative": ">=",
              "non-positive": "<=", "nonpositive": "<=", "zero": "=", "non-zero": "!=", "nonzero": "!="}
COMPARATIVES = {"larger": ">", "greater": ">", "smaller": "<", "less": "<", "above": ">", "below": "<"}
BRANCHES = {"upper": 0, "middle": 1, "lower": 2, "lowest": 2}


def normalise(text: str) -> str:
    """The paper's symbols as ASCII operators; spaces collapsed."""
    if not isinstance(text, str):
        raise StatementError(f"a printed condition is a text, not {text!r}")
    t = text.replace("≤", "<=").replace("≥", ">=").replace("≠", "!=").replace("−", "-").replace("^", "**")
    return " ".join(t.split())


# ---------------------------------------------------------------- expressions
@dataclass
class Names:
    """The names a caller declares: printed text -> SymPy expression or Algebraic number.
    Algebraic numbers enter expressions as placeholder symbols with known values."""

    table: dict = field(default_factory=dict)
    values: dict = field(default_factory=dict)          # placeholder Symbol -> Algebraic
    _locals: dict = field(default_factory=dict)
    _pattern: re.Pattern | None = None

    @classmethod
    def of(cls, names: dict | None) -> Names:
        out = cls(dict(names or {}))
        for k, (name, value) in enumerate(out.table.items()):
            key = f"__n{k}"
            if isinstance(value, Algebraic):
                sym = sp.Symbol(f"⟨{name}⟩")
                out.values[sym] = value
                value = sym
            elif isinstance(value, (int, sp.Basic)):
                value = sp.sympify(value)
            else:
                raise TypeError(f"name {name!r}: a SymPy expression or an Algebraic number, not {type(value)}")
            out._locals[key] = value
        if out.table:
            alternatives = sorted(out.table, key=len, reverse=True)
            out._pattern = re.compile(r"(?<![\w'])(" + "|".join(re.escape(normalise(n)) for n in alternatives)
                                      + r")(?![\w'(])")
        return out

    @property
    def allowed(self) -> set:
        out = {R_SYMBOL}
        for v in self._locals.values():
            out |= v.free_symbols
        return out

    def expr(self, text: str) -> sp.Expr:
        """One member of a relation, read strictly: only r, numbers, sqrt, Abs and the declared names."""
        t = text.strip()
        if not t:
            raise StatementError("an empty member")
        keys = {normalise(n): f"__n{k}" for k, n in enumerate(self.table)}
        if self._pattern is not None:
            t = self._pattern.sub(lambda m: keys[m.group(1)], t)
        t = re.sub(r"(\d)\s*√", r"\1*√", t)
        t = re.sub(r"√\s*(\d+)", r"sqrt(\1)", t)
        t = t.replace("√(", "sqrt(")
        t = re.sub(r"\|([^|]+)\|", r"Abs(\1)", t)
        if re.search(r"[√|]", t):
            raise StatementError(f"{text.strip()!r}: unbalanced |…| or a √ without its argument")
        try:
            e = _member(t, tuple(self._locals.items()))
        except (sp.SympifyError, SyntaxError, TypeError, NameError, AttributeError, ValueError) as exc:
            raise StatementError(f"{text.strip()!r} is not an expression ({exc.__class__.__name__})") from None
        if not isinstance(e, sp.Expr) or isinstance(e, (sp.Rel, sp.logic.boolalg.BooleanFunction,
                                                          sp.logic.boolalg.BooleanAtom)):
            raise StatementError(f"{text.strip()!r} is not an expression")
        unknown = e.free_symbols - self.allowed - set(self.values)
        if unknown:
            raise StatementError(f"{text.strip()!r}: unknown name(s) {', '.join(sorted(map(str, unknown)))}")
        bad = [f for f in e.atoms(sp.Function) if isinstance(f, AppliedUndef) or not isinstance(f, sp.Abs)]
        if bad:
            raise StatementError(f"{text.strip()!r}: unknown function {bad[0]}")
        return e


def constant(e: sp.Expr, values: dict | None = None) -> Algebraic:
    """A constant member as an exact algebraic number: a rational, a + b√n, or a
    declared name; anything else is not read."""
    values = values or {}
    if e in values:
        return values[e]
    e = sp.expand(e)
    if e.free_symbols:
        raise StatementError(f"{e} is not a constant")
    if e.is_Rational:
        return Algebraic.rational(sp.Rational(e))
    a, rest = e.as_coeff_Add()
    b, root = rest.as_coeff_Mul()
    if a.is_Rational and b.is_Rational and root.is_Pow and root.exp == sp.S.Half and root.base.is_Integer \
            and root.base > 0:
        return Algebraic.surd(sp.Rational(a), sp.Rational(b), int(root.base))
    raise StatementError(f"{e} is not a rational, nor a + b√n")


# ---------------------------------------------------------------- relations
@dataclass(frozen=True)
class Relation:
    """A printed relation: members m0 op1 m1 op2 m2 … (a chain), read whole."""

    text: str
    members: tuple
    ops: tuple
    values: dict = field(default_factory=dict, compare=False, hash=False)
    texts: tuple = field(default=(), compare=False)        # the members as printed

    def __str__(self) -> str:
        return self.text

    def pairs(self):
        return [(self.members[k], op, self.members[k + 1]) for k, op in enumerate(self.ops)]

    def sympy(self) -> sp.Basic:
        rel = {"<": sp.Lt, ">": sp.Gt, "<=": sp.Le, ">=": sp.Ge, "=": sp.Eq, "!=": sp.Ne}
        return sp.And(*(rel[op](a, b, evaluate=False) for a, op, b in self.pairs()))

    def sign_of(self, d: sp.Expr, known: dict) -> int:
        """The sign of d from the known signs: d must be a non-zero constant multiple
        of one known quantity (or a constant)."""
        d = sp.expand(d)
        if not d.free_symbols:
            return _sign(constant(d, self.values))
        for quantity, s in known.items():
            ratio = sp.cancel(sp.together(d / quantity))
            if not ratio.free_symbols and ratio != 0:
                if s not in (-1, 0, 1):
                    raise StatementError(f"the sign of {quantity} is not certified ({s})")
                return _sign(constant(ratio)) * s
        raise StatementError(f"cannot evaluate {self.text!r}: {d} is not a constant multiple of a certified quantity "
                             f"({', '.join(map(str, known)) or 'none'})")

    def holds(self, known: dict) -> bool:
        """Whether the relation holds when each quantity of ``known`` has the given sign."""
        return all(_HOLDS[op](self.sign_of(a - b, known)) for a, op, b in self.pairs())

    def holds_on(self, quantity: sp.Expr, signs) -> bool:
        """Whether it holds at every sign in ``signs`` (a set from a sign table: a
        non-sign entry such as NO_BRANCH, UNDECIDED or None makes it fail); False on an empty set."""
        signs = set(signs)
        return bool(signs) and signs <= {-1, 0, 1} and all(self.holds({quantity: s}) for s in signs)

    def truth(self, quantity: sp.Expr) -> dict:
        """{sign of ``quantity``: whether the relation holds}, for the signs -1, 0, 1."""
        return {s: self.holds({quantity: s}) for s in (-1, 0, 1)}

    def compare(self) -> bool:
        """Whether it holds when every member is a constant (declared Algebraic
        numbers, rationals, a + b√n): exact comparisons."""
        out = True
        for a, op, b in self.pairs():
            try:
                x, y = constant(a, self.values), constant(b, self.values)
            except StatementError as e:
                raise StatementError(f"cannot evaluate {self.text!r} on numbers: {e}") from None
            out &= _HOLDS[op](_cmp(x, y))
        return out


def _sign(a: Algebraic) -> int:
    return _cmp(a, Algebraic.rational(0))


def _cmp(x: Algebraic, y: Algebraic) -> int:
    return 0 if x == y else (-1 if x < y else 1)


def relation(text: str, names: dict | None = None, subject: str | None = None) -> Relation:
    """A claim (no range) as a :class:`Relation`: a chain, a comparative phrase or a
    sign word; ``subject`` names the quantity a phrase without a subject is about."""
    return _reading(text, _relation, text, names, subject)


@caches.for_a_run
def _member(t: str, names: tuple) -> sp.Expr:
    """``t`` read by SymPy with r, sqrt, Abs and the declared ``names`` (pairs), memoised for
    the run (the same members recur in many statements)."""
    return sp.sympify(t, locals={"r": R_SYMBOL, "sqrt": sp.sqrt, "Abs": sp.Abs, **dict(names)}, rational=True)


def _reading(text, fn, *args):
    """``fn(*args)``, its StatementError prefixed with the whole printed text."""
    try:
        return fn(*args)
    except StatementError as e:
        raise StatementError(f"cannot read {text!r}: {e}") from None


def _relation(text: str, names: dict | None, subject: str | None) -> Relation:
    t = normalise(text)
    N = Names.of(names)
    phrase = (re.fullmatch(r"(?:(?P<subj>.+?) (?:is|lies) )?(?:then )?(?P<word>larger|greater|smaller|less) than "
                           r"(?P<obj>.+)", t)
              or re.fullmatch(r"(?:(?P<subj>.+?) (?:is|lies) )?(?P<word>above|below) (?P<obj>.+)", t))
    if phrase:
        op, lhs, rhs = COMPARATIVES[phrase["word"]], phrase["subj"] or subject, phrase["obj"]
    elif m := re.fullmatch(r"(?:(?P<subj>.+?) is )?(?P<word>[a-z-]+)", t):
        if m["word"] not in SIGN_WORDS:
            raise StatementError(f"{m['word']!r} is not a sign word "
                                 f"({', '.join(SIGN_WORDS)})")
        op, lhs, rhs = SIGN_WORDS[m["word"]], m["subj"] or subject, "0"
    else:
        parts = _OP_RE.split(t)
        if len(parts) < 3:
            raise StatementError("no relation (<, >, ≤, ≥, =, ≠) and no phrase of the grammar")
        members = tuple(N.expr(p) for p in parts[0::2])
        ops = tuple("=" if o == "==" else o for o in parts[1::2])
        return Relation(text, members, ops, N.values, tuple(p.strip() for p in parts[0::2]))
    if lhs is None:
        raise StatementError("a phrase without its subject")
    return Relation(text, (N.expr(lhs), N.expr(rhs)), (op,), N.values, (lhs, rhs))


@dataclass(frozen=True)
class Range:
    """An open interval ]lo, hi[ of r with exact algebraic ends."""

    lo: Algebraic
    hi: Algebraic
    text: str = ""
    ends: tuple = ("", "")          # the ends as printed (or the domain's)

    def __str__(self) -> str:
        """'lo < r < hi' with the printed ends: 'r > 5-2√6' in ]0,1[ is '5-2√6 < r < 1'."""
        return f"{self.ends[0]} < r < {self.ends[1]}"

    def signs(self, intervals) -> set:
        """The signs a polynomial takes on the range, from its exact sign intervals
        [(a, b, sign)] over a larger interval (certify.algebraic.sign_intervals):
        every interval meeting the range, and 0 at every root inside it."""
        out = {sg for a, b, sg in intervals if a < self.hi and b > self.lo}
        out |= {0 for a, b, sg in intervals[:-1] if self.lo < b < self.hi}
        return out


@dataclass(frozen=True)
class Statement:
    """A claim with the range of r where it is claimed (the whole domain when none is printed)."""

    relation: Relation
    range: Range
    text: str

    def __str__(self) -> str:
        return self.text


def range_of(text: str, names: dict | None = None, domain=(0, 1)) -> Range:
    """A strict chain in r with constant other members, within ``domain``."""
    return _reading(text, _range, text, names, domain)


def _range(text: str, names: dict | None, domain) -> Range:
    rel = _relation(text, names, None)
    (lo, lo_text), (hi, hi_text) = ((Algebraic.rational(e), str(e)) for e in domain)
    for k, (a, op, b) in enumerate(rel.pairs()):
        if op not in ("<", ">"):
            raise StatementError(f"the range {text!r}: only strict bounds (<, >) are read")
        if a == R_SYMBOL and b != R_SYMBOL:
            bound, bound_text, below = constant(b, rel.values), rel.texts[k + 1], op == "<"
        elif b == R_SYMBOL and a != R_SYMBOL:
            bound, bound_text, below = constant(a, rel.values), rel.texts[k], op == ">"
        else:
            raise StatementError(f"the range {text!r}: each bound compares r with a constant")
        if below and bound < hi:
            hi, hi_text = bound, bound_text
        elif not below and bound > lo:
            lo, lo_text = bound, bound_text
    if not lo < hi:
        raise StatementError(f"the range {text!r} is empty in ]{domain[0]}, {domain[1]}[")
    return Range(lo, hi, text, (lo_text, hi_text))


def statement(text: str, names: dict | None = None, subject: str | None = None, domain=(0, 1)) -> Statement:
    """``claim [for range]``: the claim as a :class:`Relation`, the range of r as a
    :class:`Range` (the whole ``domain`` when no range is printed)."""
    return _reading(text, _statement, text, names, subject, domain)


def _statement(text: str, names: dict | None, subject: str | None, domain) -> Statement:
    claim, sep, rng = normalise(text).partition(" for ")
    if sep and " for " in rng:
        raise StatementError("two ranges")
    whole = Range(Algebraic.rational(domain[0]), Algebraic.rational(domain[1]), "", tuple(map(str, domain)))
    return Statement(_relation(claim, names, subject), _range(rng, names, domain) if sep else whole, text)


def corrected(text: str, old: str, new: str) -> str | None:
    """A printed text with a stated correction applied (the first ``old`` replaced by
    ``new``); None when the text does not contain ``old``: the correction was stated
    for another text, and a corrected check built on it must fail."""
    return text.replace(old, new, 1) if isinstance(text, str) and old in text else None


# ---------------------------------------------------------------- phrases
@dataclass(frozen=True)
class Count:
    """'infinitely many collisions' / 'finitely many collisions'."""

    infinite: bool
    noun: str


def count(text: str, nouns=("collisions",)) -> Count:
    m = re.fullmatch(r"(infinitely|finitely) many (.+)", normalise(text))
    if not m:
        raise StatementError(f"cannot read {text!r}: expected 'infinitely many …' or 'finitely many …'")
    if m[2] not in nouns:
        raise StatementError(f"cannot read {text!r}: many {m[2]!r}, expected {' or '.join(nouns)}")
    return Count(m[1] == "infinitely", m[2])


EXTENTS = {"a prefix": "prefix", "the beginning": "prefix", "the whole": "whole"}


def extent(text: str) -> str:
    """'a prefix' / 'the beginning' -> 'prefix'; 'the whole' -> 'whole'."""
    t = normalise(text)
    if t not in EXTENTS:
        raise StatementError(f"cannot read {text!r}: expected one of {', '.join(EXTENTS)}")
    return EXTENTS[t]


def branch(text: str) -> int:
    """A branch of the spectrum by the paper's name: 0 upper, 1 middle, 2 lower (lowest)."""
    t = normalise(text)
    if t not in BRANCHES:
        raise StatementError(f"cannot read the branch {text!r}: expected one of {', '.join(BRANCHES)}")
    return BRANCHES[t]


@dataclass(frozen=True)
class ProductEquation:
    """'AC = CA': two products of named matrices, equal or not."""

    lhs: str
    equal: bool
    rhs: str


def product_equation(text: str, alphabet: str = "ABC") -> ProductEquation:
    m = re.fullmatch(r"([A-Z]+)\s*(!=|=)\s*([A-Z]+)", normalise(text))
    if not m or not set(m[1] + m[3]) <= set(alphabet):
        raise StatementError(f"cannot read {text!r}: expected products of {', '.join(alphabet)} joined by = or ≠")
    return ProductEquation(m[1], m[2] == "=", m[3])


@dataclass(frozen=True)
class WordRule:
    """'c_k = a, c_{k+1} = c ⇒ c_{k+2} ≠ a': premises (all) imply one of the conclusions,
    at every position k of a collision word.  Atoms are (offset, letter, equal)."""

    premises: tuple
    conclusions: tuple
    text: str

    @property
    def reach(self) -> int:
        return max(o for o, _, _ in self.premises + self.conclusions)

    def applies(self, word: str, k: int) -> bool:
        return k + self.reach < len(word) and all((word[k + o] == L) == eq for o, L, eq in self.premises)

    def holds_at(self, word: str, k: int) -> bool:
        return any((word[k + o] == L) == eq for o, L, eq in self.conclusions)

    def tally(self, words) -> tuple[int, int]:
        """(positions where the premises hold with a full look-ahead, those where a conclusion holds)."""
        seen = good = 0
        for w in words:
            for k in range(len(w)):
                if self.applies(w, k):
                    seen += 1
                    good += self.holds_at(w, k)
        return seen, good


def word_rule(text: str, letters: str = "abc") -> WordRule:
    t = normalise(text).replace("=>", "⇒")
    given, sep, then = t.partition("⇒")
    if not sep or "⇒" in then:
        raise StatementError(f"cannot read {text!r}: expected premises ⇒ conclusions")

    def atoms(part, joiner):
        out = []
        for a in part.split(joiner):
            m = re.fullmatch(r"c_(?:k|\{k\+(\d+)\})\s*(!=|=)\s*([a-z])", a.strip())
            if not m or m[3] not in letters:
                raise StatementError(f"cannot read {a.strip()!r} in {text!r}: expected c_k or c_{{k+m}} = or ≠ "
                                     f"a letter of {letters}")
            out.append((int(m[1] or 0), m[3], m[2] == "="))
        return tuple(out)
    return WordRule(atoms(given, ","), atoms(then, " or "), text)
