/* solve/solve.h -- the face of src/solve/: the solvers for the modules above: the band solvers
 * and their shared helpers (solvers.h), progressive refinement and its
 * race (progressive.h), the matrix-free solve (solvefree.h); rad_solve
 * itself is public (radiosity/solve.h).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#ifndef RAD_SOLVE_FACE_H
#define RAD_SOLVE_FACE_H

#include "solve/solvers.h"
#include "solve/progressive.h"
#include "solve/solvefree.h"

#endif /* RAD_SOLVE_FACE_H */
