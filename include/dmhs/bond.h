/* Bond modules (bond_harmonic.c, bond_nonlinear.c): shared parameters, the
 * -bond_style names, and the scene-side default setter.
 *   harmonic:  U = K (r - r0)^2                          K [J/m^2]
 *   nonlinear: U = k_b (r - r0)^2 / (r_max^2 - (r - r0)^2)  k_b [J], r_max [m]
 * Coefficients are per bond type: -bond_k 1e6 (every type) or -bond_k 1e6,2e6 (types 0, 1). */
#ifndef DMHS_BOND_H
#define DMHS_BOND_H
#include <petscoptions.h>
#include "dmhs/module.h"
#include "dmhs/topology.h"

struct sim;

typedef enum { BOND_HARMONIC, BOND_NONLINEAR } bond_style;
extern const char *const bond_style_names[];

/* Spring time-step limit dt <= SPRING_DT_FACTOR sqrt(m / k), k = U'' [N/m], m the
 * smallest moving mass. Velocity Verlet is stable for omega dt < 2; a particle
 * held by n equal springs has omega up to about sqrt(2 n k/m) (n = 2 in a chain:
 * 2 sqrt(k/m)); 0.2 keeps omega dt <= 0.6 for up to 4-5 springs per particle and
 * the energy error per period small (about (omega dt)^2/24 in relative terms). */
#define SPRING_DT_FACTOR 0.2

typedef struct bond_params {
  double k[TOPOLOGY_MAX_TYPES];    /* K [J/m^2] (harmonic) or k_b [J] (nonlinear) */
  double r0[TOPOLOGY_MAX_TYPES];   /* rest length [m] */
  double rmax[TOPOLOGY_MAX_TYPES]; /* nonlinear only: largest |r - r0| [m] */
  PetscInt n_k, n_r0, n_rmax;      /* values given on the command line (0 = scene default) */
  double m_min;                    /* smallest mass of a moving bonded particle [kg] */
  double damping;                  /* harmonic only: the dashpots' damping ratio zeta [1] */
} bond_params;

PetscErrorCode bond_harmonic_module_create(module **m);

/* The bonds one harmonic law U = K (r - r0)^2 acts on: the local bond entries of the types
 * `owner` claimed, K per bond type, r0 per bond type or (r0 NULL) each bond's own rest length
 * (topology bond_r0: the clots', so that a bond starts unstressed). bond_harmonic.c. */
typedef struct harmonic_bonds {
  const void *owner;
  const double *k;  /* [TOPOLOGY_MAX_TYPES] J/m^2 */
  const double *r0; /* [TOPOLOGY_MAX_TYPES] m, or NULL */
  double damping;   /* damping ratio zeta of each bond's dashpot (dashpot_iact.h), 0 = none */
} harmonic_bonds;
/* Adds the law's accelerations to a. */
PetscErrorCode bond_harmonic_forces(struct sim *s, const harmonic_bonds *set);
/* Adds the bonds' pair virial to W (per row: xx, yy, xy). */
PetscErrorCode bond_harmonic_virial_add(struct sim *s, const harmonic_bonds *set, double (*W)[3]);
/* The bonds' energy over all ranks (each entry by its weight). Collective. */
PetscErrorCode bond_harmonic_energy_of(struct sim *s, const harmonic_bonds *set, double *e);
PetscErrorCode bond_nonlinear_module_create(module **m);
/* The scene's defaults for every bond type (rmax ignored by the harmonic style);
 * call after solid_modules_enable, before the options pass of the modules. */
PetscErrorCode bond_set_default(struct sim *s, double k, double r0, double rmax);
/* Resolved bond parameters of the enabled bond module (for scenes' diagnostics). */
PetscErrorCode bond_get_params(struct sim *s, bond_style *style, const bond_params **p);

/* Shared by the two bond modules: reads -bond_k (help text per style) and
 * -bond_r0 inside their options block; checks them per type and finds the
 * smallest solid mass in setup (k_unit names K's unit in messages); frees. */
PetscErrorCode bond_options_k_r0(PetscOptionItems *PetscOptionsObject, bond_params *p,
                                 const char *k_help);
PetscErrorCode bond_setup_k_r0(struct sim *s, bond_params *p, const char *k_unit);
PetscErrorCode bond_destroy(module *self);
/* Claims for `self` every bond type of the scene's own bonds that no other module claimed
 * (topology_claim_bond_type), in its setup. */
PetscErrorCode bond_claim_scene_types(struct sim *s, const module *self);
/* Shared by the solid modules' setup: checks per-type coefficients given for
 * n_given types cover n_types (one value = every type), names the option. */
PetscErrorCode bond_check_type_coeffs(const char *option, double v[], PetscInt n_given,
                                      PetscInt n_types);
/* An internal error naming who asked when the topology's local lists do not exist yet: the
 * time-step limits are asked for after the first neighbour build, and never change state. */
PetscErrorCode bond_check_resolved(const struct sim *s, const char *who);
/* Smallest mass among owned solid particles, over all ranks (+inf when none). */
PetscErrorCode bond_min_solid_mass(struct sim *s, double *m);
/* A bond's Jacobian blocks (solid_modes.h) for rows i, j, d = x_i - x_j, r = |d|: the
 * block -dF_i/dx_i has U'' along d and U'/r = -fr across it; -dF_i/dx_j is its negative. */
PetscErrorCode bond_jacobian_add(struct solid_jacobian *J, PetscInt i, PetscInt j,
                                 const double d[2], double r, double upp, double fr);

/* For scenes with solids: reads -bond_style (default: the scene's style) and
 * -special_bonds_include, and enables the bond module of that style and angle_harmonic
 * (which, needing bonds and angles, bring sim->topo). Scene defaults for the bond/angle
 * coefficients are set afterwards with bond_set_default / angle_set_default. */
PetscErrorCode solid_modules_enable(struct sim *s, bond_style style);

#endif
