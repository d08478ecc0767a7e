/* The virial of a central pair force (stress diagnostics, src/diag/stress.c):
 * a force F_i = fr d on i (d = x_i - x_j, F_j = -F_i) gives both particles
 * W += -1/2 d (x) F_i, components (xx, xy, yy). Shared by the bond and
 * repulsion modules. */
#ifndef DMHS_VIRIAL_IACT_H
#define DMHS_VIRIAL_IACT_H
#include <petscsys.h>

static inline void virial_pair_add(double (*W)[3], PetscInt i, PetscInt j, double fr,
                                   const double d[2]) {
  const double w[3] = {-0.5 * fr * d[0] * d[0], -0.5 * fr * d[0] * d[1], -0.5 * fr * d[1] * d[1]};
  for (int c = 0; c < 3; c++) {
    W[i][c] += w[c];
    W[j][c] += w[c];
  }
}

#endif
