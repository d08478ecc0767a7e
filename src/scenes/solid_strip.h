/* Internal to the scenes: a two-layer mass-spring strip as the vein leaflets
 * are built (doc/cases.md), and its Timoshenko beam constants (doc/theory.md,
 * "Mass-spring leaflets as Timoshenko beams"). */
#ifndef DMHS_SOLID_STRIP_H
#define DMHS_SOLID_STRIP_H
#include "dmhs/sim.h"

typedef struct solid_strip {
  PetscInt n;       /* columns, clamped ones included */
  PetscInt n_clamp; /* first columns made of fixed (wall) particles */
  PetscBool hinged; /* n_clamp = 1 only: column 0's layer-1 particle free, so that the strip
                       turns freely about the layer-0 one */
  double origin[2]; /* first column's layer-0 particle [m] */
  double along[2];  /* unit vector from column to column */
  double across[2]; /* unit vector from layer 0 to layer 1 */
  double spacing;   /* column and layer spacing = bond rest length [m] */
  double mass, rho; /* per particle [kg], initial density [kg/m^3] */
  PetscInt64
      first_gid; /* gids first_gid .. first_gid + 2n - 1: column c layer l = first_gid + 2c + l */
} solid_strip;

/* Adds the particles (clamped columns as PTYPE_WALL, the last column marked
 * SOLID_LOAD_MARK in the load field, with solid_load), bonds along both layers and across every
 * column, and the four right angles of every cell (theta0 = pi/2) to s->topo. Bonds and angles
 * between clamped particles only are left out. A hinged strip fixes only column 0's layer-0
 * particle (and bonds column 0 across): the angles fix the cells' shape, not their direction. */
PetscErrorCode solid_strip_build(sim *s, solid_strip *st, PetscInt64 *next_gid);
/* Timoshenko constants of the strip: layer bond stiffness k_s = U''(r0) [N/m],
 * EI = k_s r0 d^2/2 + 2 k_a r0 with d = r0 [N m^2] (layers, plus the corner
 * angles that bending opens and closes by kappa r0/2), kGA = 8 k_a/r0 [N],
 * mass per length 2m/r0. */
void solid_strip_beam(double k_s, double k_a, double r0, double mass, double *EI, double *kGA,
                      double *mu);

#endif
