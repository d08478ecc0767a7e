/* Bonds and angles by global id: a store distributed with the particles, and its
 * resolution to local rows after every ghost build.
 *
 * Store: each rank holds every bond and angle with at least one end it owns (LAMMPS's
 * newton_bond off), sorted by global bond / angle id. A scene adds its structure on every
 * rank while it builds (topology_add_bond / _angle); the first resolution after the
 * first migration keeps what each rank needs. Migration sends an entry along with each
 * end that leaves (topology_migrate), and each resolution drops the entries no owned end
 * holds any more. At run time, bonds are made and removed collectively
 * (topology_add_bonds / topology_remove_bonds): every rank takes part, the store changes
 * the same way on any rank count, and the next step rebuilds the local lists
 * (topology.changed). The store is checkpointed (topology_checkpoint.c).
 *
 * Any particle type may be a bond end. Each bond type belongs to the module that claims it
 * (topology_claim_bond_type): the harmonic or nonlinear bond module claims the scene's
 * types, the clots their own, and each computes only the entries of its types.
 *
 * Resolution (topology_resolve): for every bond/angle with at least one OWNED
 * end, one local entry is made per owned end that still needs its force: the
 * owned row is the anchor and the other ends are the copies (owned or ghost)
 * nearest to it (minimum image when several rows share a gid: periodic
 * images). An entry writes forces into all its rows; writes into ghost rows
 * are discarded (Newton's third law inside a rank only). A bond whose two ends
 * are owned but nearest to each other only through a periodic image gives two
 * entries, one per owned end. Energies are weighted by the share of owned rows
 * in the entry, so sums over entries (and ranks) count every bond once. Entries
 * follow the global ids, so each particle sums its bonds in the same order on any
 * rank count (bitwise rank invariance).
 *
 * Exclusions (LAMMPS special_bonds lj/coul 0 0 1 angle yes): 1-2 partners (bonds and the
 * arms of angles) and 1-3 partners (the ends of an angle) are left out of the pair
 * list, hence out of SPH and repulsion sums, unless -special_bonds_include. A pair with an
 * owned end finds all its exclusions here, since the store holds every entry of its owned
 * particles; ghost-ghost pairs are never made. */
#ifndef DMHS_TOPOLOGY_H
#define DMHS_TOPOLOGY_H
#include <petscsys.h>
#include <stdint.h>
#include "dmhs/particles.h"

struct sim;

#define TOPOLOGY_MAX_TYPES 8

typedef struct topology {
  /* this rank's store, sorted by id (see above) */
  PetscInt n_bonds, n_alloc_bonds;
  PetscInt64 (*bond_gid)[2];
  PetscInt *bond_type;
  double *bond_r0;     /* per bond rest length [m]; 0 = the type's r0 (run-time bonds set it) */
  PetscInt64 *bond_id; /* global id: creation order, never reused */
  PetscInt n_angles, n_alloc_angles;
  PetscInt64 (*angle_gid)[3]; /* i, j (centre), k */
  PetscInt *angle_type;
  PetscInt64 *angle_id;
  /* replicated: the next ids, and the global counts (every rank sees every change) */
  PetscInt64 next_bond_id, next_angle_id;
  PetscInt64 n_bonds_global, n_angles_global;
  PetscInt64 n_bonds_of_type[TOPOLOGY_MAX_TYPES];
  /* 1 + the largest type of the scene's own bonds/angles (those of no claimed type): the
   * types the bond modules' per-type coefficients must cover */
  PetscInt n_bond_types, n_angle_types;
  /* the module that computes each bond type's forces (topology_claim_bond_type), or NULL */
  const void *bond_owner[TOPOLOGY_MAX_TYPES];
  /* the structure changed at run time since the last resolution: the next step rebuilds */
  PetscBool changed;

  /* gid-level tables of the store, rebuilt when it changes (dirty) */
  PetscBool dirty;
  PetscInt n_gids;
  PetscInt64 *gids;          /* sorted unique gids of bonded particles */
  PetscInt *ex_start;        /* n_gids + 1 offsets into ex_gid */
  PetscInt64 *ex_gid;        /* per gid: sorted excluded partners (1-2 and 1-3) */
  uint64_t *bonded_bits;     /* bit g set: gid g is in gids (a row's O(1) first test) */
  PetscInt64 n_bonded_bits;  /* bits in bonded_bits */
  PetscBool special_include; /* -special_bonds_include: keep bonded pairs in pair sums */

  /* local resolution, valid until the next ghost build */
  PetscBool resolved; /* topology_resolve has run at least once */
  PetscInt *head;     /* per gid slot: first local row with that gid, -1 = none */
  PetscInt *owned;    /* per gid slot: the owned row, -1 = none */
  PetscInt *next;     /* per local row: next row with the same gid, -1 = end */
  PetscInt *slot;     /* per local row: gid slot, -1 = not bonded (exclusion lookup) */
  PetscInt n_alloc_rows;
  PetscInt n_bond_local, n_alloc_bond_local;
  PetscInt (*bond)[2];  /* local rows */
  PetscInt *bond_ltype; /* type */
  double *bond_weight;  /* energy share: owned rows / 2 */
  PetscInt *bond_index; /* the bond's index in this rank's store (bond_r0, bond_id) */
  PetscInt n_angle_local, n_alloc_angle_local;
  PetscInt (*angle)[3];
  PetscInt *angle_ltype;
  double *angle_weight; /* owned rows / 3 */
} topology;

PetscErrorCode topology_create(topology **t);
PetscErrorCode topology_destroy(topology **t);
/* Scene builders add the whole structure by global id, on every rank, before the first
 * neighbour build (ids follow the order of the calls). */
PetscErrorCode topology_add_bond(topology *t, PetscInt64 gi, PetscInt64 gj, PetscInt type);
/* The same with the bond's own rest length r0 [m]. */
PetscErrorCode topology_add_bond_r0(topology *t, PetscInt64 gi, PetscInt64 gj, PetscInt type,
                                    double r0);
PetscErrorCode topology_add_angle(topology *t, PetscInt64 gi, PetscInt64 gj, PetscInt64 gk,
                                  PetscInt type);
/* Module `owner` computes the forces of bond type `type` (error if another module did
 * claim it). Bond modules skip the entries of types they do not own. */
PetscErrorCode topology_claim_bond_type(topology *t, PetscInt type, const void *owner);

/* Run time, collective (topology_exchange.c): rank r passes n[r] bonds (gid pairs, types,
 * rest lengths [m], 0 = the type's); the union over the ranks, ordered by (gid pair, type),
 * gets the next ids and each rank keeps those with an end it owns. Give each bond on one
 * rank only (a bond given twice is made twice). Marks the structure changed. */
PetscErrorCode topology_add_bonds(topology *t, const particles *ps, MPI_Comm comm, PetscInt n,
                                  const PetscInt64 (*gid)[2], const PetscInt *type,
                                  const double *r0);
/* Collective: removes every bond joining one of the given gid pairs (either order) with
 * the given type (-1 = any type); the pairs may be given on any rank. Marks the
 * structure changed. */
PetscErrorCode topology_remove_bonds(topology *t, const particles *ps, MPI_Comm comm, PetscInt n,
                                     const PetscInt64 (*gid)[2], PetscInt type);
/* Migration (called by migrate.c before the leaving rows go): sends every store entry
 * with an end among the n_leave leaving owned rows to that row's destination rank, and
 * merges the entries that arrive. Collective. */
PetscErrorCode topology_migrate(topology *t, const particles *ps, MPI_Comm comm,
                                const PetscInt *leaving, const PetscMPIInt *dest, PetscInt n_leave);
/* Sorted gids of the owned rows, with their rows (for "is this end owned here?" between
 * builds, when the structure may have changed); free with PetscFree2(gid, row). */
PetscErrorCode topology_owned_lookup(const particles *ps, PetscInt64 **gid, PetscInt **row);
/* Row of gid g in a topology_owned_lookup table of n entries, or -1. */
PetscInt topology_lookup_row(const PetscInt64 *gid, const PetscInt *row, PetscInt n, PetscInt64 g);

/* Store internals (topology_exchange.c, the checkpoint): checks that name the entry at
 * fault, and appends with a given id (the caller keeps the store sorted by id). */
PetscErrorCode topology_check_bond(PetscInt64 gi, PetscInt64 gj, PetscInt type, double r0);
PetscErrorCode topology_check_angle(const PetscInt64 gid[3], PetscInt type);
PetscErrorCode topology_store_bond(topology *t, PetscInt64 id, PetscInt64 gi, PetscInt64 gj,
                                   PetscInt type, double r0);
PetscErrorCode topology_store_angle(topology *t, PetscInt64 id, const PetscInt64 gid[3],
                                    PetscInt type);
/* Copies store entry src over entry dst (compacting the store after removals). */
void topology_move_bond(topology *t, PetscInt dst, PetscInt src);
void topology_move_angle(topology *t, PetscInt dst, PetscInt src);
/* Empties the store, keeping the claims and options (a restart loads its own). */
void topology_clear(topology *t);

/* Index of a bonded particle's gid in t->gids (sorted), or -1 when it has no bond here. */
PetscErrorCode topology_gid_slot(topology *t, PetscInt64 gid, PetscInt *slot);
/* Number of bonded (1-2 and 1-3) partners of a particle owned here (or of any particle
 * before the first build): its bonded work, for the partition's weights. */
PetscErrorCode topology_partner_count(topology *t, PetscInt64 gid, PetscInt *count);
/* Local entries from gids, after a ghost build (called by neighbours_rebuild); first drops
 * the store entries no owned row holds. */
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
