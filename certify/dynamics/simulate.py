"""The relative dynamics of four particles, exact (fmpq) or in balls (arb).

The state is p = (p1, p2, p3), the gaps x_{i+1} - x_i >= 0, and q = (q1, q2, q3),
the relative velocities v_{i+1} - v_i.  Between collisions p moves as p + t q; the
pair i collides when p_i reaches 0, which needs q_i < 0, after the time -p_i/q_i.
The next collision is the smallest such time; at a collision of type a, b, c the
velocities become A q, B q, C q (l. 209-232), and the gap that closed is set to 0
exactly.

Two number systems behind one interface:

* exact: entries are ``flint.fmpq`` (and r is an fmpq).  Every sign and every
  comparison is decided; a and c at exactly the same time is the simultaneous
  collision of the paper (A and C commute, l. 240); b at the same time as a or c
  (or a collision next to particles already in contact) is a multiple collision:
  three or four particles meet, the dynamics is not defined (:class:`MultipleCollision`).
* balls: entries are ``flint.arb`` (r an arb or fmpq).  A sign is used only when the
  ball proves it (0 only for an exact zero) and the next collision only when its time
  ball lies strictly below all the other time balls; otherwise :class:`Undecided` is
  raised, and the caller raises the precision (:func:`run_certified`).

>>> from flint import fmpq
>>> follow(exact([1, 0, 2]), exact([-1, "1/2", -1]), fmpq(1, 2), 3).word   # a at t=1, c at t=2
'acb'
"""
from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import flint

from certify.algebra.balls import precision
from certify.algebra.poly import to_fmpq
from certify.errors import Undecided

from .model import INDEX, LETTERS, LETTERS_N, collide, collide_gaps, collide_integral


class MultipleCollision(ArithmeticError):
    """Three or four particles meet at one point: a particle meets two others at once,
    a multiple collision, where the collision law is undefined (l. 185).  It happens
    when b comes at the same time as a or c, or when a pair collides next to a gap
    that is closed then (particles in contact).  ``particles``: those that meet (1..4,
    consecutive); ``t``: the time from the current state to the meeting."""

    def __init__(self, particles: Sequence[int], t):
        self.particles, self.t = tuple(particles), t
        kind = meeting_kind(len(self.particles))
        super().__init__(f"{kind} collision of particles {', '.join(map(str, self.particles))}")


def meeting_kind(count: int) -> str:
    """"triple", "quadruple", or "5-fold", ... : the name of a meeting of ``count`` particles."""
    return {3: "triple", 4: "quadruple"}.get(count, f"{count}-fold")


# --- numbers -------------------------------------------------------------------

def is_ball(z) -> bool:
    return isinstance(z, flint.arb)


def sign(z) -> int:
    """The sign of an exact rational, or of a ball when the ball proves it
    (an exact zero ball is 0); Undecided otherwise.

    An fmpq is canonical (denominator > 0): its sign is its numerator's, read
    without the subtraction python-flint's ``z < 0`` makes."""
    if type(z) is flint.fmpq:
        n = z.p
        return (n > 0) - (n < 0)
    if not is_ball(z):
        return (z > 0) - (z < 0)
    if z > 0:
        return 1
    if z < 0:
        return -1
    if z.is_zero():
        return 0
    raise Undecided(f"sign of {z.str(5, radius=True)} undecided")


def zero_like(z):
    """An exact zero of the same kind as z."""
    return flint.arb(0) if is_ball(z) else flint.fmpq(0)


def less(s, t) -> bool:
    """s < t, proven (balls) or exact; Undecided when balls overlap.

    Two fmpq are compared by cross-multiplying their integers (denominators > 0):
    python-flint's ``s < t`` forms the canonical difference s - t, with its gcd."""
    if type(s) is flint.fmpq and type(t) is flint.fmpq:
        return s.p * t.q < t.p * s.q
    if not (is_ball(s) or is_ball(t)):
        return s < t
    if s < t:
        return True
    if s >= t:
        return False
    raise Undecided("two collision times not separated")


# --- collisions ----------------------------------------------------------------

def collision_times(p: Sequence, q: Sequence) -> dict[str, object]:
    """{letter: -p_i/q_i} for every pair with q_i < 0 (certified sign)."""
    return {L: -p[i] / q[i] for L, i in INDEX.items() if sign(q[i]) < 0}


def first_collisions(times: dict[str, object]) -> tuple[str, object]:
    """(letters, time): the pairs with the smallest collision time, in the order a, b, c.
    Balls must separate that time from the others (Undecided otherwise)."""
    for L, t in times.items():
        if all(less(t, s) for M, s in times.items() if M != L):
            return L, t
    # no strict minimum: in exact mode a tie, in ball mode undecided
    if any(is_ball(t) for t in times.values()):
        raise Undecided("the smallest collision time is not separated from the others")
    tmin = min(times.values())
    return "".join(L for L in LETTERS if L in times and times[L] == tmin), tmin


def first_collisions_exact(p: Sequence, q: Sequence) -> tuple[str, flint.fmpq] | None:
    """:func:`collision_times` then :func:`first_collisions` for fmpq p and q, None when
    no pair approaches.  With p_i = P_i/D_i and q_i = Q_i/E_i (denominators > 0), the
    time of an approaching pair is p_i/(-q_i) = (P_i E_i)/(-Q_i D_i), both integers of
    that fraction with -Q_i D_i > 0: times are compared by cross-multiplying them, and
    only the first time is formed as an fmpq (not one division per approaching pair)."""
    times = []
    for L, i in INDEX.items():
        num = q[i].p
        if num < 0:
            times.append((L, p[i].p * q[i].q, -num * p[i].q))
    return earliest(times)


def earliest(times: list) -> tuple[str, flint.fmpq] | None:
    """The letters whose time n/d (``(letter, n, d)``, d > 0) is the least, and that time; None for
    none.  Compared by cross-multiplication: one fmpq is formed, for the answer."""
    if not times:
        return None
    _, n, d = times[0]
    for _L, n1, d1 in times[1:]:
        if n1 * d < n * d1:
            n, d = n1, d1
    return "".join(L for L, n1, d1 in times if n1 * d == n * d1), flint.fmpq(n, d)


def touches(p: Sequence, q: Sequence, t, i: int) -> bool:
    """Is the gap p_i of a pair that does not approach (q_i >= 0) zero at the time
    t >= 0?  p_i + t q_i = 0 exactly when p_i = 0 and t q_i = 0 (signs certified)."""
    return sign(q[i]) >= 0 and sign(p[i]) == 0 and (sign(q[i]) == 0 or sign(t) == 0)


def meeting(p: Sequence, q: Sequence, t, letters: str) -> tuple[int, ...]:
    """The particles (1..4) that meet at one point at the collisions ``letters`` at the
    time t, () when the collisions are binary.  The closed gaps then are ``letters`` and
    the pairs in contact (:func:`touches`; an approaching pair not in ``letters`` closes
    later); three particles meet when the gap b and a gap next to it are closed."""
    closed = [INDEX[L] for L in LETTERS if L in letters or touches(p, q, t, INDEX[L])]
    if INDEX["b"] not in closed or len(closed) == 1:
        return ()
    return tuple(range(min(closed) + 1, max(closed) + 3))


def next_collision(p: Sequence, q: Sequence) -> tuple[str, object] | None:
    """The next collision as (letters, time): letters is "a", "b", "c" or "ac"
    (a and c simultaneous, exact mode only); None when no pair approaches.
    Raises Undecided (balls) or MultipleCollision (three or four particles meet:
    b tied with a or c, or a collision next to particles in contact)."""
    if all(type(z) is flint.fmpq for z in (*p, *q)):
        first = first_collisions_exact(p, q)
        if first is None:
            return None
        letters, t = first
    else:
        times = collision_times(p, q)
        if not times:
            return None
        letters, t = first_collisions(times)
    particles = meeting(p, q, t, letters)
    if particles:
        raise MultipleCollision(particles, t)
    return letters, t


def step(p: Sequence, q: Sequence, r) -> tuple[str, object, tuple, tuple] | None:
    """Advance to the next collision: (letters, time, p, q) right after it
    (velocities post-collisional, l. 195), or None when no collision comes."""
    nxt = next_collision(p, q)
    return None if nxt is None else _collide_after(p, q, r, nxt, INDEX.__getitem__, collide)


def _collide_after(p: Sequence, q: Sequence, r, nxt: tuple, index: Callable[[str], int], law: Callable) -> tuple:
    """(letters, t, p, q) right after the collisions ``nxt`` = (letters, t): free flight for t, each
    closed gap set to exactly zero, q mapped by ``law`` (collide, collide_gaps) for each letter."""
    letters, t = nxt
    p = [pi + t * qi for pi, qi in zip(p, q)]
    for L in letters:
        p[index(L)] = zero_like(p[index(L)])    # the closed gap is exactly zero
        q = law(L, q, r)
    return letters, t, tuple(p), tuple(q)


# --- orbits --------------------------------------------------------------------

@dataclass
class State:
    """The state right after a collision (or the initial state)."""

    t: object            # the time since t = 0
    p: tuple
    q: tuple


@dataclass
class Collisions:
    """The collisions of a run (``events``, "ac" for a simultaneous pair) and why it ended
    (``stop``: "n" all requested collisions, "free" no pair approaches, "undecided" a ball
    comparison failed: raise the precision, or "multiple" three or four particles meet, see
    :class:`MultipleCollision`; ``reason`` says which)."""

    events: list[str] = field(default_factory=list)
    stop: str = "n"
    reason: str = ""

    @property
    def word(self) -> str:
        return "".join(e if len(e) == 1 else f"[{e}]" for e in self.events)


@dataclass
class Run(Collisions):
    """An orbit: its :class:`Collisions` and the states right after each (``states[0]`` is
    the initial state)."""

    states: list[State] = field(default_factory=list)


def follow(p0: Sequence, q0: Sequence, r, n: int, prec: int | None = None,
        until: Callable[[Run], bool] | None = None) -> Run:
    """At most n collisions from (p0, q0); ball arithmetic at ``prec`` bits.
    A comparison that cannot be decided ends the run with stop="undecided" (the
    prefix is certified).  ``until(run)`` may stop the run early (stop="until")."""
    if until is None and type(r) is flint.fmpq and all(type(z) is flint.fmpq for z in (*p0, *q0)):
        return _follow_exact(tuple(p0), tuple(q0), r, n)
    with precision(prec):
        return _iterate(tuple(p0), tuple(q0), n, lambda p, q: step(p, q, r), until)


def _iterate(p: tuple, q: tuple, n: int, advance: Callable[[tuple, tuple], tuple | None],
             until: Callable[[Run], bool] | None = None) -> Run:
    """At most n steps ``advance(p, q) -> (letters, dt, p, q)`` (None: no collision ahead), the Run
    they make; an Undecided or MultipleCollision step ends it with its stop and reason."""
    t = zero_like(p[0])
    out = Run(states=[State(t, p, q)])
    for _ in range(n):
        try:
            nxt = advance(p, q)
        except Undecided as exc:
            out.stop, out.reason = "undecided", str(exc)
            return out
        except MultipleCollision as exc:
            out.stop, out.reason = "multiple", str(exc)
            return out
        if nxt is None:
            out.stop = "free"
            return out
        letters, dt, p, q = nxt
        t = t + dt
        out.events.append(letters)
        out.states.append(State(t, p, q))
        if until is not None and until(out):
            out.stop = "until"
            return out
    return out


def _follow_exact(p: tuple, q: tuple, r: flint.fmpq, n: int) -> Run:
    """:func:`follow` for fmpq p, q and r: the same steps as :func:`step` (the next
    collision by :func:`first_collisions_exact`, the meeting test of :func:`meeting`, the
    closed gap set to 0, the law of :func:`certify.dynamics.model.collide` with h = (1 + r)/2
    formed once), inlined; the same Run, without the generic dispatch per step."""
    zero, h = flint.fmpq(0), (1 + r) / 2
    t = zero
    out = Run(states=[State(t, p, q)])
    events, states = out.events, out.states
    for _ in range(n):
        first = first_collisions_exact(p, q)
        if first is None:
            out.stop = "free"
            return out
        letters, dt = first
        closed = [i for i, L in enumerate(LETTERS)
                  if L in letters or (q[i].p >= 0 and p[i].p == 0 and (q[i].p == 0 or dt.p == 0))]
        if 1 in closed and len(closed) > 1:
            exc = MultipleCollision(range(min(closed) + 1, max(closed) + 3), dt)
            out.stop, out.reason = "multiple", str(exc)
            return out
        p = [p[0] + dt * q[0], p[1] + dt * q[1], p[2] + dt * q[2]]
        q1, q2, q3 = q
        for L in letters:
            if L == "a":
                p[0] = zero
                q1, q2 = -r * q1, q2 + h * q1
            elif L == "b":
                p[1] = zero
                q1, q2, q3 = q1 + h * q2, -r * q2, q3 + h * q2
            else:
                p[2] = zero
                q2, q3 = q2 + h * q3, -r * q3
        p, q = tuple(p), (q1, q2, q3)
        t = t + dt
        events.append(letters)
        states.append(State(t, p, q))
    return out


@dataclass
class Rays(Collisions):
    """An exact run kept up to positive factors: its :class:`Collisions`, and after each
    integer vectors (P, Q) positively proportional to p and q, P primitive (``rays[0]`` for
    the initial state, both primitive).  What depends on the directions of p and q only (the
    collisions, the plane Span(p, q) and its orientation) is read here as on the exact run."""

    rays: list[tuple] = field(default_factory=list)


def _ray(v) -> tuple:
    """The primitive integer vector positively proportional to the integer vector v (v = 0 kept)."""
    g = v[0].gcd(v[1]).gcd(v[2])
    return v if g == 1 or g == 0 else (v[0] // g, v[1] // g, v[2] // g)


def follow_rays(p0: Sequence, q0: Sequence, r: flint.fmpq, n: int) -> Rays:
    """:func:`follow` for exact p0, q0 and r (at most n collisions), on the directions of
    p and q: the same collisions, stop and reason, exactly, without forming p, q or t.

    Proof that the run is the same.  Put p = αP, q = βQ (α, β > 0, P, Q integer).  A pair
    approaches iff Q_i < 0; its time is t_i = p_i/(−q_i) = (α/β)·P_i/(−Q_i), so the times
    compare (ties included) as the integers P_i(−Q_j) and P_j(−Q_i), and t = 0 iff P_i = 0:
    the next collisions, and the meeting test of :func:`meeting` (signs of P, Q and of t),
    are those of the run.  Then p + t q = (α/(−Q_i))((−Q_i)P + P_i Q), with the closed gaps 0,
    and K q = (β/(2d)) (2d K) Q for r = m/d, where 2d K has the integer entries −2m, 2d,
    m + d (:func:`certify.dynamics.model.collide_integral`): positive multiples of the new p
    and q.  P is made primitive at every step (it would grow quadratically), Q never (its
    content grows by at most 2d a step; the gcds cost more than the longer products).  (A test
    runs both.)"""
    zero = flint.fmpz(0)
    P, Q = _ray(integral_vector(p0)), _ray(integral_vector(q0))
    out = Rays(rays=[(P, Q)])
    events, rays = out.events, out.rays
    for _ in range(n):
        Q0, Q1, Q2 = Q
        times = []                               # the approaching pairs: (letter, P_i, −Q_i)
        if Q0 < 0:
            times.append(("a", P[0], -Q0))
        if Q1 < 0:
            times.append(("b", P[1], -Q1))
        if Q2 < 0:
            times.append(("c", P[2], -Q2))
        if not times:
            out.stop = "free"
            return out
        letters, num, den = times[0]
        for L, n1, d1 in times[1:]:              # the smallest time, and every pair that ties with it
            left, right = n1 * den, num * d1
            if left < right:
                letters, num, den = L, n1, d1
            elif left == right:
                letters += L
        closed = [i for i, L in enumerate(LETTERS)
                  if L in letters or (Q[i] >= 0 and P[i] == 0 and (Q[i] == 0 or num == 0))]
        if 1 in closed and len(closed) > 1:
            exc = MultipleCollision(range(min(closed) + 1, max(closed) + 3), None)
            out.stop, out.reason = "multiple", str(exc)
            return out
        # (−Q_i)P + P_i Q, the gaps that close set to 0 (they are 0), then 2d·K Q for each collision
        P = _ray(tuple(zero if L in letters else den * P[i] + num * Q[i] for i, L in enumerate(LETTERS)))
        for L in letters:
            Q = collide_integral(L, Q, r)
        events.append(letters)
        rays.append((P, Q))
    return out


# --- N particles (beyond the paper) -------------------------------------------

def next_collision_gaps(p: Sequence, q: Sequence) -> tuple[str, flint.fmpq] | None:
    """:func:`next_collision` for exact (fmpq) gaps p and velocities q of N = len(p) + 1
    particles: (letters, time), letters the pairs (a, b, c, d, ...) whose gap closes first,
    several when non-adjacent pairs tie (their laws act on disjoint pairs and commute);
    None when no pair approaches.  The closed gaps at that time are those letters and the
    pairs in contact (:func:`touches`); two adjacent closed gaps, one of them a collision,
    are particles meeting at one point: :class:`MultipleCollision`, with the particles of
    that run of closed gaps.  For N = 4 the same decisions as :func:`next_collision`."""
    first = earliest([(LETTERS_N[i], p[i].p * q[i].q, -q[i].p * p[i].q) for i in range(len(q)) if q[i].p < 0])
    if first is None:
        return None
    letters, t = first
    closed = [i for i in range(len(q)) if LETTERS_N[i] in letters or touches(p, q, t, i)]
    runs: list[list[int]] = []
    for i in closed:
        if runs and runs[-1][-1] == i - 1:
            runs[-1].append(i)
        else:
            runs.append([i])
    for run in runs:
        if len(run) > 1 and any(LETTERS_N[i] in letters for i in run):
            raise MultipleCollision(range(run[0] + 1, run[-1] + 3), t)
    return letters, t


def follow_gaps(p0: Sequence, q0: Sequence, r: flint.fmpq, n: int) -> Run:
    """At most n collisions of N = len(p0) + 1 particles from the exact gaps p0 and relative
    velocities q0: the next collision by :func:`next_collision_gaps`, free flight p + t q, the
    closed gaps set to 0 and q mapped by K_i (:func:`certify.dynamics.model.collide_gaps`) for
    each letter.  Exact (fmpq); the same :class:`Run` as :func:`follow` gives for N = 4."""
    p, q = tuple(flint.fmpq(z) for z in p0), tuple(flint.fmpq(z) for z in q0)
    return _iterate(p, q, n, lambda p, q: step_gaps(p, q, r))


def step_gaps(p: tuple, q: tuple, r: flint.fmpq) -> tuple | None:
    """One collision of N = len(p) + 1 particles, exactly: (letters, dt, p, q) after it, or None
    when no gap closes (:func:`next_collision_gaps`, free flight, :func:`collide_gaps`)."""
    nxt = next_collision_gaps(p, q)
    return None if nxt is None else _collide_after(p, q, r, nxt, LETTERS_N.index, collide_gaps)


def integral_vector(v: Sequence) -> tuple:
    """A positive multiple of the rational vector v with integer (fmpz) entries."""
    den = flint.fmpz(1)
    for z in v:
        den = den.lcm(flint.fmpq(z).q)
    return tuple((flint.fmpq(z) * den).p for z in v)


def run_certified(datum: Callable[[int], tuple], n: int, prec: int = 128,
                  maxprec: int = 1 << 15, until: Callable[[Run], bool] | None = None
                  ) -> tuple[Run, int]:
    """Run with balls, doubling the precision until the run is decided.

    ``datum(prec)`` returns (p0, q0, r) as balls computed at that precision (the
    initial datum itself must be recomputed when the precision rises).  Returns the
    run and the precision used; raises Undecided beyond ``maxprec``."""
    while prec <= maxprec:
        with precision(prec):
            p0, q0, r = datum(prec)
        result = follow(p0, q0, r, n, prec, until)
        if result.stop != "undecided":
            return result, prec
        prec *= 2
    raise Undecided(f"run undecided at {maxprec} bits: {result.reason}")


def exact(values) -> tuple:
    """A tuple of fmpq from integers, strings "p/q", Fractions or fmpq."""
    return tuple(to_fmpq(z) for z in values)


def balls(values, prec: int | None = None) -> tuple:
    """A tuple of arb from exact rationals (exact balls) or arbs."""
    with precision(prec):
        return tuple(z if is_ball(z) else flint.arb(flint.fmpq(z)) for z in values)
