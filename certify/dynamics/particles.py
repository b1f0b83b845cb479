"""Four particles on a line in absolute coordinates, exactly (fmpq).

The state is x = (x1, x2, x3, x4), the positions (x1 <= x2 <= x3 <= x4), and
v = (v1, v2, v3, v4), the velocities; r in ]0, 1[ is the restitution coefficient,
the masses are equal.  Between collisions x moves as x + t v (l. 155-156); at a
collision of the pair i, i+1 (a: 1-2, b: 2-3, c: 3-4) the velocities follow the law
of l. 158-163 (:func:`certify.dynamics.model.collide_particles`).

Which pair collides next, and whether collisions tie, is decided by the relative
simulator on p = (x2 - x1, x3 - x2, x4 - x3), q = (v2 - v1, v3 - v2, v4 - v3)
(:func:`certify.dynamics.simulate.next_collision`), one decision logic for both; the state
itself is moved here in absolute coordinates, with the absolute law, so that the
two simulators are independent computations of the same orbit (tests compare them).
A simultaneous a and c is one event "ac", both laws applied (they commute, l. 240);
three or four particles meeting at one point is a multiple collision, where the
law is undefined (l. 185): the run stops there (``History.stop == "triple"``).

Both outer pairs close at speed 1 and meet at t = 1 ("ac"); with r = 1/2, h = 3/4,
v becomes (1/4, 3/4, -3/4, -1/4), and the gap x3 - x2 = 2 closes at speed 3/2 after
4/3, at t = 7/3:

>>> h = evolve([0, 1, 3, 4], [1, 0, 0, -1], "1/2", 2)
>>> h.word, [str(c.t) for c in h.collisions], [str(z) for z in h.collisions[0].v]
('[ac]b', ['1', '7/3'], ['1/4', '3/4', '-3/4', '-1/4'])
"""
from __future__ import annotations

import decimal
import re
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from fractions import Fraction

import flint

from certify.algebra.poly import Q, to_fmpq
from certify.errors import UsageError

from . import simulate as sim
from .model import alphabet, collide_particles

NUMBER = re.compile(r"[+-]?(\d+(/\d+)?|\d+\.\d*|\.\d+)")
PROGRESS_STEPS = 200          # at most this many progress reports per run


# --- the datum -----------------------------------------------------------------

def rational(value, name: str) -> flint.fmpq:
    """``value`` as an exact rational: an fmpq, int, Fraction, or a string such as
    "-2", "3/7" or "0.25" (read exactly, as 1/4).  Floats are refused (not exact)."""
    if isinstance(value, (flint.fmpq, flint.fmpz, int, Fraction)) and not isinstance(value, bool):
        return to_fmpq(value)
    text = value.strip() if isinstance(value, str) else None
    if text is None or not NUMBER.fullmatch(text):
        raise UsageError(f"{name} = {value!r} is not an exact number: "
                         "use an integer (-2), a fraction (3/7) or a decimal (0.25)")
    try:
        return to_fmpq(text)
    except ZeroDivisionError:
        raise UsageError(f"{name} = {value!r} divides by zero") from None


def check_r(value) -> flint.fmpq:
    """The restitution coefficient: a rational in ]0, 1[; UsageError otherwise."""
    r = rational(value, "r")
    if not 0 < r < 1:
        raise UsageError(f"the restitution coefficient r = {r} is outside ]0,1[")
    return r


COUNTS = {3: "three", 4: "four", 5: "five", 6: "six", 7: "seven", 8: "eight"}


def count_word(n: int) -> str:
    """"four", "five", ... (digits beyond eight)."""
    return COUNTS.get(n, str(n))


def check_four(values, name: str, count: int = 4) -> tuple:
    """Exactly four (``count``) rationals name1..name4; UsageError otherwise."""
    if isinstance(values, (str, bytes)) or not isinstance(values, Sequence):
        raise UsageError(f"{name} must be a sequence of {count_word(count)} numbers, got {values!r}")
    if len(values) != count:
        names = " ".join(f"{name}{i}" for i in range(1, count + 1)) if count <= 8 else f"{name}1 ... {name}{count}"
        raise UsageError(f"expected {count_word(count)} values {names}, got {len(values)}")
    return tuple(rational(z, f"{name}{i}") for i, z in enumerate(values, 1))


def check_positions(values, count: int = 4) -> tuple:
    """Four (``count``) positions, ordered x1 <= x2 <= x3 <= x4 (the particles are labelled
    from left to right, l. 150); UsageError otherwise."""
    x = check_four(values, "x", count)
    for i in range(count - 1):
        if x[i] > x[i + 1]:
            order = " <= ".join(f"x{k}" for k in range(1, count + 1)) if count <= 8 else "x1 <= x2 <= ..."
            raise UsageError(f"the positions must satisfy {order} (particles "
                             f"labelled left to right): x{i + 1} = {x[i]} > x{i + 2} = {x[i + 1]}")
    return x


def check_count(n) -> int:
    """The number of collisions: an integer >= 1; UsageError otherwise."""
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise UsageError(f"the number of collisions must be a positive integer, got {n!r}")
    return n


# --- the orbit -----------------------------------------------------------------

@dataclass(frozen=True)
class Collision:
    """One collision event: ``letters`` "a", "b", "c" or "ac" (simultaneous), its
    time ``t``, the positions ``x`` then (each colliding pair exactly in contact)
    and the velocities ``v`` right after it (post-collisional, l. 171)."""

    letters: str
    t: flint.fmpq
    x: tuple
    v: tuple


@dataclass(frozen=True)
class Meeting:
    """A multiple collision: the ``particles`` (three or four, consecutive) meet at
    the time ``t`` at the positions ``x``; ``v`` are the velocities just before."""

    particles: tuple[int, ...]
    t: flint.fmpq
    x: tuple
    v: tuple


@dataclass
class History:
    """The orbit of the datum (``x``, ``v``, ``r``): the ``collisions`` in time order.
    ``stop`` says why it ended: "n" (all requested collisions done), "separate" (no
    pair approaches any more: no collision will ever come) or "triple" (three or four
    particles meet, described by ``triple``)."""

    x: tuple
    v: tuple
    r: flint.fmpq
    collisions: list[Collision] = field(default_factory=list)
    stop: str = "n"
    triple: Meeting | None = None

    @property
    def word(self) -> str:
        """The collision word, a simultaneous a and c written [ac] as in certify.dynamics.simulate."""
        return "".join(c.letters if len(c.letters) == 1 else f"[{c.letters}]"
                       for c in self.collisions)


def differences(z: Sequence) -> tuple:
    """(z2 - z1, z3 - z2, z4 - z3) (and on for N particles): p from x, q from v."""
    return tuple(z[i + 1] - z[i] for i in range(len(z) - 1))


def advance(x: Sequence, v: Sequence, dt) -> tuple:
    """The free motion (l. 155-156): the positions x + dt v after the time dt."""
    return tuple(xi + dt * vi for xi, vi in zip(x, v))


def evolve(x, v, r, collisions: int,
             progress: Callable[[int, int, str], None] | None = None, particles: int = 4) -> History:
    """At most ``collisions`` collision events from the positions x and velocities v
    (four exact rationals each, x ordered; ``particles`` of them for N particles, the pairs
    a, b, c, d, ... and the next collision by :func:`certify.dynamics.simulate.next_collision_gaps`),
    restitution coefficient r in ]0, 1[.

    Exact: every comparison is decided in fmpq, no rounding anywhere.  The next
    collision is decided by :func:`certify.dynamics.simulate.next_collision` on the differences
    of x and v; x is then moved freely and v changed by the absolute law, for each
    letter of the event.  Invalid data raise UsageError.  ``progress(k, n, label)``,
    e.g. :func:`certify.run.progress.show`, is told about every n/200-th collision and
    called with k = n at the end."""
    alphabet(particles)
    x, v = check_positions(x, particles), check_four(v, "v", particles)
    r, n = check_r(r), check_count(collisions)
    next_collision = sim.next_collision if particles == 4 else sim.next_collision_gaps
    out = History(x, v, r)
    t = Q(0)
    every = max(1, n // PROGRESS_STEPS)
    try:
        for k in range(n):
            if progress is not None and k % every == 0:
                progress(k, n, "collisions")
            try:
                nxt = next_collision(differences(x), differences(v))
            except sim.MultipleCollision as exc:
                out.stop = "triple"
                out.triple = Meeting(exc.particles, t + exc.t, advance(x, v, exc.t), v)
                return out
            if nxt is None:
                out.stop = "separate"
                return out
            letters, dt = nxt
            t, x = t + dt, advance(x, v, dt)
            for letter in letters:
                v = collide_particles(letter, v, r)
            out.collisions.append(Collision(letters, t, x, v))
        return out
    finally:
        if progress is not None:
            progress(n, n, "")


# --- printing ------------------------------------------------------------------

def decimal_digits(z: flint.fmpq, digits: int = 20) -> tuple[str, bool]:
    """(text, exact): z rounded to ``digits`` significant digits, exact=True when no
    rounding happened.  The quotient of the exact integers z.p / z.q is correctly
    rounded (half to even) by the decimal module: every printed digit is right."""
    ctx = decimal.Context(prec=digits, rounding=decimal.ROUND_HALF_EVEN,
                          Emin=decimal.MIN_EMIN, Emax=decimal.MAX_EMAX)
    value = ctx.divide(decimal.Decimal(int(z.p)), decimal.Decimal(int(z.q)))
    text = f"{value:f}" if -12 <= value.adjusted() < digits else f"{value:e}"
    return text, not ctx.flags[decimal.Inexact]


def show_time(t: flint.fmpq, digits: int = 20, full: bool = False, width: int = 40) -> str:
    """"= 3/2" or "≈ 1.7222222222222222222 = 31/18": the decimal value, and the exact
    fraction when it is at most ``width`` characters long (always with ``full``)."""
    text, exact = decimal_digits(t, digits)
    fraction = str(t)
    if exact and fraction == text:
        return f"= {text}"
    if full or len(fraction) <= width:
        return f"{'=' if exact else '≈'} {text}   = {fraction}"
    return f"≈ {text}   (a fraction of {len(str(t.p))}/{len(str(t.q))} digits)"


def report_lines(history: History, digits: int = 20, full: bool = False) -> Iterator[str]:
    """The orbit as text: one line per collision (index, letters, time), the word,
    then why it stopped."""
    w = len(str(len(history.collisions)))
    for k, c in enumerate(history.collisions, 1):
        yield f"{k:>{w}}  {c.letters:<2}  t {show_time(c.t, digits, full)}"
    k = len(history.collisions)
    count = f"{k} collision{'' if k == 1 else 's'}"
    yield f"word: {history.word}" if k else "word: (empty)"
    if history.stop == "n":
        yield f"{count} done"
    elif history.stop == "separate":
        yield f"the particles separate after {count}: no pair approaches"
    else:
        m = history.triple
        kind = sim.meeting_kind(len(m.particles))
        where = m.x[m.particles[0] - 1]
        yield (f"{kind} collision of particles {', '.join(map(str, m.particles))} at "
               f"t {show_time(m.t, digits, full)}, x {show_time(where, digits, full)}, "
               f"after {count}: the collision law is undefined there (l. 185)")
