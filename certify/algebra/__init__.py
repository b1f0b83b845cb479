"""Layer 1, exact algebra: polynomials over Q, Sturm sequences, real algebraic numbers,
ball arithmetic, eliminations, identities in cos/sin, and certified signs on the
eigenvalue branches of a matrix over Q(r).  It imports nothing of certify above the
ground floor (:mod:`certify.errors`, :mod:`certify.caches`).

- :mod:`.poly`: the paper's notation in (``parse``), python-flint out; Q[r, λ].
- :mod:`.sturm`: two routes to real roots, kept apart: Sturm counts over Q (exact
  sign changes only) and python-flint's root isolation, compared; fast isolation.
- :mod:`.algebraic`: a real algebraic number as (minimal polynomial, isolating interval).
- :mod:`.numberfield`: arithmetic in Q(α)[λ] for exact zero tests.
- :mod:`.elimination`: elimination twice, by a Gröbner basis (SymPy) and a resultant (flint).
- :mod:`.balls`: working precision of arb balls, and "double until decided".
- :mod:`.trig`: identities in cos, sin of θ, φ, by two routes.
- :mod:`.branches`: signs of conditions on the eigenvalue branches over r-intervals.
- :mod:`.radicals`: printed nested radicals ("3+2√2-2√(4+3√2)") read into Algebraic numbers.
- :mod:`.statements`: the paper's printed conditions read whole (relations, ranges of r,
  the paper's phrases), evaluated on certified signs and numbers; unread text is an error.
"""
from . import numberfield, statements, trig
from .algebraic import Algebraic, rational_between, roots_in_unit_interval, sign_at, sign_intervals, unique_root
from .balls import GUARD, decide, ends, ordered, precision, tight
from .branches import (
                       BRANCH_NAMES,
                       LOWER,
                       MIDDLE,
                       UPPER,
                       X_MINUS,
                       X_PLUS,
                       Condition,
                       FixedPoint,
                       SignTable,
                       Spectrum,
                       ball_value,
                       sign_word,
                       simplest_between,
)
from .elimination import Elimination, eliminate, show_factored_int
from .poly import (
                       FIELD,
                       RING,
                       Lf,
                       Q,
                       Rf,
                       discriminant_lambda,
                       divides,
                       expr,
                       from_flint,
                       irreducible_factors,
                       lam,
                       parse,
                       primitive,
                       r,
                       resultant_lambda,
                       same_up_to_constant,
                       show,
                       squarefree_part,
                       to_field,
                       to_fmpq,
                       to_fmpq_poly,
                       to_fmpz_poly,
                       to_ring,
                       u,
                       v,
                       x,
)
from .radicals import radical
from .statements import StatementError
from .sturm import checked_real_root_count, count_roots, flint_real_roots, isolate, refine, sturm_count, sturm_sequence

__all__ = [
    "numberfield", "statements", "trig", "StatementError", "radical",
    "Algebraic", "rational_between", "roots_in_unit_interval", "sign_at", "sign_intervals", "unique_root",
    "GUARD", "decide", "ends", "ordered", "precision", "tight",
    "BRANCH_NAMES", "LOWER", "MIDDLE", "UPPER", "X_MINUS", "X_PLUS", "Condition", "FixedPoint", "SignTable",
    "Spectrum", "ball_value", "sign_word", "simplest_between",
    "Elimination", "eliminate", "show_factored_int",
    "FIELD", "Q", "RING", "Lf", "Rf", "discriminant_lambda", "divides", "expr", "from_flint", "irreducible_factors",
    "lam",
    "parse", "primitive", "r", "resultant_lambda", "same_up_to_constant", "show", "squarefree_part", "to_field",
    "to_fmpq",
    "to_fmpq_poly", "to_fmpz_poly", "to_ring", "u", "v", "x",
    "checked_real_root_count", "count_roots", "flint_real_roots", "isolate", "refine", "sturm_count",
    "sturm_sequence",
]
