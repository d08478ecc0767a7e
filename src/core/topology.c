/* The bond/angle store by global id, its exclusion lists, and its resolution to
 * local rows after every ghost build (see include/dmhs/topology.h). Collective
 * changes and migration are in topology_exchange.c.
 *
 * Cost per build: one pass over the local rows (a bit test per row, a binary search
 * in the sorted bonded-gid table for bonded ones), then one pass over the store.
 * Exclusions are applied once, in the pair-list build (cells.c), only to pairs of
 * two bonded particles: every pair sum (SPH, repulsion) then sees the filtered list
 * at no cost inside its hot loop. */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/topology.h"

PetscErrorCode topology_create(topology **t) {
  PetscFunctionBeginUser;
  PetscCall(PetscNew(t));
  (*t)->dirty = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode topology_destroy(topology **tp) {
  topology *t = *tp;
  PetscFunctionBeginUser;
  if (!t)
    PetscFunctionReturn(0);
  PetscCall(PetscFree4(t->bond_gid, t->bond_type, t->bond_r0, t->bond_id));
  PetscCall(PetscFree3(t->angle_gid, t->angle_type, t->angle_id));
  PetscCall(PetscFree(t->gids));
  PetscCall(PetscFree(t->bonded_bits));
  PetscCall(PetscFree2(t->ex_start, t->ex_gid));
  PetscCall(PetscFree2(t->head, t->owned));
  PetscCall(PetscFree2(t->next, t->slot));
  PetscCall(PetscFree4(t->bond, t->bond_ltype, t->bond_weight, t->bond_index));
  PetscCall(PetscFree3(t->angle, t->angle_ltype, t->angle_weight));
  PetscCall(PetscFree(*tp));
  PetscFunctionReturn(0);
}

PetscErrorCode topology_add_bond(topology *t, PetscInt64 gi, PetscInt64 gj, PetscInt type) {
  PetscFunctionBeginUser;
  PetscCall(topology_add_bond_r0(t, gi, gj, type, 0.0));
  PetscFunctionReturn(0);
}

PetscErrorCode topology_check_bond(PetscInt64 gi, PetscInt64 gj, PetscInt type, double r0) {
  PetscFunctionBeginUser;
  PetscCheck(r0 >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "bond %" PetscInt64_FMT "-%" PetscInt64_FMT ": rest length %g m < 0", gi, gj, r0);
  PetscCheck(gi != gj, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "bond from particle gid %" PetscInt64_FMT " to itself", gi);
  PetscCheck(gi >= 0 && gj >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "bond %" PetscInt64_FMT "-%" PetscInt64_FMT ": a negative gid", gi, gj);
  PetscCheck(type >= 0 && type < TOPOLOGY_MAX_TYPES, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "bond %" PetscInt64_FMT "-%" PetscInt64_FMT ": type %" PetscInt_FMT " outside [0, %d)",
             gi, gj, type, TOPOLOGY_MAX_TYPES);
  PetscFunctionReturn(0);
}

PetscErrorCode topology_check_angle(const PetscInt64 g[3], PetscInt type) {
  PetscFunctionBeginUser;
  PetscCheck(g[0] != g[1] && g[1] != g[2] && g[0] != g[2], PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "angle %" PetscInt64_FMT "-%" PetscInt64_FMT "-%" PetscInt64_FMT " repeats a particle",
             g[0], g[1], g[2]);
  PetscCheck(g[0] >= 0 && g[1] >= 0 && g[2] >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "angle %" PetscInt64_FMT "-%" PetscInt64_FMT "-%" PetscInt64_FMT ": a negative gid",
             g[0], g[1], g[2]);
  PetscCheck(type >= 0 && type < TOPOLOGY_MAX_TYPES, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "angle %" PetscInt64_FMT "-%" PetscInt64_FMT "-%" PetscInt64_FMT
             ": type %" PetscInt_FMT " outside [0, %d)",
             g[0], g[1], g[2], type, TOPOLOGY_MAX_TYPES);
  PetscFunctionReturn(0);
}

PetscErrorCode topology_store_bond(topology *t, PetscInt64 id, PetscInt64 gi, PetscInt64 gj,
                                   PetscInt type, double r0) {
  PetscFunctionBeginUser;
  if (t->n_bonds == t->n_alloc_bonds) {
    const PetscInt grown = PetscMax(64, 2 * t->n_alloc_bonds);
    PetscInt64(*g)[2], *ids;
    PetscInt *ty;
    double *r;
    PetscCall(PetscMalloc4(grown, &g, grown, &ty, grown, &r, grown, &ids));
    if (t->n_bonds) {
      PetscCall(PetscArraycpy(g, t->bond_gid, t->n_bonds));
      PetscCall(PetscArraycpy(ty, t->bond_type, t->n_bonds));
      PetscCall(PetscArraycpy(r, t->bond_r0, t->n_bonds));
      PetscCall(PetscArraycpy(ids, t->bond_id, t->n_bonds));
    }
    PetscCall(PetscFree4(t->bond_gid, t->bond_type, t->bond_r0, t->bond_id));
    t->bond_gid = g;
    t->bond_type = ty;
    t->bond_r0 = r;
    t->bond_id = ids;
    t->n_alloc_bonds = grown;
  }
  t->bond_gid[t->n_bonds][0] = gi;
  t->bond_gid[t->n_bonds][1] = gj;
  t->bond_type[t->n_bonds] = type;
  t->bond_r0[t->n_bonds] = r0;
  t->bond_id[t->n_bonds] = id;
  t->n_bonds++;
  t->dirty = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode topology_store_angle(topology *t, PetscInt64 id, const PetscInt64 gid[3],
                                    PetscInt type) {
  PetscFunctionBeginUser;
  if (t->n_angles == t->n_alloc_angles) {
    const PetscInt grown = PetscMax(64, 2 * t->n_alloc_angles);
    PetscInt64(*g)[3], *ids;
    PetscInt *ty;
    PetscCall(PetscMalloc3(grown, &g, grown, &ty, grown, &ids));
    if (t->n_angles) {
      PetscCall(PetscArraycpy(g, t->angle_gid, t->n_angles));
      PetscCall(PetscArraycpy(ty, t->angle_type, t->n_angles));
      PetscCall(PetscArraycpy(ids, t->angle_id, t->n_angles));
    }
    PetscCall(PetscFree3(t->angle_gid, t->angle_type, t->angle_id));
    t->angle_gid = g;
    t->angle_type = ty;
    t->angle_id = ids;
    t->n_alloc_angles = grown;
  }
  for (int k = 0; k < 3; k++)
    t->angle_gid[t->n_angles][k] = gid[k];
  t->angle_type[t->n_angles] = type;
  t->angle_id[t->n_angles] = id;
  t->n_angles++;
  t->dirty = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode topology_add_bond_r0(topology *t, PetscInt64 gi, PetscInt64 gj, PetscInt type,
                                    double r0) {
  PetscFunctionBeginUser;
  PetscCall(topology_check_bond(gi, gj, type, r0));
  PetscCall(topology_store_bond(t, t->next_bond_id++, gi, gj, type, r0));
  t->n_bonds_global++;
  t->n_bonds_of_type[type]++;
  if (!t->bond_owner[type])
    t->n_bond_types = PetscMax(t->n_bond_types, type + 1);
  PetscFunctionReturn(0);
}

PetscErrorCode topology_add_angle(topology *t, PetscInt64 gi, PetscInt64 gj, PetscInt64 gk,
                                  PetscInt type) {
  const PetscInt64 g[3] = {gi, gj, gk};
  PetscFunctionBeginUser;
  PetscCall(topology_check_angle(g, type));
  PetscCall(topology_store_angle(t, t->next_angle_id++, g, type));
  t->n_angles_global++;
  t->n_angle_types = PetscMax(t->n_angle_types, type + 1);
  PetscFunctionReturn(0);
}

void topology_move_bond(topology *t, PetscInt dst, PetscInt src) {
  if (dst == src)
    return;
  t->bond_gid[dst][0] = t->bond_gid[src][0];
  t->bond_gid[dst][1] = t->bond_gid[src][1];
  t->bond_type[dst] = t->bond_type[src];
  t->bond_r0[dst] = t->bond_r0[src];
  t->bond_id[dst] = t->bond_id[src];
}

void topology_move_angle(topology *t, PetscInt dst, PetscInt src) {
  if (dst == src)
    return;
  for (int k = 0; k < 3; k++)
    t->angle_gid[dst][k] = t->angle_gid[src][k];
  t->angle_type[dst] = t->angle_type[src];
  t->angle_id[dst] = t->angle_id[src];
}

void topology_clear(topology *t) {
  t->n_bonds = t->n_angles = 0;
  t->n_bonds_global = t->n_angles_global = 0;
  t->next_bond_id = t->next_angle_id = 0;
  for (int k = 0; k < TOPOLOGY_MAX_TYPES; k++)
    t->n_bonds_of_type[k] = 0;
  t->dirty = PETSC_TRUE;
  t->changed = PETSC_TRUE;
}

PetscErrorCode topology_claim_bond_type(topology *t, PetscInt type, const void *owner) {
  PetscFunctionBeginUser;
  PetscCheck(type >= 0 && type < TOPOLOGY_MAX_TYPES, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "bond type %" PetscInt_FMT " outside [0, %d)", type, TOPOLOGY_MAX_TYPES);
  PetscCheck(!t->bond_owner[type] || t->bond_owner[type] == owner, PETSC_COMM_SELF,
             PETSC_ERR_ARG_INCOMP,
             "bond type %" PetscInt_FMT " is claimed by two modules (each bond type belongs "
             "to one force)",
             type);
  t->bond_owner[type] = owner;
  PetscFunctionReturn(0);
}

static int cmp_int64(const void *a, const void *b) {
  const PetscInt64 x = *(const PetscInt64 *)a, y = *(const PetscInt64 *)b;
  return (x > y) - (x < y);
}

/* Slot of gid g in the sorted table, or -1. */
static PetscInt topology_slot_of(const topology *t, PetscInt64 g) {
  PetscInt lo = 0, hi = t->n_gids;
  while (lo < hi) {
    const PetscInt mid = (lo + hi) / 2;
    if (t->gids[mid] < g)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < t->n_gids && t->gids[lo] == g ? lo : -1;
}

/* Sorted unique bonded gids, and per gid the sorted unique excluded partners:
 * bond ends (1-2), angle arms (1-2) and angle ends (1-3). */
static PetscErrorCode topology_build_tables(topology *t) {
  PetscInt64 *all, (*pairs)[2];
  PetscInt n_all = 0, n_pairs = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscFree(t->gids));
  PetscCall(PetscFree2(t->ex_start, t->ex_gid));
  PetscCall(PetscFree2(t->head, t->owned));
  PetscCall(PetscMalloc1(2 * t->n_bonds + 3 * t->n_angles + 1, &all));
  for (PetscInt b = 0; b < t->n_bonds; b++) {
    all[n_all++] = t->bond_gid[b][0];
    all[n_all++] = t->bond_gid[b][1];
  }
  for (PetscInt a = 0; a < t->n_angles; a++)
    for (int k = 0; k < 3; k++)
      all[n_all++] = t->angle_gid[a][k];
  qsort(all, (size_t)n_all, sizeof(PetscInt64), cmp_int64);
  PetscInt n_unique = 0;
  for (PetscInt k = 0; k < n_all; k++)
    if (!n_unique || all[k] != all[n_unique - 1])
      all[n_unique++] = all[k];
  t->gids = all;
  t->n_gids = n_unique;

  /* directed exclusion pairs (a, b), sorted, unique */
  PetscCall(PetscMalloc1(2 * t->n_bonds + 6 * t->n_angles + 1, &pairs));
#define PUSH(a, b)                                                                                 \
  do {                                                                                             \
    pairs[n_pairs][0] = (a);                                                                       \
    pairs[n_pairs][1] = (b);                                                                       \
    n_pairs++;                                                                                     \
  } while (0)
  for (PetscInt b = 0; b < t->n_bonds; b++) {
    PUSH(t->bond_gid[b][0], t->bond_gid[b][1]);
    PUSH(t->bond_gid[b][1], t->bond_gid[b][0]);
  }
  for (PetscInt a = 0; a < t->n_angles; a++)
    for (int p = 0; p < 3; p++)
      for (int q = 0; q < 3; q++)
        if (p != q)
          PUSH(t->angle_gid[a][p], t->angle_gid[a][q]);
#undef PUSH
  qsort(pairs, (size_t)n_pairs, sizeof(pairs[0]), cmp_int64); /* by the first member only */
  /* then each run of equal first members by the second */
  for (PetscInt k = 0; k < n_pairs;) {
    PetscInt e = k;
    while (e < n_pairs && pairs[e][0] == pairs[k][0])
      e++;
    PetscInt64 *second;
    PetscCall(PetscMalloc1(e - k, &second));
    for (PetscInt q = k; q < e; q++)
      second[q - k] = pairs[q][1];
    qsort(second, (size_t)(e - k), sizeof(PetscInt64), cmp_int64);
    for (PetscInt q = k; q < e; q++)
      pairs[q][1] = second[q - k];
    PetscCall(PetscFree(second));
    k = e;
  }
  PetscCall(PetscMalloc2(n_unique + 1, &t->ex_start, n_pairs + 1, &t->ex_gid));
  PetscInt n_ex = 0, s = 0;
  t->ex_start[0] = 0;
  for (PetscInt k = 0; k < n_pairs; k++) {
    if (k && pairs[k][0] == pairs[k - 1][0] && pairs[k][1] == pairs[k - 1][1])
      continue;
    while (t->gids[s] != pairs[k][0])
      t->ex_start[++s] = n_ex; /* gids and pairs share the sorted first column */
    t->ex_gid[n_ex++] = pairs[k][1];
  }
  while (s < n_unique)
    t->ex_start[++s] = n_ex;
  PetscCall(PetscFree(pairs));
  PetscCall(PetscMalloc2(n_unique, &t->head, n_unique, &t->owned));
  /* one bit per gid up to the largest bonded one: most rows (the liquid) are not
   * bonded, and a bit test tells them apart without the binary search */
  PetscCall(PetscFree(t->bonded_bits));
  t->n_bonded_bits = n_unique ? t->gids[n_unique - 1] + 1 : 0;
  PetscCall(PetscCalloc1(t->n_bonded_bits / 64 + 1, &t->bonded_bits));
  for (PetscInt k = 0; k < n_unique; k++)
    t->bonded_bits[t->gids[k] / 64] |= (uint64_t)1 << (t->gids[k] % 64);
  t->dirty = PETSC_FALSE;
  PetscFunctionReturn(0);
}

static PetscErrorCode topology_push_bond(topology *t, PetscInt i, PetscInt j, PetscInt type,
                                         double w, PetscInt b) {
  PetscFunctionBeginUser;
  if (t->n_bond_local == t->n_alloc_bond_local) {
    const PetscInt grown = PetscMax(64, 2 * t->n_alloc_bond_local);
    PetscInt(*bond)[2], *ty, *ix;
    double *wt;
    PetscCall(PetscMalloc4(grown, &bond, grown, &ty, grown, &wt, grown, &ix));
    if (t->n_bond_local) {
      PetscCall(PetscArraycpy(bond, t->bond, t->n_bond_local));
      PetscCall(PetscArraycpy(ty, t->bond_ltype, t->n_bond_local));
      PetscCall(PetscArraycpy(wt, t->bond_weight, t->n_bond_local));
      PetscCall(PetscArraycpy(ix, t->bond_index, t->n_bond_local));
    }
    PetscCall(PetscFree4(t->bond, t->bond_ltype, t->bond_weight, t->bond_index));
    t->bond = bond;
    t->bond_ltype = ty;
    t->bond_weight = wt;
    t->bond_index = ix;
    t->n_alloc_bond_local = grown;
  }
  t->bond[t->n_bond_local][0] = i;
  t->bond[t->n_bond_local][1] = j;
  t->bond_ltype[t->n_bond_local] = type;
  t->bond_weight[t->n_bond_local] = w;
  t->bond_index[t->n_bond_local] = b;
  t->n_bond_local++;
  PetscFunctionReturn(0);
}

static PetscErrorCode topology_push_angle(topology *t, const PetscInt r[3], PetscInt type,
                                          double w) {
  PetscFunctionBeginUser;
  if (t->n_angle_local == t->n_alloc_angle_local) {
    const PetscInt grown = PetscMax(64, 2 * t->n_alloc_angle_local);
    PetscInt(*angle)[3], *ty;
    double *wt;
    PetscCall(PetscMalloc3(grown, &angle, grown, &ty, grown, &wt));
    if (t->n_angle_local) {
      PetscCall(PetscArraycpy(angle, t->angle, t->n_angle_local));
      PetscCall(PetscArraycpy(ty, t->angle_ltype, t->n_angle_local));
      PetscCall(PetscArraycpy(wt, t->angle_weight, t->n_angle_local));
    }
    PetscCall(PetscFree3(t->angle, t->angle_ltype, t->angle_weight));
    t->angle = angle;
    t->angle_ltype = ty;
    t->angle_weight = wt;
    t->n_alloc_angle_local = grown;
  }
  for (int k = 0; k < 3; k++)
    t->angle[t->n_angle_local][k] = r[k];
  t->angle_ltype[t->n_angle_local] = type;
  t->angle_weight[t->n_angle_local] = w;
  t->n_angle_local++;
  PetscFunctionReturn(0);
}

/* The row holding gid slot s that is nearest to position x (minimum image
 * among copies), or -1 when this rank holds no copy. */
static PetscInt topology_nearest(const topology *t, const particles *ps, PetscInt s,
                                 const double x[DMHS_DIM]) {
  PetscInt best = -1;
  double best_d2 = INFINITY;
  for (PetscInt r = t->head[s]; r >= 0; r = t->next[r]) {
    const double dx = ps->x[r][0] - x[0], dy = ps->x[r][1] - x[1], d2 = dx * dx + dy * dy;
    if (d2 < best_d2) {
      best_d2 = d2;
      best = r;
    }
  }
  return best;
}

PetscErrorCode topology_gid_slot(topology *t, PetscInt64 gid, PetscInt *slot) {
  PetscFunctionBeginUser;
  if (t->dirty)
    PetscCall(topology_build_tables(t));
  PetscInt lo = 0, hi = t->n_gids;
  while (lo < hi) {
    const PetscInt mid = (lo + hi) / 2;
    if (t->gids[mid] < gid)
      lo = mid + 1;
    else
      hi = mid;
  }
  *slot = lo < t->n_gids && t->gids[lo] == gid ? lo : -1;
  PetscFunctionReturn(0);
}

PetscErrorCode topology_partner_count(topology *t, PetscInt64 gid, PetscInt *count) {
  PetscInt k;
  PetscFunctionBeginUser;
  PetscCall(topology_gid_slot(t, gid, &k));
  *count = k < 0 ? 0 : t->ex_start[k + 1] - t->ex_start[k];
  PetscFunctionReturn(0);
}

/* Slot of row r's gid, or -1 when the row is not bonded (a bit test first). */
static inline PetscInt topology_row_slot(const topology *t, PetscInt64 g) {
  if (g < 0 || g >= t->n_bonded_bits || !((t->bonded_bits[g / 64] >> (g % 64)) & 1))
    return -1;
  return topology_slot_of(t, g);
}

/* gid -> rows: owned rows first, then ghosts (rows are visited in reverse so each chain
 * lists rows in increasing order: the owned copy heads it). Any particle type may be
 * bonded. */
static void topology_map_rows(topology *t, const particles *ps, PetscInt n) {
  for (PetscInt s = 0; s < t->n_gids; s++)
    t->head[s] = t->owned[s] = -1;
  for (PetscInt r = n - 1; r >= 0; r--) {
    t->next[r] = -1;
    const PetscInt s = t->slot[r] = topology_row_slot(t, ps->gid[r]);
    if (s < 0)
      continue;
    t->next[r] = t->head[s];
    t->head[s] = r;
    if (r < ps->n_owned)
      t->owned[s] = r;
  }
}

/* Drops the store entries none of whose ends is owned here (they left with migrated
 * particles, whose new owners received them); the order of the rest is kept. Returns
 * whether any went. */
static PetscBool topology_prune(topology *t) {
  PetscInt kept = 0;
  const PetscInt nb = t->n_bonds, na = t->n_angles;
  for (PetscInt b = 0; b < nb; b++) {
    if (t->owned[topology_slot_of(t, t->bond_gid[b][0])] < 0 &&
        t->owned[topology_slot_of(t, t->bond_gid[b][1])] < 0)
      continue;
    topology_move_bond(t, kept++, b);
  }
  t->n_bonds = kept;
  kept = 0;
  for (PetscInt a = 0; a < na; a++) {
    PetscBool mine = PETSC_FALSE;
    for (int k = 0; k < 3; k++)
      if (t->owned[topology_slot_of(t, t->angle_gid[a][k])] >= 0)
        mine = PETSC_TRUE;
    if (!mine)
      continue;
    topology_move_angle(t, kept++, a);
  }
  t->n_angles = kept;
  return t->n_bonds < nb || t->n_angles < na ? PETSC_TRUE : PETSC_FALSE;
}

PetscErrorCode topology_resolve(topology *t, const particles *ps) {
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscFunctionBeginUser;
  if (t->dirty)
    PetscCall(topology_build_tables(t));
  if (n > t->n_alloc_rows) {
    PetscCall(PetscFree2(t->next, t->slot));
    t->n_alloc_rows = n + n / 4 + 16;
    PetscCall(PetscMalloc2(t->n_alloc_rows, &t->next, t->n_alloc_rows, &t->slot));
  }
  topology_map_rows(t, ps, n);
  if (topology_prune(t)) { /* the tables shrink with the store */
    PetscCall(topology_build_tables(t));
    topology_map_rows(t, ps, n);
  }
  t->changed = PETSC_FALSE;

  t->n_bond_local = 0;
  for (PetscInt b = 0; b < t->n_bonds; b++) {
    const PetscInt sa = topology_slot_of(t, t->bond_gid[b][0]),
                   sb = topology_slot_of(t, t->bond_gid[b][1]);
    const PetscInt oa = t->owned[sa], ob = t->owned[sb];
    PetscBool b_done = PETSC_FALSE;
    if (oa >= 0) {
      const PetscInt rb = topology_nearest(t, ps, sb, ps->x[oa]);
      PetscCheck(rb >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "bond %" PetscInt64_FMT "-%" PetscInt64_FMT ": partner gid %" PetscInt64_FMT
                 " is neither owned nor a ghost here (does it exist? is it farther than the "
                 "ghost width?)",
                 t->bond_gid[b][0], t->bond_gid[b][1], t->bond_gid[b][1]);
      b_done = rb == ob ? PETSC_TRUE : PETSC_FALSE;
      PetscCall(topology_push_bond(t, oa, rb, t->bond_type[b], b_done ? 1.0 : 0.5, b));
    }
    if (ob >= 0 && !b_done) {
      const PetscInt ra = topology_nearest(t, ps, sa, ps->x[ob]);
      PetscCheck(ra >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "bond %" PetscInt64_FMT "-%" PetscInt64_FMT ": partner gid %" PetscInt64_FMT
                 " is neither owned nor a ghost here (does it exist? is it farther than the "
                 "ghost width?)",
                 t->bond_gid[b][0], t->bond_gid[b][1], t->bond_gid[b][0]);
      PetscCall(topology_push_bond(t, ra, ob, t->bond_type[b], ra == oa ? 1.0 : 0.5, b));
    }
  }

  t->n_angle_local = 0;
  for (PetscInt a = 0; a < t->n_angles; a++) {
    PetscInt s[3], o[3];
    PetscBool done[3];
    for (int k = 0; k < 3; k++) {
      s[k] = topology_slot_of(t, t->angle_gid[a][k]);
      o[k] = t->owned[s[k]];
      done[k] = o[k] < 0 ? PETSC_TRUE : PETSC_FALSE; /* only owned ends need their force here */
    }
    for (int anchor = 0; anchor < 3; anchor++) {
      if (done[anchor])
        continue;
      PetscInt r[3] = {-1, -1, -1};
      r[anchor] = o[anchor];
      /* from the anchor through the centre (1) to the far end */
      if (anchor != 1)
        r[1] = topology_nearest(t, ps, s[1], ps->x[r[anchor]]);
      for (int k = 0; k < 3; k += 2)
        if (k != anchor && r[1] >= 0)
          r[k] = topology_nearest(t, ps, s[k], ps->x[r[1]]);
      for (int k = 0; k < 3; k++)
        PetscCheck(r[1] >= 0 && r[k] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                   "angle %" PetscInt64_FMT "-%" PetscInt64_FMT "-%" PetscInt64_FMT
                   ": particle gid %" PetscInt64_FMT
                   " (owned here) has partner gid %" PetscInt64_FMT
                   " neither owned nor a ghost here (is it farther than the ghost width?)",
                   t->angle_gid[a][0], t->angle_gid[a][1], t->angle_gid[a][2],
                   t->angle_gid[a][anchor], t->angle_gid[a][r[1] >= 0 ? k : 1]);
      int n_owned_rows = 0;
      for (int k = 0; k < 3; k++)
        if (r[k] < ps->n_owned) {
          n_owned_rows++;
          done[k] = PETSC_TRUE;
        }
      PetscCall(topology_push_angle(t, r, t->angle_type[a], n_owned_rows / 3.0));
    }
  }
  t->resolved = PETSC_TRUE;
  PetscFunctionReturn(0);
}
