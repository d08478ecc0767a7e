/* Module agglomeration (src/physics/agglomeration.c): clots that grow from
 * seed particles of the liquid by bonds made at run time.
 *
 * Every -agglomeration_interval of physical time (after the seeds are placed
 * at -agglomeration_start) an event, collective and identical on every rank:
 * liquid particles within R_max of a clot particle are candidates; each
 * candidate picks its closest clot particle that has fewer than max_bonds clot
 * bonds, each such clot particle picks its closest candidate (ties: the lower
 * gid); a mutual pair bonds when its draw u(seed, event, gid pair) < P. A
 * joined particle becomes PTYPE_CLOT, bonded harmonically (bond_harmonic_forces) with
 * the rest length it had at creation. The bonds are added to the topology
 * collectively (topology_add_bonds) under the bond type this module claims, so
 * they travel with their particles, weigh in the partition, appear in snapshots
 * and are checkpointed with the topology. */
#ifndef DMHS_AGGLOMERATION_H
#define DMHS_AGGLOMERATION_H
#include <stdint.h>
#include <petscsys.h>
#include "dmhs/module.h"
#include "dmhs/domain.h"

#define AGGLOMERATION_MAX_SEEDS 8
/* the topology bond type of the clot bonds */
#define AGGLOMERATION_BOND_TYPE 7

/* Counter-based random number: a hash of (seed, event, min gid, max gid), so
 * the draw of a pair depends on nothing else (not the rank, the visiting order
 * or earlier draws). Uniform in [0, 1), symmetric in (ga, gb). */
uint64_t agglomeration_hash(uint64_t seed, uint64_t event, PetscInt64 ga, PetscInt64 gb);
double agglomeration_uniform(uint64_t seed, uint64_t event, PetscInt64 ga, PetscInt64 gb);

/* A clot particle or a candidate, as every rank sees it during an event. */
typedef struct agglomeration_point {
  PetscInt64 gid;
  double x[DMHS_DIM];
  PetscInt n_bonds; /* clot bonds it has (clot particles) */
} agglomeration_point;

typedef struct agglomeration_rules {
  double rmax;        /* [m] */
  double probability; /* [1] */
  PetscInt max_bonds;
  uint64_t seed;
  uint64_t event;    /* event number (1, 2, ...) */
  const domain *dom; /* minimum image when not NULL */
} agglomeration_rules;

/* The pairs of one event: clot[] and cand[] sorted by gid (any order gives
 * the same pairs, since choices tie-break by gid). pairs[k] = (index in clot,
 * index in cand), in increasing clot index; r0[k] their distance. pairs and r0
 * must hold min(n_clot, n_cand) entries. Pure (no communication). */
PetscErrorCode agglomeration_pair(const agglomeration_rules *r, const agglomeration_point *clot,
                                  PetscInt n_clot, const agglomeration_point *cand, PetscInt n_cand,
                                  PetscInt *n_pairs, PetscInt (*pairs)[2], double *r0);

/* Scene side (options pass, after solid_modules_enable): defaults in the scene's
 * units; an automatic seed chooser used when -agglomeration_seeds is not given
 * (collective; returns n <= AGGLOMERATION_MAX_SEEDS liquid gids, the same on
 * every rank). */
typedef PetscErrorCode (*agglomeration_seed_fn)(struct sim *s, void *ctx, PetscInt *n,
                                                PetscInt64 gids[]);
PetscErrorCode agglomeration_set_defaults(module *m, double rmax, double start);
PetscErrorCode agglomeration_set_seed_chooser(module *m, agglomeration_seed_fn fn, void *ctx);
PetscErrorCode agglomeration_module_create(module **m);

#endif
