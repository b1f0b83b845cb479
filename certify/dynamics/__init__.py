"""Layer 2, the models: the collision law and collision words (Section 2), the candidate
of a word, the exact and ball simulators of the four particles, and the spherical
billiard reduction (Section 4).  It imports only :mod:`certify.algebra` and the ground floor.

- :mod:`.model`: the law, the matrices A, B, C, words and their matrices M_w, cp(M_w).
- :mod:`.words`: the candidate of a word a…b: M_w, its branches, q(0), the position map.
- :mod:`.simulate`: relative dynamics, exact (fmpq) and in balls (arb).
- :mod:`.particles`: the four particles in absolute coordinates (``certify particles``).
- :mod:`.reduction`: the reduction map, projective, vectorial and trigonometric.
- :mod:`.cones`: the step lemma of the reduction on each of the six cones of states, exact
  and symbolic (every orbit, not samples).
"""
from . import cones, particles, reduction, simulate
from .model import (
                    INDEX,
                    LETTERS,
                    LETTERS_N,
                    A,
                    B,
                    C,
                    characteristic_polynomial,
                    check_word,
                    collide,
                    collide_gaps,
                    collide_particles,
                    collision_matrix,
                    det3,
                    word_matrix,
)
from .simulate import MultipleCollision, Undecided
from .words import (
                    Candidate,
                    candidate,
                    check_position_map,
                    eigenvector,
                    fixed_point_ball,
                    position_map,
                    reduce_mod,
                    run_word,
                    velocities,
)

__all__ = [
    "cones", "particles", "reduction", "simulate",
    "INDEX", "LETTERS", "LETTERS_N", "A", "B", "C", "characteristic_polynomial", "check_word", "collide",
    "collide_gaps", "collide_particles", "collision_matrix", "det3", "word_matrix",
    "MultipleCollision", "Undecided",
    "Candidate", "candidate", "check_position_map", "eigenvector", "fixed_point_ball", "position_map",
    "reduce_mod", "run_word", "velocities",
]
