/* Particle snapshots: every FIELD_OUTPUT field of the field table, owned rows
 * of every rank in rank order, one parallel HDF5 file per output time
 * (layout in snapshot.h). Nothing here names a field: adding a row with
 * FIELD_OUTPUT to fields.c adds it to the snapshots and the XDMF index. */
#include "dmhs/sim.h"
#include "dmhs/io.h"
#include "dmhs/snapshot.h"
#include "dmhs/events.h"
#include "dmhs/gather.h"
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
 * joins, for the XDMF Polyline grid. The store is distributed: each bond is written
 * by the rank owning its first end (rank order, then id order); the rows of second
 * ends owned elsewhere are asked of every rank at once (bonds across rank borders
 * are few: a gather of their gids and a max reduction of the answers). */
static PetscErrorCode snapshot_write_bonds(sim *s, const char *path, hid_t fid, PetscInt64 offset,
                                           PetscInt64 *n_bonds) {
  topology *t = s->topo;
  static const field_desc rows_field = {"rows", 2, FIELD_INT64, 0, 0, "1"};
  PetscInt64 *og, *pairs, *ask, *all_ask, *answer, my_offset;
  PetscInt *orow, nb = 0, n_ask = 0;
  size_t n_gathered, my_first;
  hid_t grp;
  PetscFunctionBeginUser;
  *n_bonds = t ? t->n_bonds_global : 0;
  if (!*n_bonds)
    PetscFunctionReturn(0);
  PetscCall(topology_owned_lookup(&s->ps, &og, &orow));
  PetscCall(PetscMalloc2(2 * t->n_bonds + 2, &pairs, t->n_bonds + 1, &ask));
  for (PetscInt b = 0; b < t->n_bonds; b++) {
    const PetscInt r0 = topology_lookup_row(og, orow, s->ps.n_owned, t->bond_gid[b][0]);
    if (r0 < 0)
      continue; /* written by its first end's owner */
    const PetscInt r1 = topology_lookup_row(og, orow, s->ps.n_owned, t->bond_gid[b][1]);
    pairs[2 * nb] = offset + r0;
    pairs[2 * nb + 1] = r1 >= 0 ? offset + r1 : -1 - n_ask; /* -1 - k: the k-th question */
    if (r1 < 0)
      ask[n_ask++] = t->bond_gid[b][1];
    nb++;
  }
  /* every rank's questions, answered by the owners */
  PetscCall(gather_all(s->comm, "snapshot bond ends", ask, (size_t)n_ask, sizeof(PetscInt64),
                       &all_ask, &n_gathered, &my_first));
  const PetscInt n_all = (PetscInt)n_gathered;
  PetscCall(PetscMalloc1(n_all + 1, &answer));
  for (PetscInt k = 0; k < n_all; k++) {
    const PetscInt r = topology_lookup_row(og, orow, s->ps.n_owned, all_ask[k]);
    answer[k] = r >= 0 ? offset + r : -1;
  }
  PetscCallMPI(
      MPI_Allreduce(MPI_IN_PLACE, answer, (PetscMPIInt)n_all, MPIU_INT64, MPI_MAX, s->comm));
  for (PetscInt b = 0; b < nb; b++) {
    if (pairs[2 * b + 1] >= 0)
      continue;
    const PetscInt k = (PetscInt)(-1 - pairs[2 * b + 1]);
    pairs[2 * b + 1] = answer[(PetscInt)my_first + k];
    PetscCheck(pairs[2 * b + 1] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "snapshot: a bond names particle gid %" PetscInt64_FMT " that no rank owns", ask[k]);
  }
  PetscInt64 n_check;
  PetscCall(h5io_offsets(s->comm, nb, &my_offset, &n_check));
  PetscCheck(n_check == *n_bonds, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "snapshot: %" PetscInt64_FMT " bonds written over the ranks, %" PetscInt64_FMT
             " in the structure",
             n_check, *n_bonds);
  PetscCall(h5io_group_create(path, fid, "bonds", &grp));
  PetscCall(h5io_write_rows(s->comm, path, grp, &rows_field, pairs, nb, my_offset, n_check, 2));
  PetscCallHDF5(path, H5Gclose(grp));
  PetscCall(PetscFree(all_ask));
  PetscCall(PetscFree(answer));
  PetscCall(PetscFree2(pairs, ask));
  PetscCall(PetscFree2(og, orow));
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
    PetscCall(h5io_put_string(tmp, fid, "scene", s->scene_name));
    PetscCall(h5io_put_string(tmp, fid, "options", s->io->options ? s->io->options : ""));
    /* the box, for post-processing across periodic boundaries, and the rest spacing */
    PetscInt64 periodic[DMHS_DIM];
    for (int k = 0; k < DMHS_DIM; k++)
      periodic[k] = s->dom.periodic[k] ? 1 : 0;
    PetscCall(h5io_put_reals(tmp, fid, "box_lo", s->dom.lo, DMHS_DIM));
    PetscCall(h5io_put_reals(tmp, fid, "box_hi", s->dom.hi, DMHS_DIM));
    PetscCall(h5io_put_int64s(tmp, fid, "periodic", periodic, DMHS_DIM));
    PetscCall(h5io_put_reals(tmp, fid, "dx", &s->dx, 1));
    for (int k = 0; k < s->io->n_snapshot_attributes; k++) {
      const io_attribute *a = &s->io->snapshot_attributes[k];
      if (a->text[0])
        PetscCall(h5io_put_string(tmp, fid, a->name, a->text));
      else
        PetscCall(h5io_put_reals(tmp, fid, a->name, &a->value, 1));
    }
  }
  PetscCall(h5io_group_create(tmp, fid, "particles", &grp));
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
