"""The statement language: a tokenizer and a Pratt parser from text to a tree of tuples.

Formulas are read as written in statements/*.txt (docs/statements.md): arithmetic on numbers,
polynomials, vectors and matrices (``+ - * / ^``, ``·`` a product, ``∧`` the cross product,
``√`` a square root, ``M[i,j]`` an entry), intervals ``]a, b[``, ``[a, b]``, ..., comparisons
(``= ≠ < > ≤ ≥ ≈ ~``), ``and or not implies iff``, and the binders ``forall ...: F`` and
``{r in I : F}``.  Nothing is evaluated here, and no Python code is ever run on the text.
"""
from __future__ import annotations

import re

_TOKEN = re.compile(r"""
    (?P<space>\s+)
  | (?P<str>"[^"]*")
  | (?P<num>\d+(?:\.\d+)?)
  | (?P<name>[^\W\d]\w*[′']*)
  | (?P<op>implies|iff|and|or|not|forall|mod|in|∞|π|≤|≥|≠|≈|∧|·|√|⊆|−|<=|>=|!=|[-+*/^()\[\],:;<>=~{}|])
""", re.VERBOSE)

_WORDS = {"and", "or", "not", "implies", "iff", "forall", "mod", "in"}
_ALIAS = {"−": "-", "<=": "≤", ">=": "≥", "!=": "≠"}
COMPARISONS = ("=", "≠", "<", ">", "≤", "≥", "≈", "~", "⊆", "in")


class Syntax(ValueError):
    """The text is not a formula of the language (the message says where)."""


def tokens(text: str) -> list[tuple[str, str]]:
    """(kind, text) pairs; kinds "num", "name", "op", and a final ("end", "")."""
    out, at = [], 0
    while at < len(text):
        m = _TOKEN.match(text, at)
        if m is None:
            raise Syntax(f"unexpected character {text[at]!r} at {text[at:at + 20]!r}")
        at = m.end()
        kind = m.lastgroup
        word = m.group(kind)
        if kind == "space":
            continue
        if kind == "name" and word in _WORDS:
            kind = "op"
        out.append((kind, _ALIAS.get(word, word)))
    out.append(("end", ""))
    return out


_INFIX = {"iff": 1, "implies": 2, "or": 3, "and": 4, "+": 20, "-": 20, "*": 30, "/": 30, "·": 30, "∧": 30, "^": 50}


class Parser:
    """A Pratt parser over :func:`tokens`."""

    def __init__(self, text: str):
        self.text, self.toks, self.at = text, tokens(text), 0

    def peek(self, k: int = 0) -> tuple[str, str]:
        return self.toks[min(self.at + k, len(self.toks) - 1)]

    def next(self) -> tuple[str, str]:
        tok = self.peek()
        self.at += 1
        return tok

    def expect(self, word: str) -> None:
        kind, got = self.next()
        if got != word:
            raise Syntax(f"expected {word!r}, found {got or 'the end'!r} in {self.text!r}")

    def whole(self):
        """The text as one formula (nothing left over)."""
        tree = self.formula()
        if self.peek()[0] != "end":
            raise Syntax(f"unexpected {self.peek()[1]!r} in {self.text!r}")
        return tree

    # ---------------------------------------------------------------- formulas
    def formula(self, power: int = 0, brackets: bool = True):
        """A formula or an expression: prefix, then infix operators binding tighter than ``power``."""
        left = self.prefix(brackets)
        while True:
            kind, op = self.peek()
            if kind != "op":
                return left
            if op in COMPARISONS and power < 10:
                left = self.comparison(left, brackets)
                continue
            if op == "mod" and power < 10:
                self.next()
                left = ("mod", left, self.formula(10, brackets))
                continue
            if op == "√" and power < 30:                     # 2√6: a number times a root
                left = ("bin", "*", left, self.formula(30, brackets))
                continue
            bp = _INFIX.get(op)
            if bp is None or bp <= power:
                if op == "[" and brackets and power < 60:
                    left = self.index(left)
                    continue
                return left
            self.next()
            right = self.formula(bp - 1 if op in ("^", "implies") else bp, brackets)   # right-associative
            left = (op, left, right) if op in ("and", "or", "implies", "iff") else ("bin", op, left, right)

    def comparison(self, left, brackets: bool):
        """a op b [op c ...]: a chain of comparisons (each pair compared)."""
        ops, items = [], [left]
        while self.peek()[0] == "op" and self.peek()[1] in COMPARISONS:
            ops.append(self.next()[1])
            items.append(self.formula(10, brackets))
        return ("cmp", tuple(ops), tuple(items))

    def index(self, left):
        self.expect("[")
        idx = [self.formula()]
        while self.peek()[1] == ",":
            self.next()
            idx.append(self.formula())
        self.expect("]")
        return ("index", left, tuple(idx))

    def prefix(self, brackets: bool):
        kind, tok = self.next()
        if kind == "num":
            return ("num", tok)
        if kind == "str":
            return ("str", tok[1:-1])
        if kind == "name":
            if self.peek()[1] == "(":
                self.next()
                return ("call", tok, tuple(self.items(")")))
            return ("name", tok)
        if tok == "-":
            return ("neg", self.formula(40, brackets))
        if tok == "+":
            return self.formula(40, brackets)
        if tok == "not":
            return ("not", self.formula(4, brackets))
        if tok == "√":
            return ("sqrt", self.formula(45, brackets))
        if tok in ("∞", "π"):
            return ("const", tok)
        if tok == "(":
            items = self.items(")")
            return items[0] if len(items) == 1 else ("tuple", tuple(items))
        if tok == "]":
            return self.interval(False)
        if tok == "[":
            if self.peek()[1] == "[":
                rows = self.items("]")
                if not all(row[0] == "list" for row in rows):
                    raise Syntax(f"a matrix is a list of rows [[...], ...] in {self.text!r}")
                return ("matrix", tuple(row[1] for row in rows))
            return self.interval(True)
        if tok == "{":
            return self.braces()
        if tok == "forall":
            binders = self.binders()
            self.expect(":")
            return ("forall", binders, self.formula())
        raise Syntax(f"unexpected {tok or 'end'!r} in {self.text!r}")

    def items(self, close: str) -> list:
        """Comma-separated formulas up to ``close`` (a row ``[a, b]`` inside a matrix as ("list", ...))."""
        out = []
        if self.peek()[1] == close:
            self.next()
            return out
        while True:
            if close == "]" and self.peek()[1] == "[":
                self.next()
                out.append(("list", tuple(self.items("]"))))
            else:
                out.append(self.formula())
            kind, tok = self.next()
            if tok == close:
                return out
            if tok != ",":
                raise Syntax(f"expected ',' or {close!r}, found {tok or 'the end'!r} in {self.text!r}")

    def interval(self, lo_closed: bool):
        """]a, b[ and its closed variants: the ends are read without indexing (a [ closes)."""
        lo = self.formula(0, brackets=False)
        self.expect(",")
        hi = self.formula(0, brackets=False)
        kind, tok = self.next()
        if tok not in ("[", "]"):
            raise Syntax(f"an interval ends with [ or ], found {tok or 'the end'!r} in {self.text!r}")
        return ("interval", lo, hi, lo_closed, tok == "]")

    def binders(self) -> tuple:
        """NAME in SET | NAME = EXPR, separated by commas."""
        out = []
        while True:
            kind, name = self.next()
            if kind != "name":
                raise Syntax(f"a binder starts with a variable, not {name!r} in {self.text!r}")
            kind, op = self.next()
            if op not in ("in", "="):
                raise Syntax(f"a binder is 'NAME in SET' or 'NAME = EXPR', found {op!r} in {self.text!r}")
            out.append((name, op, self.formula(10)))
            if self.peek()[1] != ",":
                return tuple(out)
            self.next()

    def braces(self):
        """{r in I : F} (a set of r), {a, b} (a finite set of numbers), {} (the empty set)."""
        if self.peek()[1] == "}":
            self.next()
            return ("finite", ())
        if self.peek()[0] == "name" and self.peek(1)[1] == "in":
            binders = self.binders()
            self.expect(":")
            body = self.formula()
            self.expect("}")
            return ("setof", binders, body)
        return ("finite", tuple(self.items("}")))


def parse(text: str):
    """The tree of one formula or expression."""
    return Parser(text).whole()
