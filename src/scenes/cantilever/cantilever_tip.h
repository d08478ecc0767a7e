/* The diagnostic "cantilever" (src/scenes/cantilever/cantilever_tip.c): the loaded beam's
 * tip and energies at every output time in <output_dir>/cantilever.csv:
 *   t, tip_dx, tip_dy (mean displacement of the particles the load acts on [m]),
 *   kinetic and potential energy [J]; header lines '# key = value' give the beam
 *   constants, the load F [N] and the damping rate gamma [1/s]
 *   (scripts/post/plot_cantilever.py). A restart continues the file (csv.h).
 * At the end, a line with the final tip displacement. */
#ifndef DMHS_CANTILEVER_TIP_H
#define DMHS_CANTILEVER_TIP_H
#include "dmhs/sim.h"

typedef struct cantilever_beam {
  PetscInt n, n_clamp;   /* columns, clamped ones included */
  double spacing, mass;  /* r0 [m], particle mass [kg] */
  double L, EI, kGA, mu; /* free length [m] and the Timoshenko constants (doc/theory.md) */
  module *load;          /* the tip load (solid_load): force and damping for the header */
} cantilever_beam;

PetscErrorCode cantilever_tip_register(sim *s, const cantilever_beam *beam);

#endif
