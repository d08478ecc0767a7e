/* Bonds and angles between solid particles, stored by global id (so they
 * survive migration and ghost rebuilds) and resolved to local rows after every
 * ghost build. Exists only in scenes with solids (sim->topo == NULL otherwise).
 *
 * Resolution (topology_resolve): for every bond/angle with at least one OWNED
 * end, one local entry is made per owned end that still needs its force: the
 * owned row is the anchor and the other ends are the copies (owned or ghost)
 * nearest to it (minimum image when several rows share a gid: periodic
 * images). An entry writes forces into all its rows; writes into ghost rows
 * are discarded (Newton's third law inside a rank only). A bond whose two ends
 * are owned but nearest to each other only through a periodic image gives two
 * entries, one per owned end. Energies are weighted by the share of owned rows
 * in the entry, so sums over entries (and ranks) count every bond once.
 *
 * Exclusions (LAMMPS special_bonds lj/coul 0 0 1 angle yes): 1-2 partners (bonds and the arms of
 * angles) and 1-3 partners (the ends of an angle) are left out of the pair
 * list, hence out of SPH and repulsion sums, unless -special_bonds_include. */
#ifndef DMHS_TOPOLOGY_H
#define DMHS_TOPOLOGY_H
#include <petscsys.h>
#include "dmhs/particles.h"

struct sim;

#define TOPOLOGY_MAX_TYPES 8

typedef struct topology {
  /* by global id: the whole structure, replicated on every rank (solids are a
   * few thousand particles at most; bonds then never migrate) */
  PetscInt n_bonds, n_alloc_bonds;
  PetscInt64 (*bond_gid)[2];
  PetscInt *bond_type;
  double *bond_r0; /* per bond rest length [m]; 0 = the type's r0 (bonds made at run time set it) */
  /* bond type of the bonds made at run time (agglomeration.c), which its own
   * force (bond_clot.c) handles and the bond modules skip; -1 = none */
  PetscInt runtime_type;
  PetscInt n_angles, n_alloc_angles;
  PetscInt64 (*angle_gid)[3]; /* i, j (centre), k */
  PetscInt *angle_type;
  PetscInt n_bond_types, n_angle_types; /* 1 + largest type used */

  /* gid-level tables, rebuilt when the structure changes (dirty) */
  PetscBool dirty;
  PetscInt n_gids;
  PetscInt64 *gids;          /* sorted unique gids of bonded particles */
  PetscInt *ex_start;        /* n_gids + 1 offsets into ex_gid */
  PetscInt64 *ex_gid;        /* per gid: sorted excluded partners (1-2 and 1-3) */
  PetscBool special_include; /* -special_bonds_include: keep bonded pairs in pair sums */

  /* local resolution, valid until the next ghost build */
  PetscBool resolved; /* topology_resolve has run at least once */
  PetscInt *head;     /* per gid slot: first local row with that gid, -1 = none */
  PetscInt *owned;    /* per gid slot: the owned row, -1 = none */
  PetscInt *next;     /* per local row: next row with the same gid, -1 = end */
  PetscInt *slot;     /* per local row: gid slot, -1 = not bonded (exclusion lookup) */
  PetscInt n_alloc_rows;
  PetscInt n_bond_local, n_alloc_bond_local;
  PetscInt (*bond)[2];    /* local rows */
  PetscInt *bond_ltype;   /* type */
  double *bond_weight;    /* energy share: owned rows / 2 */
  PetscInt64 *bond_index; /* global bond index (for messages) */
  PetscInt n_angle_local, n_alloc_angle_local;
  PetscInt (*angle)[3];
  PetscInt *angle_ltype;
  double *angle_weight; /* owned rows / 3 */
} topology;

PetscErrorCode topology_create(topology **t);
PetscErrorCode topology_destroy(topology **t);
/* Scene builders add the structure by global id. */
PetscErrorCode topology_add_bond(topology *t, PetscInt64 gi, PetscInt64 gj, PetscInt type);
/* The same with the bond's own rest length r0 [m] (bonds made at run time). */
PetscErrorCode topology_add_bond_r0(topology *t, PetscInt64 gi, PetscInt64 gj, PetscInt type,
                                    double r0);
PetscErrorCode topology_add_angle(topology *t, PetscInt64 gi, PetscInt64 gj, PetscInt64 gk,
                                  PetscInt type);
/* Index of a bonded particle's gid in t->gids (sorted), or -1 when it has no bond. */
PetscErrorCode topology_gid_slot(topology *t, PetscInt64 gid, PetscInt *slot);
/* Number of bonded (1-2 and 1-3) partners of a particle: its bonded work, for
 * the partition's weights. */
PetscErrorCode topology_partner_count(topology *t, PetscInt64 gid, PetscInt *count);
/* Local entries from gids, after a ghost build (called by neighbours_rebuild). */
PetscErrorCode topology_resolve(topology *t, const particles *ps);
/* True when pair (i, j) (local rows) is excluded from pair sums. */
static inline PetscBool topology_excluded(const topology *t, const particles *ps, PetscInt i,
                                          PetscInt j) {
  const PetscInt si = t->slot[i];
  if (si < 0 || t->slot[j] < 0)
    return PETSC_FALSE;
  const PetscInt64 g = ps->gid[j];
  PetscInt lo = t->ex_start[si], hi = t->ex_start[si + 1];
  while (lo < hi) { /* binary search in a short sorted list */
    const PetscInt mid = (lo + hi) / 2;
    if (t->ex_gid[mid] < g)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < t->ex_start[si + 1] && t->ex_gid[lo] == g ? PETSC_TRUE : PETSC_FALSE;
}

#endif
