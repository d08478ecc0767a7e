/* Internal interface between the sph module's files (not public). */
#ifndef DMHS_SPH_INTERNAL_H
#define DMHS_SPH_INTERNAL_H
#include "dmhs/sim.h"
#include "sph_correction_iact.h"

/* sph_force.c: momentum (and continuity) sweep over the pair list; the work
 * arrays hold per-particle p/rho^2, 1/rho and sqrt(mu_i + mu_j)/rho (owned and ghost rows) */
typedef struct sph_cells_work sph_cells_work;
typedef struct {
  PetscInt n_alloc;
  double *P, *inv_rho, *J; /* p/rho^2, 1/rho, sqrt(mu_i + mu_j)/rho per row */
  sph_cells_work *cells;   /* the vectorised sweep's copy (sph_force_cells.c) */
  PetscBool visc_is_est;   /* no walls: the viscous term reads v_est (sph_viscous_velocity) */
} sph_force_work;
/* corr: the per-row tensors of -sph_kernel_correction and pair: the per-pair kernel
 * values of the same pass (sph_correction.c); NULL, NULL = plain operators */
PetscErrorCode sph_force_compute(sim *s, const sph_params *sp, sph_force_work *work,
                                 const sph_correction *corr, const double (*pair)[2]);
/* The specialised sweeps of one kernel, one per (density form, artificial viscosity):
 * X(name, kernel, continuity, artificial, diffusion); and a row of their dispatch table,
 * [summation, continuity, continuity + diffusion][artificial viscosity], each entry P(name). */
#define SPH_SWEEP_VARIANTS(X, stem, K)                                                             \
  X(stem, K, 0, 0, 0)                                                                              \
  X(stem##_c, K, 1, 0, 0)                                                                          \
  X(stem##_av, K, 0, 1, 0)                                                                         \
  X(stem##_c_av, K, 1, 1, 0)                                                                       \
  X(stem##_cd, K, 1, 0, 1)                                                                         \
  X(stem##_cd_av, K, 1, 1, 1)
#define SPH_SWEEP_ROW(P, stem)                                                                     \
  {                                                                                                \
    {P(stem), P(stem##_av)}, {P(stem##_c), P(stem##_c_av)}, {                                      \
      P(stem##_cd), P(stem##_cd_av)                                                                \
    }                                                                                              \
  }
/* The velocity every SPH sweep's viscous term sees per row: with walls v_visc (the wall
 * pass's extrapolation on wall rows, v_est on the others), without them v_est itself. */
static inline const double (*sph_viscous_velocity(const particles *ps,
                                                  PetscBool visc_is_est))[DMHS_DIM] {
  return (const double(*)[DMHS_DIM])(visc_is_est ? ps->v_est : ps->v_visc);
}
/* flops of one pair inside h (-log_view) */
double sph_force_flops_per_pair(int continuity, int artificial, int diffusion, int corrected);
/* sph_force_cells.c: the same sweep over cell ranges with AVX-512 or AVX2, bitwise equal to the
 * pair-list sweep. Its copy of the fields in cell order, one row of cells in each of two slots:
 * x, y, v_visc (2), v_est (2), p/rho^2, 1/rho, m, rho, a (2), d rho/dt, sqrt(mu_i + mu_j)/rho,
 * and per row the pair flags. */
#define SPH_CELLS_NFIELDS 14
typedef struct sph_cells_work {
  PetscInt n_alloc;                /* rows per slot */
  double *f[2][SPH_CELLS_NFIELDS]; /* NULL where the run does not read the field */
  unsigned char *fl[2];
  PetscInt64 n_pairs; /* pairs inside h in the last sweep */
} sph_cells_work;
/* PETSC_TRUE when this build has the vectorised sweep */
PetscBool sph_force_cells_available(void);
/* PETSC_TRUE when it applies to the current settings (-sph_force_sweep, uncorrected, Lucy or
 * Wendland); the choice depends on settings only, never on a rank's rows */
PetscBool sph_force_cells_applies(const sph_params *sp);
/* visc_is_est: v_visc equals v_est (no walls), read once */
PetscErrorCode sph_force_cells_compute(sim *s, const sph_params *sp, sph_cells_work *w,
                                       PetscBool visc_is_est);
PetscErrorCode sph_cells_work_destroy(sph_cells_work *w);
/* sph_correction.c: the tensors of the corrected operators for every row: owned
 * non-wall rows get L, G, B (the identity where the neighbourhood is too sparse),
 * ghost and wall rows zero */
typedef struct {
  PetscInt n_alloc;
  sph_moments *mom;
  sph_correction *corr;
  double *vol;        /* m/rho per row, negative on rows that need no moments */
  double (*e_div)[2]; /* v_div - v_visc per row (sph_correction.c) */
  PetscInt n_pair_alloc;
  double (*pair)[2]; /* per pair of the list: (dW/dr)/r and 1/r^2, 0 beyond h */
} sph_correction_work;
/* vv: the velocity of the viscous term per row (sph_viscous_velocity) */
PetscErrorCode sph_correction_compute(sim *s, const sph_params *sp, const double (*vv)[2],
                                      sph_correction_work *w);
PetscErrorCode sph_correction_destroy(sph_correction_work *w);
/* sph_stress.c: the SPH virial, pressure force and shear rate (stress diagnostics) */
PetscErrorCode sph_stress_virial(sim *s, const sph_params *sp, const double (*vv)[2],
                                 double (*W)[3]);
/* sph_density.c: summation density rho_i = sum_j m_j W_ij (self included), owned non-walls */
PetscErrorCode sph_density_summation(sim *s, const sph_params *sp);
/* sph_tensile.c: Monaghan's artificial pressure (-sph_tensile_eps), added to the
 * accelerations after the momentum sweep; R holds eps |p|/rho^2 per row under tension */
typedef struct {
  PetscInt n_alloc;
  double *R;
} sph_tensile_work;
PetscErrorCode sph_tensile_compute(sim *s, const sph_params *sp, sph_tensile_work *w);
PetscErrorCode sph_tensile_destroy(sph_tensile_work *w);
/* sph_eos.c: p from rho for every non-wall row (owned and ghost: no communication) */
PetscErrorCode sph_eos_compute(sim *s, const sph_params *sp);
/* sph_wall.c: wall velocity/pressure/density extrapolated from the liquid (Adami 2012) */
typedef struct sph_wall_work sph_wall_work;
PetscErrorCode sph_wall_create(sph_wall_work **w);
PetscErrorCode sph_wall_destroy(sph_wall_work **w);
/* g: the body acceleration at the current time (its hydrostatic part of the wall pressure) */
PetscErrorCode sph_wall_compute(sim *s, const sph_params *sp, const double g[2], sph_wall_work *w);

#endif
