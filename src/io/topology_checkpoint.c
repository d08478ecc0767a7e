/* The bond/angle store in a checkpoint (group /topology, layout in checkpoint.h).
 *
 * Writing: each entry once, by the rank owning its first end (the store holds an entry on
 * every rank owning one of its ends), in rank order then id order. Reading: every rank
 * reads the whole group (the structure is small beside the particles), checks it, and
 * keeps the entries with an end it owns now, in id order; when the rank count differs
 * from the writer's, migration then carries them to their particles' owners. */
#include <stdlib.h>
#include "dmhs/sim.h"
#include "h5check.h"
#include "h5io.h"
#include "checkpoint_rows.h"
#include "topology_checkpoint.h"

static const field_desc bond_gid_f = {"bond_gid", 2, FIELD_INT64, 0, 0, "1"},
                        bond_type_f = {"bond_type", 1, FIELD_INT64, 0, 0, "1"},
                        bond_r0_f = {"bond_r0", 1, FIELD_REAL, 0, 0, "m"},
                        bond_id_f = {"bond_id", 1, FIELD_INT64, 0, 0, "1"},
                        angle_gid_f = {"angle_gid", 3, FIELD_INT64, 0, 0, "1"},
                        angle_type_f = {"angle_type", 1, FIELD_INT64, 0, 0, "1"},
                        angle_id_f = {"angle_id", 1, FIELD_INT64, 0, 0, "1"};

PetscErrorCode topology_checkpoint_write(sim *s, const char *path, hid_t fid) {
  const topology *t = s->topo;
  PetscInt64 *og, *g2, *ty, *id, *g3, *aty, *aid, offset, n_bonds, n_angles;
  PetscInt *orow, nb = 0, na = 0;
  double *r0;
  hid_t grp;
  PetscFunctionBeginUser;
  PetscCall(topology_owned_lookup(&s->ps, &og, &orow));
  PetscCall(PetscMalloc4(2 * t->n_bonds + 1, &g2, t->n_bonds + 1, &ty, t->n_bonds + 1, &r0,
                         t->n_bonds + 1, &id));
  PetscCall(PetscMalloc3(3 * t->n_angles + 1, &g3, t->n_angles + 1, &aty, t->n_angles + 1, &aid));
  for (PetscInt b = 0; b < t->n_bonds; b++) {
    if (topology_lookup_row(og, orow, s->ps.n_owned, t->bond_gid[b][0]) < 0)
      continue;
    g2[2 * nb] = t->bond_gid[b][0];
    g2[2 * nb + 1] = t->bond_gid[b][1];
    ty[nb] = t->bond_type[b];
    r0[nb] = t->bond_r0[b];
    id[nb++] = t->bond_id[b];
  }
  for (PetscInt a = 0; a < t->n_angles; a++) {
    if (topology_lookup_row(og, orow, s->ps.n_owned, t->angle_gid[a][0]) < 0)
      continue;
    for (int k = 0; k < 3; k++)
      g3[3 * na + k] = t->angle_gid[a][k];
    aty[na] = t->angle_type[a];
    aid[na++] = t->angle_id[a];
  }
  PetscCall(h5io_group_create(path, fid, "topology", &grp));
  PetscCall(h5io_offsets(s->comm, nb, &offset, &n_bonds));
  PetscCheck(n_bonds == t->n_bonds_global, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "checkpoint: %" PetscInt64_FMT " bonds found over the ranks, %" PetscInt64_FMT
             " expected (an entry lost its owner)",
             n_bonds, t->n_bonds_global);
  if (n_bonds) {
    PetscCall(checkpoint_write_rows(s->comm, path, grp, &bond_gid_f, g2, nb, offset, n_bonds));
    PetscCall(checkpoint_write_rows(s->comm, path, grp, &bond_type_f, ty, nb, offset, n_bonds));
    PetscCall(checkpoint_write_rows(s->comm, path, grp, &bond_r0_f, r0, nb, offset, n_bonds));
    PetscCall(checkpoint_write_rows(s->comm, path, grp, &bond_id_f, id, nb, offset, n_bonds));
  }
  PetscCall(h5io_offsets(s->comm, na, &offset, &n_angles));
  PetscCheck(n_angles == t->n_angles_global, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "checkpoint: %" PetscInt64_FMT " angles found over the ranks, %" PetscInt64_FMT
             " expected (an entry lost its owner)",
             n_angles, t->n_angles_global);
  if (n_angles) {
    PetscCall(checkpoint_write_rows(s->comm, path, grp, &angle_gid_f, g3, na, offset, n_angles));
    PetscCall(checkpoint_write_rows(s->comm, path, grp, &angle_type_f, aty, na, offset, n_angles));
    PetscCall(checkpoint_write_rows(s->comm, path, grp, &angle_id_f, aid, na, offset, n_angles));
  }
  const PetscInt64 counts[4] = {n_bonds, n_angles, t->next_bond_id, t->next_angle_id};
  PetscCall(h5io_put_int64s(path, grp, "n_bonds", &counts[0], 1));
  PetscCall(h5io_put_int64s(path, grp, "n_angles", &counts[1], 1));
  PetscCall(h5io_put_int64s(path, grp, "next_bond_id", &counts[2], 1));
  PetscCall(h5io_put_int64s(path, grp, "next_angle_id", &counts[3], 1));
  PetscCallHDF5(path, H5Gclose(grp));
  PetscCall(PetscFree3(g3, aty, aid));
  PetscCall(PetscFree4(g2, ty, r0, id));
  PetscCall(PetscFree2(og, orow));
  PetscFunctionReturn(0);
}

typedef struct {
  PetscInt64 id;
  PetscInt at;
} id_at;

static int cmp_id_at(const void *pa, const void *pb) {
  const id_at *a = pa, *b = pb;
  return (a->id > b->id) - (a->id < b->id);
}

/* Positions of the n ids in increasing id order (the file holds them in rank order). */
static PetscErrorCode topology_id_order(const char *path, const char *what, const PetscInt64 *id,
                                        PetscInt n, PetscInt **order) {
  id_at *key;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n + 1, &key));
  PetscCall(PetscMalloc1(n + 1, order));
  for (PetscInt k = 0; k < n; k++)
    key[k] = (id_at){id[k], k};
  qsort(key, (size_t)n, sizeof(id_at), cmp_id_at);
  for (PetscInt k = 0; k < n; k++) {
    PetscCheck(k == 0 || key[k].id != key[k - 1].id, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
               "checkpoint %s is corrupt: /topology/%s holds id %" PetscInt64_FMT " twice", path,
               what, key[k].id);
    (*order)[k] = key[k].at;
  }
  PetscCall(PetscFree(key));
  PetscFunctionReturn(0);
}

PetscErrorCode topology_checkpoint_read(sim *s, const char *path, hid_t fid) {
  topology *t = s->topo;
  PetscInt64 n_bonds, n_angles, next_bond, next_angle, *og, *g2, *ty, *id, *g3, *aty, *aid;
  PetscInt *orow, *order;
  double *r0;
  hid_t grp;
  PetscFunctionBeginUser;
  PetscCall(checkpoint_open_group(path, fid, "topology", "bonds and angles", &grp));
  PetscCall(h5io_get_int64s(path, grp, "n_bonds", &n_bonds, 1));
  PetscCall(h5io_get_int64s(path, grp, "n_angles", &n_angles, 1));
  PetscCall(h5io_get_int64s(path, grp, "next_bond_id", &next_bond, 1));
  PetscCall(h5io_get_int64s(path, grp, "next_angle_id", &next_angle, 1));
  PetscCheck(n_bonds >= 0 && n_angles >= 0 && next_bond >= n_bonds && next_angle >= n_angles &&
                 n_bonds < PETSC_MAX_INT && n_angles < PETSC_MAX_INT,
             PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "checkpoint %s is corrupt: /topology counts %" PetscInt64_FMT
             " bonds and %" PetscInt64_FMT " angles with next ids %" PetscInt64_FMT
             " and %" PetscInt64_FMT,
             path, n_bonds, n_angles, next_bond, next_angle);
  const PetscInt nb = (PetscInt)n_bonds, na = (PetscInt)n_angles;
  PetscCall(PetscMalloc4(2 * nb + 2, &g2, nb + 1, &ty, nb + 1, &r0, nb + 1, &id));
  PetscCall(PetscMalloc3(3 * na + 3, &g3, na + 1, &aty, na + 1, &aid));
  if (nb) {
    PetscCall(checkpoint_read_rows(s->comm, path, grp, "topology", &bond_gid_f, g2, nb, 0, nb,
                                   PETSC_FALSE));
    PetscCall(checkpoint_read_rows(s->comm, path, grp, "topology", &bond_type_f, ty, nb, 0, nb,
                                   PETSC_FALSE));
    PetscCall(checkpoint_read_rows(s->comm, path, grp, "topology", &bond_r0_f, r0, nb, 0, nb,
                                   PETSC_FALSE));
    PetscCall(checkpoint_read_rows(s->comm, path, grp, "topology", &bond_id_f, id, nb, 0, nb,
                                   PETSC_FALSE));
  }
  if (na) {
    PetscCall(checkpoint_read_rows(s->comm, path, grp, "topology", &angle_gid_f, g3, na, 0, na,
                                   PETSC_FALSE));
    PetscCall(checkpoint_read_rows(s->comm, path, grp, "topology", &angle_type_f, aty, na, 0, na,
                                   PETSC_FALSE));
    PetscCall(checkpoint_read_rows(s->comm, path, grp, "topology", &angle_id_f, aid, na, 0, na,
                                   PETSC_FALSE));
  }
  PetscCallHDF5(path, H5Gclose(grp));

  /* validated whole before the store changes */
  for (PetscInt b = 0; b < nb; b++) {
    PetscErrorCode ierr;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = topology_check_bond(g2[2 * b], g2[2 * b + 1], (PetscInt)ty[b], r0[b]);
    PetscCall(PetscPopErrorHandler());
    PetscCheck(!ierr && id[b] >= 0 && id[b] < next_bond, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
               "checkpoint %s is corrupt: /topology bond row %" PetscInt_FMT
               " (gids %" PetscInt64_FMT "-%" PetscInt64_FMT ", type %" PetscInt64_FMT
               ", id %" PetscInt64_FMT ") is invalid",
               path, b, g2[2 * b], g2[2 * b + 1], ty[b], id[b]);
  }
  for (PetscInt a = 0; a < na; a++) {
    PetscErrorCode ierr;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = topology_check_angle(&g3[3 * a], (PetscInt)aty[a]);
    PetscCall(PetscPopErrorHandler());
    PetscCheck(!ierr && aid[a] >= 0 && aid[a] < next_angle, PETSC_COMM_SELF,
               PETSC_ERR_FILE_UNEXPECTED,
               "checkpoint %s is corrupt: /topology angle row %" PetscInt_FMT
               " (id %" PetscInt64_FMT ") is invalid",
               path, a, aid[a]);
  }

  /* the file's structure replaces the one the scene built */
  topology_clear(t);
  t->next_bond_id = next_bond;
  t->next_angle_id = next_angle;
  t->n_bonds_global = n_bonds;
  t->n_angles_global = n_angles;
  PetscCall(topology_owned_lookup(&s->ps, &og, &orow));
  PetscCall(topology_id_order(path, "bond_id", id, nb, &order));
  for (PetscInt k = 0; k < nb; k++) {
    const PetscInt b = order[k];
    t->n_bonds_of_type[ty[b]]++;
    if (topology_lookup_row(og, orow, s->ps.n_owned, g2[2 * b]) >= 0 ||
        topology_lookup_row(og, orow, s->ps.n_owned, g2[2 * b + 1]) >= 0)
      PetscCall(topology_store_bond(t, id[b], g2[2 * b], g2[2 * b + 1], (PetscInt)ty[b], r0[b]));
  }
  PetscCall(PetscFree(order));
  PetscCall(topology_id_order(path, "angle_id", aid, na, &order));
  for (PetscInt k = 0; k < na; k++) {
    const PetscInt a = order[k];
    PetscBool mine = PETSC_FALSE;
    for (int e = 0; e < 3; e++)
      if (topology_lookup_row(og, orow, s->ps.n_owned, g3[3 * a + e]) >= 0)
        mine = PETSC_TRUE;
    if (mine)
      PetscCall(topology_store_angle(t, aid[a], &g3[3 * a], (PetscInt)aty[a]));
  }
  PetscCall(PetscFree(order));
  PetscCall(PetscFree2(og, orow));
  PetscCall(PetscFree3(g3, aty, aid));
  PetscCall(PetscFree4(g2, ty, r0, id));
  PetscFunctionReturn(0);
}
