"""Layer 3, analyses of collision patterns: where in r the candidate of a word is
realised by the dynamics (feasibility), as exact regions with algebraic end points.
It imports the models and the exact algebra below it.

- :mod:`.feasibility`: the requirements of a word (gaps, approaches, first collisions)
  and their certified regions of r on each eigenvalue branch.
"""
from .feasibility import (BRANCH_NAMES, Analysis, Requirement, fmt, mod_cp, prefix_requirements,
                          vanishes_on_branch)

__all__ = ["BRANCH_NAMES", "Analysis", "Requirement", "fmt", "mod_cp", "prefix_requirements",
           "vanishes_on_branch"]
