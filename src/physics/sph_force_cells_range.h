/* What the vectorised sweep's range kernels share (sph_force_cells_avx512.h,
 * sph_force_cells_avx2.h): the two slots' layout, the constants of a sweep, the buffer of a
 * particle's own sums and the pair flags of the copy (sph_force_cells.c). */
#ifndef DMHS_SPH_FORCE_CELLS_RANGE_H
#define DMHS_SPH_FORCE_CELLS_RANGE_H
#include "dmhs/particles.h"
#include "dmhs/topology.h"
#include "sph_kernel.h"

#define SPH_CELLS_BUF 64 /* own-sum buffer, flushed before it can overflow */
/* rows past a slot's end that a vector may read and write back unchanged (AVX2's loads and
 * stores are unmasked) */
#define SPH_CELLS_PAD 8

/* flags of the copy: cells.c's 1 = ghost, 2 = wall, 4 = not liquid (at the build), and the
 * current type */
#define FL_NO_PAIR  3 /* two ghosts, two walls: no pair (cells.c) */
#define FL_SOLID    4 /* two bonded particles: maybe partners, left out (cells.c) */
#define FL_WALL_NOW 8 /* a wall now: no density diffusion through it */

/* One row of cells in a slot: slot position t holds cell-order position base + t. */
typedef struct {
  double *X, *Y, *VX, *VY, *EX, *EY, *P, *IR, *M, *RHO, *J;
  double *AX, *AY, *DR;
  unsigned char *FL;
  const PetscInt *order; /* slot position -> row */
} cells_slot;

typedef struct {
  const struct topology *excl; /* bonded pairs to leave out, or NULL */
  const particles *ps;
  double h2, r2_floor, inv_h, grad_norm, grad_norm_inv_h, h, av_h2, neg_alpha_c0, beta, two_dhc;
} cells_args;

/* the particle a's own sums, in the order of its partners */
typedef struct {
  double x[SPH_CELLS_BUF + 8], y[SPH_CELLS_BUF + 8], q[SPH_CELLS_BUF + 8], d[SPH_CELLS_BUF + 8];
  int n;
  double ax, ay, ad;
  PetscInt64 pairs; /* pairs inside h: the flop count */
} own_sums;

SPH_INLINE void own_flush(own_sums *o, int continuity, int diffusion) {
  for (int t = 0; t < o->n; t++) {
    o->ax += o->x[t];
    o->ay += o->y[t];
    if (continuity) {
      o->ad += o->q[t];
      if (diffusion)
        o->ad += o->d[t];
    }
  }
  o->n = 0;
}
#endif
