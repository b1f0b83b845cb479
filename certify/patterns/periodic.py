"""Periodic collision words as the user writes them: reading, validation, normal forms.

A period is written over the letters a, b, c (collisions of the pairs 1-2, 2-3, 3-4),
plainly (``ababcb``), with powers of groups (``(ab)^3(cb)^3``, ``(a b)^2 c b``) and
with ``[ac]`` (or ``[ca]``) for a simultaneous a and c collision.  Internally a word is
a plain string; the simultaneous collision is the one letter ``s`` (shown as ``[ac]``
again by :func:`show`).  A letter ``s`` typed by the user is not accepted.

Which system a word belongs to (:func:`system_of`):

* ``four``: a and c both occur (four particles, gaps p_1, p_2, p_3, 3x3 matrices);
* ``three``: only a and b, or only c and b (three particles, gaps p_1, p_2, 2x2
  matrices; the word over c, b is its mirror image, particles numbered from the right);
* ``symmetric``: only [ac] and b (the symmetric four-particle system of L2, p_1 = p_3,
  q_1 = q_3, reduced to two gaps).

Validation (:func:`validate`) raises :class:`~certify.errors.UsageError` with one line:
an empty word, other letters, two equal letters adjacent (cyclically: the word is a
period), [ac] mixed with single a or c collisions, aca or cac (cyclically: impossible
by Proposition 4.4 of the paper, l. 997), a proper power of a shorter word (the root is
named).

Normal form (:func:`normal_form`): a period is a cyclic word, and the mirror a<->c
(particles numbered from the right) maps orbits to orbits, so every rotation and the
mirror of a word describe the same periodic orbits.  The normal form is the
lexicographically least (a < b < c) rotation or mirrored rotation that starts with the
first-gap collision (a, or [ac]) and ends with b: the paper's normalisation
q(0) = (-1, u, …), p(0) = (1, 0, …) (l. 270-280).  For a four-particle word such a
rotation exists: if every a were preceded by c, and every c by a, the word would
contain aca.
"""
from __future__ import annotations

import re

from certify.errors import UsageError

SIM = "s"                                   # the internal letter of [ac]
SYSTEMS = ("four", "three", "symmetric")
MIRROR = str.maketrans("ac", "ca")
_GROUP = re.compile(r"\(([^()]*)\)\s*\^\s*(\d+)")
_POWER = re.compile(r"(\[[^\]]*\]|[A-Za-z])\s*\^\s*(\d+)")
MAX_LENGTH = 400


def show(word: str) -> str:
    """The internal word as the user writes it: ``s`` back to ``[ac]``."""
    return word.replace(SIM, "[ac]")


def compact(word: str) -> str:
    """A short spelling with powers of repeated blocks, e.g. ``(ab)^3(cb)^3``; the
    plain word when nothing repeats."""
    out, i = [], 0
    while i < len(word):
        best = (1, 1)
        for size in range(1, (len(word) - i) // 2 + 1):
            block, k = word[i:i + size], 1
            while word[i + k * size:i + (k + 1) * size] == block:
                k += 1
            if k > 1 and k * size > best[0] * best[1] and size <= 6:
                best = (size, k)
        size, k = best
        if k > 1:
            out.append(f"({show(word[i:i + size])})^{k}" if size > 1 else f"{show(word[i])}^{k}")
            i += size * k
        else:
            out.append(show(word[i]))
            i += 1
    return "".join(out)


def parse(text: str) -> str:
    """The internal word of a written period: powers expanded, ``[ac]`` as ``s``,
    spaces ignored.  Raises UsageError on anything else (nothing is guessed)."""
    if not isinstance(text, str):
        raise UsageError(f"invalid pattern word {text!r}: a text over a, b, c")
    t = "".join(text.split())
    if not t:
        raise UsageError("invalid pattern word: the word is empty")
    if len(t) > 10 * MAX_LENGTH:
        raise UsageError(f"invalid pattern word: longer than {MAX_LENGTH} collisions")
    _check_powers(t, text)
    for _ in range(20):                                   # nested groups, innermost first
        new = _GROUP.sub(lambda m: m.group(1) * _count(m.group(2), text), t)
        if new == t:
            break
        t = new
        if len(t) > 10 * MAX_LENGTH:
            raise UsageError(f"invalid pattern word {text.strip()!r}: more than {MAX_LENGTH} collisions "
                             f"(a word has at most {MAX_LENGTH} letters)")
    t = _POWER.sub(lambda m: m.group(1) * _count(m.group(2), text), t)
    typed = {SIM} & set(t)                                # the internal letter is not for users
    t = re.sub(r"\[(ac|ca)\]", SIM, t.replace(SIM, ""))
    bad = sorted((set(t) - set("abc" + SIM)) | typed)
    if bad:
        raise UsageError(f"invalid pattern word {text.strip()!r}: unexpected {', '.join(repr(b) for b in bad)}; "
                         "use the letters a, b, c, powers (…)^n and [ac] for a simultaneous a and c collision")
    if not t:
        raise UsageError(f"invalid pattern word {text.strip()!r}: the word is empty")
    if len(t) > MAX_LENGTH:
        raise UsageError(f"invalid pattern word {text.strip()!r}: {len(t)} collisions, more than {MAX_LENGTH}")
    return t


def _check_powers(t: str, text: str) -> None:
    """One clear line for a misplaced power or parenthesis (before any expansion)."""
    where = f"invalid pattern word {text.strip()!r}"
    negative = re.search(r"\^-(\d*)", t)
    if negative:
        raise UsageError(f"{where}: negative power -{negative.group(1)}; a power is a whole number n ≥ 1")
    if re.search(r"\^(?!\d)", t):
        raise UsageError(f"{where}: '^' must be followed by a whole number n ≥ 1, as in (ab)^3")
    depth = 0
    for ch in t:
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if depth < 0:
            break
    if depth != 0:
        raise UsageError(f"{where}: unbalanced parentheses")
    bare = re.search(r"\(([^()]*)\)(?!\^)", t)
    if bare:
        raise UsageError(f"{where}: the group ({bare.group(1)}) has no power: write ({bare.group(1)})^n, "
                         "or leave out the parentheses")


def _count(digits: str, text: str) -> int:
    n = int(digits)
    if n < 1:
        raise UsageError(f"invalid pattern word {text.strip()!r}: a power must be at least 1")
    if n > MAX_LENGTH:
        raise UsageError(f"invalid pattern word {text.strip()!r}: the power {n} is too large (a word has at most "
                         f"{MAX_LENGTH} letters)")
    return n


def primitive_root(word: str) -> tuple[str, int]:
    """(root, k) with word = root^k and root not itself a proper power."""
    n = len(word)
    for size in range(1, n + 1):
        if n % size == 0 and word[:size] * (n // size) == word:
            return word[:size], n // size
    return word, 1                                          # pragma: no cover (size = n always matches)


def system_of(word: str) -> str:
    """``four``, ``three`` or ``symmetric`` (see the module docstring); the word is valid."""
    if SIM in word:
        return "symmetric"
    return "four" if ("a" in word and "c" in word) else "three"


def _cyclic(word: str, k: int) -> list[str]:
    """The k-letter factors of the cyclic word."""
    w = word * (k // len(word) + 2)
    return [w[i:i + k] for i in range(len(word))]


def validate(word: str, written: str | None = None) -> str:
    """Raise UsageError (one line) unless ``word`` (internal) is an admissible period;
    return its system."""
    name = repr(written.strip() if written is not None else show(word))
    if not word:
        raise UsageError("invalid pattern word: the word is empty")
    if set(word) - set("abc" + SIM):
        raise UsageError(f"invalid pattern word {name}: use the letters a, b, c and [ac]")
    for pair in _cyclic(word, 2):
        if pair[0] == pair[1]:
            where = "" if len(word) > 1 else " (a one-letter period repeats itself)"
            raise UsageError(f"invalid pattern word {name}: two equal letters {show(pair)!r} are adjacent "
                             f"(cyclically){where}: the same pair cannot collide twice in a row")
    if SIM in word and ("a" in word or "c" in word):
        raise UsageError(f"invalid pattern word {name}: [ac] is read only in the symmetric system, a word over "
                         "[ac] and b; it cannot be mixed with single a or c collisions")
    if "b" not in word:
        raise UsageError(f"invalid pattern word {name}: without b the pairs never interact (a word with a but no c "
                         "is read as the three-particle system only when it alternates a and b)")
    for bad in ("aca", "cac"):
        if bad in _cyclic(word, 3):
            raise UsageError(f"invalid pattern word {name}: it contains {bad} (cyclically), impossible by "
                             "Proposition 4.4 of the paper (l. 997)")
    root, k = primitive_root(word)
    if k > 1:
        raise UsageError(f"invalid pattern word {name}: it is a proper power of {show(root)!r} "
                         f"(({show(root)})^{k}); a period is primitive, analyse {show(root)!r}")
    return system_of(word)


def normal_form(word: str) -> tuple[str, str]:
    """(normal, explanation): the canonical representative of the orbit of ``word``
    (internal, valid) under rotations and the mirror a<->c; see the module docstring.

    >>> normal_form("bcbaba")[0], normal_form("cbab")[0]
    ('ababcb', 'abcb')
    >>> normal_form("cbab")[1].split(":")[0]
    'cbab → abcb'
    """
    system = validate(word)
    first = SIM if system == "symmetric" else "a"
    candidates = []
    for mirrored in (False, True):
        w = word.translate(MIRROR) if mirrored else word
        for k in range(len(w)):
            v = w[k:] + w[:k]
            if v[0] == first and v[-1] == "b":
                candidates.append((v, k, mirrored))
    normal, k, mirrored = min(candidates)
    if normal == word:
        why = "already in normal form"
    else:
        steps = []
        if mirrored:
            steps.append("mirrored a<->c (the particles numbered from the right: the same orbits, seen in a mirror)")
        if k:
            steps.append(f"rotated by {k} (a period read from another collision: the same periodic orbit)")
        why = "; ".join(steps) or "the same word"
    rule = {"four": "the least rotation or mirrored rotation starting with a and ending with b",
            "three": "three particles (a and b only); the rotation starting with a",
            "symmetric": "the symmetric system p_1 = p_3; the rotation starting with [ac]"}[system]
    return normal, f"{show(word)} → {show(normal)}: {why} ({rule})"


def read(text: str) -> tuple[str, str, str]:
    """(normal, system, explanation) of a written period; UsageError on a bad one."""
    word = parse(text)
    system = validate(word, text)
    normal, why = normal_form(word)
    return normal, system, why
