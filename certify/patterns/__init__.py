"""Layer 3, analyses of collision patterns: where in r the candidate of a word is
realised by the dynamics (feasibility), as exact regions with algebraic end points.
It imports the models and the exact algebra below it.

- :mod:`.feasibility`: the requirements of a word (gaps, approaches, first collisions)
  and their certified regions of r on each eigenvalue branch.
- :mod:`.periodic`: periods as written (powers, [ac]), validation, normal forms.
- :mod:`.pattern`: ``certify pattern WORD``: exists / feasible / stable regions of a
  word, its verdict, Markdown and JSON (pattern.schema.json).
- :mod:`.island_theorem`: ``certify island``: the elliptic island around [ac]b, every step
  proved exactly; the rotation number, the resonances, the island's share of the section.
"""
from certify.algebra.branches import BRANCH_NAMES

from . import family_limit, family_windows, island_theorem  # family_*: L5, L6 (the windows, the proof beyond N0)
from .census import end_number  # an end point of a committed r-set, as an algebraic number
from .feasibility import NO_X, Analysis, Requirement, fmt, mod_cp, prefix_requirements, vanishes_on_branch
from .pattern import (
                          SCHEMA_PATH,
                          PatternResult,
                          analyse,
                          check_range,
                          dominance_requirements,
                          end_data,
                          known_factors,
                          stability_conditions,
)
from .periodic import compact, normal_form, parse, primitive_root, read, system_of, validate
from .periodic import show as show_word

__all__ = ["BRANCH_NAMES", "island_theorem", "NO_X", "Analysis", "Requirement", "fmt", "mod_cp", "prefix_requirements",
           "vanishes_on_branch",
           "compact", "normal_form", "parse", "primitive_root", "read", "show_word", "system_of", "validate",
           "SCHEMA_PATH", "PatternResult", "analyse", "check_range", "dominance_requirements", "end_data",
           "known_factors",
           "stability_conditions", "family_limit", "family_windows", "end_number"]
