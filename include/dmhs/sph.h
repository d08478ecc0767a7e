/* SPH parameters shared by the sph_* files, and the "sph" physics module that
 * runs density (summation or continuity), equation of state, wall boundary
 * values and the momentum equation, in that order, once per step. */
#ifndef DMHS_SPH_H
#define DMHS_SPH_H
#include <petscsys.h>
#include "dmhs/module.h"

typedef enum { SPH_KERNEL_LUCY, SPH_KERNEL_CUBIC, SPH_KERNEL_WENDLAND } sph_kernel_kind;
typedef enum { SPH_EOS_TAIT, SPH_EOS_LINEAR, SPH_EOS_LINEAR_SHIFTED } sph_eos_kind;
typedef enum { SPH_DENSITY_CONTINUITY, SPH_DENSITY_SUMMATION } sph_density_kind;
/* wall velocity for the viscous term: Adami's Shepard mirror, or the quadratic
 * no-slip extrapolation along the wall normal (needs the to_surface field) */
typedef enum { SPH_WALL_ADAMI, SPH_WALL_QUADRATIC } sph_wall_kind;
/* the momentum sweep: auto (cells where it applies, else pairs), the pair list, or the
 * vectorised sweep over cell ranges (sph_force_cells.c); the same bits either way */
typedef enum { SPH_SWEEP_AUTO, SPH_SWEEP_PAIRS, SPH_SWEEP_CELLS } sph_sweep_kind;

extern const char *const sph_kernel_names[];
extern const char *const sph_eos_names[];
extern const char *const sph_density_names[];
extern const char *const sph_wall_names[];
extern const char *const sph_sweep_names[];

typedef struct sph_params {
  sph_kernel_kind kernel;
  double h;    /* kernel support radius [m] (W = 0 for r >= h, LAMMPS convention) */
  double rho0; /* reference density [kg/m^3] */
  double c0;   /* reference sound speed [m/s] */
  double nu;   /* kinematic viscosity [m^2/s] */
  sph_eos_kind eos;
  sph_density_kind density;
  double av_alpha; /* Monaghan artificial viscosity (0 = off) */
  double av_beta;
  double p_background; /* p_b [Pa] added to every EOS: p = EOS(rho) + p_b (0 = off) */
  double delta;        /* density diffusion coefficient (Molteni & Colagrossi 2009; 0 = off) */
  double tensile_eps; /* Monaghan (2000) artificial pressure where p < 0 (sph_tensile.c; 0 = off) */
  PetscBool kernel_correction; /* corrected operators (sph_correction_iact.h) */
  sph_wall_kind wall;          /* wall velocity extrapolation (sph_wall.c) */
  sph_sweep_kind sweep;        /* -sph_force_sweep */
  /* continuity: the force evaluation sees the density predicted for the end of
   * the step, rho^n + dt drho^n, corrected to the trapezoid after it
   * (integrate.c), instead of the half-step rho^n + dt/2 drho^n */
  PetscBool density_predict;
} sph_params;

PetscErrorCode sph_module_create(module **m);
struct sim;
/* The sph module's parameters, for its scene to set defaults on before the options pass
 * (NULL when m is not the sph module). */
sph_params *sph_defaults(module *m);
/* The scenes' common liquid as defaults: Lucy kernel, Tait EOS, continuity density, support
 * h [m], rho0 [kg/m^3], c0 [m/s], nu [m^2/s] (sph_defaults for the rest). */
PetscErrorCode sph_set_liquid(module *m, double h, double rho0, double c0, double nu);
/* The scene builds no wall particle: the viscous term reads v_est, and the v_visc field is
 * not made (memory); building a wall after this is an error. Before the options pass. */
PetscErrorCode sph_set_no_walls(module *m);
/* The enabled sph module's parameters (after the options pass), NULL without SPH. */
const sph_params *sph_params_get(const struct sim *s);

#endif
