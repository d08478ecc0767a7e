/* Struct-of-arrays particle store: owned particles first, ghosts after.
 * Every per-particle array is one row of the field table (fields.c); growing,
 * ghost copies, checkpoint and output all loop over that table. */
#ifndef DMHS_PARTICLES_H
#define DMHS_PARTICLES_H
#include <petscsys.h>

#define DMHS_DIM 2

/* Fluid and solid share one store, told apart by type. */
typedef enum {
  PTYPE_FLUID = 0, /* SPH liquid, integrated */
  PTYPE_WALL = 1,  /* SPH wall: prescribed velocity, boundary values extrapolated (sph_wall.c) */
  PTYPE_SOLID = 2, /* bonded particle that is also an SPH particle, integrated */
  PTYPE_CLOT =
      3, /* liquid particle joined to a clot (agglomeration.c): SPH, integrated, moved by its
          * bonds, no liquid body force by default, no liquid-solid repulsion with the liquid */
  PTYPE_COUNT
} particle_type;

typedef struct particles {
  PetscInt n_owned;  /* particles [0, n_owned) are owned by this rank */
  PetscInt n_ghost;  /* particles [n_owned, n_owned + n_ghost) are copies (images or other ranks) */
  PetscInt capacity; /* allocated rows of every field */
  PetscInt64 *gid;   /* global id, unique across ranks, stable for the whole run */
  PetscInt *type;    /* particle_type */
  /* optional named marks, each enabled by who uses it (0 = none): */
  PetscInt *load;            /* solid_load: 1 = carries a share of the point load */
  PetscInt *segment;         /* peristalsis: 1 + the pocket whose membrane segment it belongs to */
  PetscInt *tracer;          /* a scene's tracked set of liquid (the colon's white / red, the vein's
                                sinus liquid) */
  double (*x)[DMHS_DIM];     /* position [m] */
  double (*v)[DMHS_DIM];     /* velocity [m/s]; half-step value between the two kicks */
  double (*v_est)[DMHS_DIM]; /* predicted velocity at the force evaluation [m/s] */
  double (*v_visc)[DMHS_DIM];  /* velocity seen by the viscous term (walls: extrapolated) [m/s] */
  double (*a)[DMHS_DIM];       /* acceleration [m/s^2] */
  double (*x0)[DMHS_DIM];      /* optional: initial position (peristalsis' and solid_load's
                                  anchors, displacement diagnostics) [m] */
  double (*x_build)[DMHS_DIM]; /* position at the last neighbour-list build [m] */
  double *mass;                /* [kg] per unit depth */
  double *rho;                 /* density [kg/m^3] */
  double *drho;                /* density rate [kg/m^3/s] */
  double *p;                   /* pressure [Pa] */
  /* optional rows (NULL unless enabled, fields.c) */
  PetscInt *body;     /* solid body id, 0 = none (repulsion between bodies) */
  double *shear_rate; /* sqrt(2 D:D) from the SPH velocity gradient [1/s] */
  double *stress_xx, *stress_xy, *stress_yy; /* virial stress [Pa] (src/diag/stress.c) */
  double *stress_mag;                        /* its Frobenius norm [Pa] */
  double *pressure_force;                    /* |SPH pressure force| [N/m] */
  double *speed;                             /* |v| [m/s] */
  double *displacement;                      /* |x - x0| (minimum image) [m] */
  double (*to_surface)[DMHS_DIM]; /* wall: vector to the nearest wall-surface point [m] */
  PetscInt *side;                 /* vein: side of a leaflet, +-1 upper, +-2 lower, 0 none */
  double (*a_hold)[DMHS_DIM]; /* -solid_substeps: the solid's acceleration from everything but its
                                 own bonds and angles, held over the sub-steps [m/s^2] */
  PetscInt *substepped;       /* -solid_substeps: 1 = moves on this step's sub-steps */
  double *drho_prev; /* -sph_density_predict: drho^n over the step, for the corrector [kg/m^3/s] */
} particles;

PetscErrorCode particles_create(particles *ps);
PetscErrorCode particles_destroy(particles *ps);
/* Make room for at least n rows (owned + ghost); contents of existing rows are kept. */
PetscErrorCode particles_reserve(particles *ps, PetscInt n);
/* Append one owned particle (ghosts must be empty); returns its local index. */
PetscErrorCode particles_add_owned(particles *ps, PetscInt64 gid, particle_type type,
                                   const double x[DMHS_DIM], const double v[DMHS_DIM], double mass,
                                   double rho, PetscInt *index);
/* Copy every field row flagged by `flags` from row src to row dst. */
void particles_copy_row(particles *ps, PetscInt dst, PetscInt src, unsigned flags);
/* Takes owned row i out of the computation for good: a wall at rest (v, v_est, v_visc, a,
 * drho zero; rho = rho_rest) at x_rest, which the caller picks more than a support away
 * from every other particle (a slot of its own: it then enters no sum). The jump past the
 * neighbour skin makes the next step rebuild, so no ghost keeps its old type. */
void particles_retire(particles *ps, PetscInt i, const double x_rest[DMHS_DIM], double rho_rest);
/* Number of owned particles of a type on this rank. */
PetscInt particles_count_type(const particles *ps, particle_type type);

/* mpi: packing rows of selected fields (from the field table) into a byte buffer,
 * particle after particle, for migration and ghosts. */
#include "dmhs/fields.h"
/* Fields whose flags intersect `flags`, in table order; returns how many (<= max). */
int particles_select_fields(unsigned flags, const field_desc **out, int max);
/* Bytes of one packed particle. */
size_t particles_packed_bytes(const field_desc *const *f, int nf);
/* Packs rows[0..n) of the fields f; with shift, shift[e] is added to field x of entry e. */
void particles_pack(const particles *ps, const field_desc *const *f, int nf, const PetscInt *rows,
                    PetscInt n, const double (*shift)[DMHS_DIM], char *buf);
/* Unpacks n particles into rows [first, first + n) (capacity must suffice). */
void particles_unpack(particles *ps, const field_desc *const *f, int nf, PetscInt first, PetscInt n,
                      const char *buf);

#endif
