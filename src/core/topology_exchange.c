/* The distributed bond/angle store across ranks (include/dmhs/topology.h): collective
 * adds and removals at run time, and the entries that travel with migrating particles.
 *
 * Determinism: a collective add gathers every rank's new entries, orders the union by
 * its gids (not by rank), and numbers it from the replicated next id, so the ids, hence
 * every particle's order of bond sums, are the same on any rank count. */
#include <limits.h>
#include <math.h>
#include <string.h>
#include "dmhs/topology.h"
#include "dmhs/gather.h"

/* A bond or an angle as it travels between ranks (gid[2] unused for bonds). */
typedef struct {
  PetscInt64 id, gid[3], type;
  double r0;
} topology_msg;

static int cmp_msg_gids(const void *pa, const void *pb) {
  const topology_msg *a = pa, *b = pb;
  for (int k = 0; k < 3; k++)
    if (a->gid[k] != b->gid[k])
      return (a->gid[k] > b->gid[k]) - (a->gid[k] < b->gid[k]);
  if (a->type != b->type)
    return (a->type > b->type) - (a->type < b->type);
  return (a->r0 > b->r0) - (a->r0 < b->r0);
}

static int cmp_msg_id(const void *pa, const void *pb) {
  const topology_msg *a = pa, *b = pb;
  return (a->id > b->id) - (a->id < b->id);
}

typedef struct {
  PetscInt64 gid;
  PetscInt row;
} gid_row;

static int cmp_gid_row(const void *pa, const void *pb) {
  const gid_row *a = pa, *b = pb;
  return (a->gid > b->gid) - (a->gid < b->gid);
}

PetscErrorCode topology_owned_lookup(const particles *ps, PetscInt64 **gid, PetscInt **row) {
  gid_row *tmp;
  const PetscInt n = ps->n_owned;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n + 1, &tmp));
  for (PetscInt i = 0; i < n; i++) {
    tmp[i].gid = ps->gid[i];
    tmp[i].row = i;
  }
  qsort(tmp, (size_t)n, sizeof(gid_row), cmp_gid_row);
  PetscCall(PetscMalloc2(n + 1, gid, n + 1, row));
  for (PetscInt i = 0; i < n; i++) {
    (*gid)[i] = tmp[i].gid;
    (*row)[i] = tmp[i].row;
  }
  PetscCall(PetscFree(tmp));
  PetscFunctionReturn(0);
}

PetscInt topology_lookup_row(const PetscInt64 *gid, const PetscInt *row, PetscInt n, PetscInt64 g) {
  PetscInt lo = 0, hi = n;
  while (lo < hi) {
    const PetscInt mid = (lo + hi) / 2;
    if (gid[mid] < g)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < n && gid[lo] == g ? row[lo] : -1;
}

/* Every rank's n messages, concatenated in rank order, on every rank. */
static PetscErrorCode topology_allgather(MPI_Comm comm, const topology_msg *mine, PetscInt n,
                                         topology_msg **all, PetscInt *n_all) {
  size_t total;
  PetscFunctionBeginUser;
  PetscCall(gather_all(comm, "topology entries", mine, (size_t)n, sizeof(topology_msg), all, &total,
                       NULL));
  *n_all = (PetscInt)total;
  PetscFunctionReturn(0);
}

/* Every rank's entries on every rank, ordered by their gids (not by rank): what makes
 * the collective changes rank-count invariant. */
static PetscErrorCode topology_gather_sorted(MPI_Comm comm, const topology_msg *mine, PetscInt n,
                                             topology_msg **all, PetscInt *n_all) {
  PetscFunctionBeginUser;
  PetscCall(topology_allgather(comm, mine, n, all, n_all));
  qsort(*all, (size_t)*n_all, sizeof(topology_msg), cmp_msg_gids);
  PetscFunctionReturn(0);
}

PetscErrorCode topology_add_bonds(topology *t, const particles *ps, MPI_Comm comm, PetscInt n,
                                  const PetscInt64 (*gid)[2], const PetscInt *type,
                                  const double *r0) {
  topology_msg *mine, *all;
  PetscInt n_all;
  PetscInt64 *og;
  PetscInt *orow;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n + 1, &mine));
  for (PetscInt k = 0; k < n; k++) {
    PetscCall(topology_check_bond(gid[k][0], gid[k][1], type[k], r0 ? r0[k] : 0.0));
    mine[k] = (topology_msg){-1, {gid[k][0], gid[k][1], -1}, type[k], r0 ? r0[k] : 0.0};
  }
  PetscCall(topology_gather_sorted(comm, mine, n, &all, &n_all));
  PetscCall(topology_owned_lookup(ps, &og, &orow));
  for (PetscInt k = 0; k < n_all; k++) {
    const topology_msg *m = &all[k];
    const PetscInt64 id = t->next_bond_id++;
    t->n_bonds_global++;
    t->n_bonds_of_type[m->type]++;
    if (topology_lookup_row(og, orow, ps->n_owned, m->gid[0]) >= 0 ||
        topology_lookup_row(og, orow, ps->n_owned, m->gid[1]) >= 0)
      PetscCall(topology_store_bond(t, id, m->gid[0], m->gid[1], (PetscInt)m->type, m->r0));
  }
  if (n_all)
    t->changed = PETSC_TRUE;
  PetscCall(PetscFree2(og, orow));
  PetscCall(PetscFree(all));
  PetscCall(PetscFree(mine));
  PetscFunctionReturn(0);
}

/* Is the store entry with these gids among the gathered removals (sorted)? */
static PetscBool topology_listed(const topology_msg *all, PetscInt n, const PetscInt64 g[3]) {
  PetscInt lo = 0, hi = n;
  const topology_msg key = {0, {g[0], g[1], g[2]}, -1, -INFINITY};
  while (lo < hi) { /* first entry >= key (key sorts before every type and r0) */
    const PetscInt mid = (lo + hi) / 2;
    if (cmp_msg_gids(&all[mid], &key) < 0)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < n && all[lo].gid[0] == g[0] && all[lo].gid[1] == g[1] && all[lo].gid[2] == g[2]
             ? PETSC_TRUE
             : PETSC_FALSE;
}

PetscErrorCode topology_remove_bonds(topology *t, const particles *ps, MPI_Comm comm, PetscInt n,
                                     const PetscInt64 (*gid)[2], PetscInt type) {
  topology_msg *mine, *all;
  PetscInt n_all, kept = 0, *orow;
  PetscInt64 *og;
  /* removed per type, each counted by the rank that owns its first end (once) */
  PetscInt64 removed[TOPOLOGY_MAX_TYPES] = {0};
  PetscFunctionBeginUser;
  PetscCheck(type >= -1 && type < TOPOLOGY_MAX_TYPES, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "topology_remove_bonds: type %" PetscInt_FMT " outside [-1, %d)", type,
             TOPOLOGY_MAX_TYPES);
  PetscCall(PetscMalloc1(n + 1, &mine));
  for (PetscInt k = 0; k < n; k++) /* either order: listed as (lower, higher) */
    mine[k] = (topology_msg){
        -1, {PetscMin(gid[k][0], gid[k][1]), PetscMax(gid[k][0], gid[k][1]), -1}, 0, 0.0};
  PetscCall(topology_gather_sorted(comm, mine, n, &all, &n_all));
  PetscCall(topology_owned_lookup(ps, &og, &orow));
  for (PetscInt b = 0; b < t->n_bonds; b++) {
    const PetscInt64 g[3] = {PetscMin(t->bond_gid[b][0], t->bond_gid[b][1]),
                             PetscMax(t->bond_gid[b][0], t->bond_gid[b][1]), -1};
    if ((type < 0 || t->bond_type[b] == type) && topology_listed(all, n_all, g)) {
      if (topology_lookup_row(og, orow, ps->n_owned, t->bond_gid[b][0]) >= 0)
        removed[t->bond_type[b]]++;
      continue;
    }
    topology_move_bond(t, kept++, b);
  }
  t->n_bonds = kept;
  t->dirty = PETSC_TRUE;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, removed, TOPOLOGY_MAX_TYPES, MPIU_INT64, MPI_SUM, comm));
  for (int ty = 0; ty < TOPOLOGY_MAX_TYPES; ty++) {
    t->n_bonds_of_type[ty] -= removed[ty];
    t->n_bonds_global -= removed[ty];
  }
  if (n_all)
    t->changed = PETSC_TRUE;
  PetscCall(PetscFree2(og, orow));
  PetscCall(PetscFree(all));
  PetscCall(PetscFree(mine));
  PetscFunctionReturn(0);
}

/* Sorts the store by id and drops repeated ids (an entry that arrived from two ranks, or
 * that this rank held already). */
static PetscErrorCode topology_sort_store(topology *t) {
  topology_msg *m;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(PetscMax(t->n_bonds, t->n_angles) + 1, &m));
  for (PetscInt b = 0; b < t->n_bonds; b++)
    m[b] = (topology_msg){
        t->bond_id[b], {t->bond_gid[b][0], t->bond_gid[b][1], -1}, t->bond_type[b], t->bond_r0[b]};
  qsort(m, (size_t)t->n_bonds, sizeof(topology_msg), cmp_msg_id);
  PetscInt kept = 0;
  for (PetscInt b = 0; b < t->n_bonds; b++) {
    if (kept && m[b].id == t->bond_id[kept - 1])
      continue;
    t->bond_id[kept] = m[b].id;
    t->bond_gid[kept][0] = m[b].gid[0];
    t->bond_gid[kept][1] = m[b].gid[1];
    t->bond_type[kept] = (PetscInt)m[b].type;
    t->bond_r0[kept] = m[b].r0;
    kept++;
  }
  t->n_bonds = kept;
  for (PetscInt a = 0; a < t->n_angles; a++)
    m[a] = (topology_msg){t->angle_id[a],
                          {t->angle_gid[a][0], t->angle_gid[a][1], t->angle_gid[a][2]},
                          t->angle_type[a],
                          0.0};
  qsort(m, (size_t)t->n_angles, sizeof(topology_msg), cmp_msg_id);
  kept = 0;
  for (PetscInt a = 0; a < t->n_angles; a++) {
    if (kept && m[a].id == t->angle_id[kept - 1])
      continue;
    t->angle_id[kept] = m[a].id;
    for (int k = 0; k < 3; k++)
      t->angle_gid[kept][k] = m[a].gid[k];
    t->angle_type[kept] = (PetscInt)m[a].type;
    kept++;
  }
  t->n_angles = kept;
  t->dirty = PETSC_TRUE;
  PetscCall(PetscFree(m));
  PetscFunctionReturn(0);
}

PetscErrorCode topology_migrate(topology *t, const particles *ps, MPI_Comm comm,
                                const PetscInt *leaving, const PetscMPIInt *dest,
                                PetscInt n_leave) {
  PetscMPIInt size;
  gid_row *out; /* leaving gids with their destination, sorted by gid */
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscMalloc1(n_leave + 1, &out));
  for (PetscInt k = 0; k < n_leave; k++) {
    out[k].gid = ps->gid[leaving[k]];
    out[k].row = (PetscInt)dest[leaving[k]];
  }
  qsort(out, (size_t)n_leave, sizeof(gid_row), cmp_gid_row);
  /* entries with a leaving end, once per destination, grouped by destination */
  PetscInt n_send = 0, cap = 0;
  topology_msg *msg = NULL;
  PetscMPIInt *to = NULL;
  const PetscInt n_entries = t->n_bonds + t->n_angles;
  for (PetscInt e = 0; e < n_entries; e++) {
    const PetscBool is_bond = e < t->n_bonds ? PETSC_TRUE : PETSC_FALSE;
    const PetscInt k = is_bond ? e : e - t->n_bonds;
    const int n_ends = is_bond ? 2 : 3;
    PetscMPIInt sent[3];
    int n_sent = 0;
    for (int q = 0; q < n_ends; q++) {
      const PetscInt64 g = is_bond ? t->bond_gid[k][q] : t->angle_gid[k][q];
      const gid_row key = {g, 0},
                    *hit = bsearch(&key, out, (size_t)n_leave, sizeof(gid_row), cmp_gid_row);
      if (!hit)
        continue;
      PetscBool again = PETSC_FALSE;
      for (int u = 0; u < n_sent; u++)
        if (sent[u] == (PetscMPIInt)hit->row)
          again = PETSC_TRUE;
      if (again)
        continue;
      sent[n_sent++] = (PetscMPIInt)hit->row;
      if (n_send == cap) {
        cap = PetscMax(64, 2 * cap);
        PetscCall(PetscRealloc(sizeof(topology_msg) * (size_t)cap, &msg));
        PetscCall(PetscRealloc(sizeof(PetscMPIInt) * (size_t)cap, &to));
      }
      to[n_send] = (PetscMPIInt)hit->row;
      msg[n_send++] =
          is_bond ? (topology_msg){t->bond_id[k],
                                   {t->bond_gid[k][0], t->bond_gid[k][1], -1},
                                   t->bond_type[k],
                                   t->bond_r0[k]}
                  : (topology_msg){-1 - t->angle_id[k], /* negative: an angle */
                                   {t->angle_gid[k][0], t->angle_gid[k][1], t->angle_gid[k][2]},
                                   t->angle_type[k],
                                   0.0};
    }
  }
  PetscMPIInt *cnt_out, *cnt_in, *d_out, *d_in;
  PetscCall(PetscCalloc4(size, &cnt_out, size, &cnt_in, size + 1, &d_out, size + 1, &d_in));
  for (PetscInt k = 0; k < n_send; k++)
    cnt_out[to[k]] += (PetscMPIInt)sizeof(topology_msg);
  PetscCallMPI(MPI_Alltoall(cnt_out, 1, MPI_INT, cnt_in, 1, MPI_INT, comm));
  size_t total_in = 0;
  for (PetscMPIInt r = 0; r < size; r++) {
    PetscCheck(d_out[r] + (size_t)cnt_out[r] < INT_MAX && total_in + (size_t)cnt_in[r] < INT_MAX,
               PETSC_COMM_SELF, PETSC_ERR_SUP, "topology_migrate: more than 2 GB of entries");
    d_out[r + 1] = d_out[r] + cnt_out[r];
    d_in[r] = (PetscMPIInt)total_in;
    total_in += (size_t)cnt_in[r];
  }
  topology_msg *send, *recv;
  PetscInt *fill;
  PetscCall(
      PetscMalloc3(n_send + 1, &send, total_in / sizeof(topology_msg) + 1, &recv, size, &fill));
  for (PetscMPIInt r = 0; r < size; r++)
    fill[r] = d_out[r] / (PetscInt)sizeof(topology_msg);
  for (PetscInt k = 0; k < n_send; k++)
    send[fill[to[k]]++] = msg[k];
  PetscCallMPI(MPI_Alltoallv(send, cnt_out, d_out, MPI_BYTE, recv, cnt_in, d_in, MPI_BYTE, comm));
  const PetscInt n_in = (PetscInt)(total_in / sizeof(topology_msg));
  for (PetscInt k = 0; k < n_in; k++) {
    const topology_msg *m = &recv[k];
    if (m->id >= 0)
      PetscCall(topology_store_bond(t, m->id, m->gid[0], m->gid[1], (PetscInt)m->type, m->r0));
    else
      PetscCall(topology_store_angle(t, -1 - m->id, m->gid, (PetscInt)m->type));
  }
  if (n_in)
    PetscCall(topology_sort_store(t));
  PetscCall(PetscFree3(send, recv, fill));
  PetscCall(PetscFree4(cnt_out, cnt_in, d_out, d_in));
  PetscCall(PetscFree(msg));
  PetscCall(PetscFree(to));
  PetscCall(PetscFree(out));
  PetscFunctionReturn(0);
}
