/* Particle snapshots: every FIELD_OUTPUT field of the field table, owned rows
 * of every rank in rank order, one parallel HDF5 file per output time
 * (layout in snapshot.h). Nothing here names a field: adding a row with
 * FIELD_OUTPUT to fields.c adds it to the snapshots and the XDMF index. */
#include "dmhs/sim.h"
#include "dmhs/snapshot.h"
#include "dmhs/events.h"
#include "h5check.h"
#include "h5io.h"
#include "guard.h"

int snapshot_file_width(const field_desc *f) {
  return f->width == DMHS_DIM && DMHS_DIM == 2 ? 3 : f->width;
}

PetscErrorCode snapshot_name(PetscInt index, char *name, size_t len) {
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(name, len, "snap_%06" PetscInt_FMT ".h5", index));
  PetscFunctionReturn(0);
}

/* /bonds/rows: each bond as the two rows of this snapshot's particle datasets it
 * joins, for the XDMF Polyline grid. The topology is replicated by gid, so
 * every rank marks the snapshot row of its owned bonded particles and a max
 * reduction gives every rank the row of every bonded gid; rank 0 writes. */
static PetscErrorCode snapshot_write_bonds(sim *s, const char *path, hid_t fid, PetscInt64 offset,
                                           PetscInt64 *n_bonds) {
  topology *t = s->topo;
  PetscInt64 *row, *pairs = NULL;
  static const field_desc rows_field = {"rows", 2, FIELD_INT64, 0, 0, "1"};
  hid_t grp;
  PetscFunctionBeginUser;
  *n_bonds = t ? t->n_bonds : 0;
  if (!*n_bonds)
    PetscFunctionReturn(0);
  PetscInt slot;
  PetscCall(topology_gid_slot(t, t->bond_gid[0][0], &slot)); /* builds the gid tables if needed */
  PetscCall(PetscMalloc1(t->n_gids + 1, &row));
  for (PetscInt k = 0; k < t->n_gids; k++)
    row[k] = -1;
  for (PetscInt i = 0; i < s->ps.n_owned; i++) {
    PetscCall(topology_gid_slot(t, s->ps.gid[i], &slot));
    if (slot >= 0)
      row[slot] = offset + i;
  }
  PetscCallMPI(
      MPI_Allreduce(MPI_IN_PLACE, row, (PetscMPIInt)t->n_gids, MPIU_INT64, MPI_MAX, s->comm));
  if (s->rank == 0) {
    PetscCall(PetscMalloc1(2 * t->n_bonds, &pairs));
    for (PetscInt b = 0; b < t->n_bonds; b++)
      for (int e = 0; e < 2; e++) {
        PetscCall(topology_gid_slot(t, t->bond_gid[b][e], &slot));
        PetscCheck(slot >= 0 && row[slot] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                   "snapshot: bond %" PetscInt_FMT " names particle gid %" PetscInt64_FMT
                   " that no rank owns",
                   b, t->bond_gid[b][e]);
        pairs[2 * b + e] = row[slot];
      }
  }
  PetscCallHDF5(path, grp = H5Gcreate2(fid, "bonds", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  PetscCall(h5io_write_rows(s->comm, path, grp, &rows_field, pairs, s->rank == 0 ? t->n_bonds : 0,
                            0, t->n_bonds, 2));
  PetscCallHDF5(path, H5Gclose(grp));
  PetscCall(PetscFree(pairs));
  PetscCall(PetscFree(row));
  PetscFunctionReturn(0);
}

PetscErrorCode snapshot_write(sim *s, PetscInt index, PetscInt64 *n_global, PetscInt64 *n_bonds) {
  char name[64], path[PETSC_MAX_PATH_LEN], tmp[PETSC_MAX_PATH_LEN + 8];
  size_t nf;
  const field_desc *t = fields_table(&nf);
  PetscInt64 offset, n;
  hid_t fid, grp;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.output, 0, 0, 0, 0));
  PetscCall(snapshot_name(index, name, sizeof(name)));
  PetscCall(io_output_path(s, name, path, sizeof(path)));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
  PetscCall(h5io_offsets(s->comm, s->ps.n_owned, &offset, &n));

  PetscCall(io_guard_finite(s, FIELD_OUTPUT, path));
  PetscCall(h5io_create(s->comm, tmp, &fid));
  {
    const double time = s->t, dt = s->dt;
    const PetscInt64 step = s->step, dim = DMHS_DIM, count = n;
    PetscCall(h5io_put_reals(tmp, fid, "time", &time, 1));
    PetscCall(h5io_put_reals(tmp, fid, "dt", &dt, 1));
    PetscCall(h5io_put_int64s(tmp, fid, "step", &step, 1));
    PetscCall(h5io_put_int64s(tmp, fid, "dim", &dim, 1));
    PetscCall(h5io_put_int64s(tmp, fid, "n_particles", &count, 1));
    PetscCall(h5io_put_string(tmp, fid, "dmhs_version", DMHS_VERSION));
    PetscCall(h5io_put_string(tmp, fid, "scene", s->scn->name));
    PetscCall(h5io_put_string(tmp, fid, "options", s->io.options ? s->io.options : ""));
  }
  PetscCallHDF5(tmp, grp = H5Gcreate2(fid, "particles", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  for (size_t k = 0; k < nf; k++) {
    if (!(t[k].flags & FIELD_OUTPUT))
      continue;
    PetscCall(h5io_write_rows(s->comm, tmp, grp, &t[k], *fields_member(&s->ps, &t[k]),
                              s->ps.n_owned, offset, n, snapshot_file_width(&t[k])));
  }
  PetscCallHDF5(tmp, H5Gclose(grp));
  PetscCall(snapshot_write_bonds(s, tmp, fid, offset, n_bonds));
  PetscCall(h5io_close(tmp, &fid));
  PetscCall(h5io_commit(s->comm, tmp, path));
  *n_global = n;
  PetscCall(PetscLogEventEnd(events.output, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
