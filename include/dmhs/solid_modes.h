/* The solids' fastest mode, for the step that sub-cycles them.
 *
 * With -solid_substeps the bonds and angles move on sub-steps of dt/N, but the
 * forces that are not sub-cycled (the liquid's) still act on them once a step,
 * as impulses. That multiple-time-step (r-RESPA) scheme resonates when dt
 * nears a third of the solids' fastest period (omega dt = 2 pi/3, the 3:1
 * nonlinear resonance; the linear 2:1 one is at pi), however small the
 * sub-step: the vein's stiffest leaflets rang at omega dt = 2.1 with their
 * sub-step well inside its own limits (doc/stability.md, "Multi-rate
 * contact"). Those limits (0.2 sqrt(m/k) per spring) bound each spring alone;
 * a lattice's fastest mode is several times faster than its stiffest spring
 * (3.3x for the vein's right-angle cells), so they cannot tell.
 *
 * omega is bounded above by Gershgorin's theorem on M^-1 H, H = -dF/dx the
 * Jacobian of the sub-cycled forces over the moving rows: each module adds the
 * 2x2 blocks of its interactions (module.h jacobian_blocks), summed per pair of
 * particles here, and the bound is the largest sum over a row of the blocks'
 * norms, divided by the row's mass (1.17-1.18x the true omega for the vein's
 * leaflets). The step's limit is dt <= 1.25/omega_bound, so that the automatic
 * dt (0.8 of it) sits at omega_bound dt = 1: the theory's 2 pi/3 is not enough
 * on the vein, whose leaflets start to ring at a true omega dt of 1.0-1.1 once
 * the valve closes (doc/stability.md, "Multi-rate contact"). */
#ifndef DMHS_SOLID_MODES_H
#define DMHS_SOLID_MODES_H
#include <petscsys.h>
#include "dmhs/particles.h"

struct sim;
struct dt_limits;

/* Per owned row, the blocks H_pq = -dF_p/dx_q summed by partner gid. */
typedef struct solid_jacobian solid_jacobian;

/* Adds B to the block of rows (p, q) (local rows); ignored unless p is an owned
 * moving row and q a moving one. */
PetscErrorCode solid_jacobian_add(solid_jacobian *J, PetscInt p, PetscInt q, const double B[2][2]);

/* Upper bound on the sub-cycled forces' fastest angular frequency [1/s]
 * over all ranks (0 when no module gives blocks). Collective. */
PetscErrorCode solid_modes_omega_bound(struct sim *s, double *omega);

/* the default of -solid_mode_dt_factor */
#define SOLID_MODES_LIMIT 1.25

/* With sub-steps on: appends the limit "solid fastest mode", f/omega with f =
 * s->substeps.mode_factor (-solid_mode_dt_factor, default 1.25; 0 leaves the
 * limit out), which bounds dt itself (not the sub-step). Dashpots on the
 * bonds and angles (-bond_damping, -angle_damping) outgrow the resonance's
 * pumping and let f rise (doc/stability.md). Collective. */
PetscErrorCode solid_modes_add_limit(struct sim *s, struct dt_limits *l);

#endif
