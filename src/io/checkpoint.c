/* Checkpoints: write and read the whole state (layout in checkpoint.h).
 *
 * What "the whole state" is, for a bitwise restart of kick-drift-kick:
 *   - every FIELD_CHECKPOINT field of owned particles, in their current row
 *     order (the pair list and so every sum is built in that order): gid, type,
 *     tag, x, v, a, x0, mass, rho, drho, p. a and drho feed the first kick
 *     after the restart; v_est is derived from v and a in that kick, v_visc and
 *     ghosts are rebuilt before the next force sweep.
 *   - run control: step, t, dt (t = step * dt is recomputed identically),
 *     next output / progress times and the snapshot counter (nothing a force
 *     evaluation reads from the previous one: the body force is evaluated
 *     before the walls read it, in the same evaluation).
 *   - the bond/angle store (topology_checkpoint.c), each entry written by the
 *     rank owning its first end;
 *   - modules' and diagnostics' private state through their checkpoint hooks.
 * Reading validates before it changes anything it cannot restore: magic,
 * format version, scene, particle count, and each dataset's shape and type. */
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/io.h"
#include "dmhs/checkpoint.h"
#include "dmhs/events.h"
#include "h5check.h"
#include "h5io.h"
#include "guard.h"
#include "checkpoint_rows.h"
#include "topology_checkpoint.h"

struct checkpoint_io {
  MPI_Comm comm;
  PetscMPIInt rank;
  const char *path;
  hid_t group;
  const char *owner; /* "module <name>" or "diagnostic <name>" */
  char where[80];    /* the group's path in the file, for messages */
};

static int checkpoint_cmp_int64(const void *a, const void *b) {
  const PetscInt64 x = *(const PetscInt64 *)a, y = *(const PetscInt64 *)b;
  return (x > y) - (x < y);
}

/* Every particle once: each gid goes to rank gid % size, which sorts what it
 * receives and looks for neighbours that are equal. Collective. */
static PetscErrorCode checkpoint_check_gids(sim *s, const char *path, PetscInt64 n_file) {
  const PetscInt n = s->ps.n_owned;
  PetscMPIInt *send_n, *recv_n, *send_at, *recv_at;
  PetscInt64 *out, *in, bad_local[2] = {-1, -1}, bad[2];
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc4(s->size, &send_n, s->size, &recv_n, s->size + 1, &send_at, s->size + 1,
                         &recv_at));
  for (PetscInt i = 0; i < n; i++) {
    const PetscInt64 g = s->ps.gid[i];
    if (g < 0)
      bad_local[1] = PetscMax(bad_local[1], -g); /* negative: reported below */
    else
      send_n[g % s->size]++;
  }
  PetscCallMPI(MPI_Alltoall(send_n, 1, MPI_INT, recv_n, 1, MPI_INT, s->comm));
  for (PetscMPIInt r = 0; r < s->size; r++) {
    send_at[r + 1] = send_at[r] + send_n[r];
    recv_at[r + 1] = recv_at[r] + recv_n[r];
  }
  PetscCall(PetscMalloc2(send_at[s->size] + 1, &out, recv_at[s->size] + 1, &in));
  for (PetscMPIInt r = 0; r < s->size; r++)
    send_n[r] = 0;
  for (PetscInt i = 0; i < n; i++) {
    const PetscInt64 g = s->ps.gid[i];
    if (g < 0)
      continue;
    const PetscMPIInt r = (PetscMPIInt)(g % s->size);
    out[send_at[r] + send_n[r]++] = g;
  }
  PetscCallMPI(
      MPI_Alltoallv(out, send_n, send_at, MPIU_INT64, in, recv_n, recv_at, MPIU_INT64, s->comm));
  qsort(in, (size_t)recv_at[s->size], sizeof(*in), checkpoint_cmp_int64);
  for (PetscMPIInt k = 1; k < recv_at[s->size] && bad_local[0] < 0; k++)
    if (in[k] == in[k - 1])
      bad_local[0] = in[k];
  PetscCallMPI(MPI_Allreduce(bad_local, bad, 2, MPIU_INT64, MPI_MAX, s->comm));
  PetscCall(PetscFree2(out, in));
  PetscCall(PetscFree4(send_n, recv_n, send_at, recv_at));
  PetscCheck(
      bad[1] < 0, s->comm, PETSC_ERR_FILE_UNEXPECTED,
      "checkpoint %s is corrupt: dataset /particles/gid holds the negative gid -%" PetscInt64_FMT,
      path, bad[1]);
  PetscCheck(bad[0] < 0, s->comm, PETSC_ERR_FILE_UNEXPECTED,
             "checkpoint %s is corrupt: dataset /particles/gid holds gid %" PetscInt64_FMT
             " more than once (%" PetscInt64_FMT " particles)",
             path, bad[0], n_file);
  PetscFunctionReturn(0);
}

static field_desc checkpoint_array_desc(const char *name, field_kind kind) {
  field_desc d = {name, 1, kind, 0, 0, "1"};
  return d;
}

PetscErrorCode checkpoint_put_reals(checkpoint_io *io, const char *name, const double *v,
                                    PetscInt n) {
  const field_desc d = checkpoint_array_desc(name, FIELD_REAL);
  PetscFunctionBeginUser;
  /* replicated state: rank 0's copy is written */
  PetscCall(
      checkpoint_write_rows(io->comm, io->path, io->group, &d, v, io->rank == 0 ? n : 0, 0, n));
  PetscFunctionReturn(0);
}

PetscErrorCode checkpoint_put_ints(checkpoint_io *io, const char *name, const PetscInt64 *v,
                                   PetscInt n) {
  const field_desc d = checkpoint_array_desc(name, FIELD_INT64);
  PetscFunctionBeginUser;
  PetscCall(
      checkpoint_write_rows(io->comm, io->path, io->group, &d, v, io->rank == 0 ? n : 0, 0, n));
  PetscFunctionReturn(0);
}

PetscErrorCode checkpoint_get_length(checkpoint_io *io, const char *name, PetscInt *n) {
  htri_t exists;
  hid_t dset, space;
  hssize_t count;
  PetscFunctionBeginUser;
  PetscCallHDF5(io->path, exists = H5Lexists(io->group, name, H5P_DEFAULT));
  *n = -1;
  if (exists <= 0)
    PetscFunctionReturn(0);
  PetscCallHDF5(io->path, dset = H5Dopen2(io->group, name, H5P_DEFAULT));
  PetscCallHDF5(io->path, space = H5Dget_space(dset));
  PetscCallHDF5(io->path, count = H5Sget_simple_extent_npoints(space));
  PetscCallHDF5(io->path, H5Sclose(space));
  PetscCallHDF5(io->path, H5Dclose(dset));
  *n = (PetscInt)count;
  PetscFunctionReturn(0);
}

static PetscErrorCode checkpoint_get(checkpoint_io *io, const char *name, field_kind kind, void *v,
                                     PetscInt n) {
  const field_desc d = checkpoint_array_desc(name, kind);
  PetscInt stored;
  PetscFunctionBeginUser;
  PetscCall(checkpoint_get_length(io, name, &stored));
  PetscCheck(stored >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "checkpoint %s lacks '%s' of %s (truncated, or written by another version)", io->path,
             name, io->owner);
  PetscCheck(stored == n, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "checkpoint %s: '%s' of %s has %" PetscInt_FMT " values, expected %" PetscInt_FMT,
             io->path, name, io->owner, stored, n);
  PetscCall(
      checkpoint_read_rows(io->comm, io->path, io->group, io->where, &d, v, n, 0, n, PETSC_FALSE));
  PetscFunctionReturn(0);
}

PetscErrorCode checkpoint_get_reals(checkpoint_io *io, const char *name, double *v, PetscInt n) {
  return checkpoint_get(io, name, FIELD_REAL, v, n);
}

PetscErrorCode checkpoint_get_ints(checkpoint_io *io, const char *name, PetscInt64 *v, PetscInt n) {
  return checkpoint_get(io, name, FIELD_INT64, v, n);
}

PetscErrorCode checkpoint_write(sim *s, const char *path) {
  char tmp[PETSC_MAX_PATH_LEN + 8];
  size_t nf;
  const field_desc *t = fields_table(&nf);
  const field_desc counts_desc = checkpoint_array_desc("rank_counts", FIELD_INT64);
  PetscInt64 offset, n, my_count = s->ps.n_owned;
  hid_t fid, grp;
  checkpoint_io io = {s->comm, s->rank, tmp, -1, NULL, ""};
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.checkpoint, 0, 0, 0, 0));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
  PetscCall(h5io_offsets(s->comm, s->ps.n_owned, &offset, &n));
  PetscCall(io_guard_finite(s, FIELD_CHECKPOINT, path));
  PetscCall(h5io_create(s->comm, tmp, &fid));
  {
    const PetscInt64 version = CHECKPOINT_FORMAT_VERSION, ranks = s->size, step = s->step,
                     snapshot_index = s->io->snapshot_index;
    PetscCall(h5io_put_string(tmp, fid, "magic", CHECKPOINT_MAGIC));
    PetscCall(h5io_put_int64s(tmp, fid, "format_version", &version, 1));
    PetscCall(h5io_put_string(tmp, fid, "dmhs_version", DMHS_VERSION));
    PetscCall(h5io_put_string(tmp, fid, "scene", s->scene_name));
    PetscCall(h5io_put_string(tmp, fid, "options", s->io->options ? s->io->options : ""));
    char *physics;
    PetscCall(options_physics(&physics));
    PetscCall(h5io_put_string(tmp, fid, "physics_options", physics));
    PetscCall(PetscFree(physics));
    PetscCall(h5io_put_int64s(tmp, fid, "n_ranks", &ranks, 1));
    PetscCall(h5io_put_int64s(tmp, fid, "n_particles", &n, 1));
    PetscCall(h5io_put_int64s(tmp, fid, "step", &step, 1));
    PetscCall(h5io_put_int64s(tmp, fid, "snapshot_index", &snapshot_index, 1));
    PetscCall(h5io_put_reals(tmp, fid, "t", &s->t, 1));
    PetscCall(h5io_put_reals(tmp, fid, "dt", &s->dt, 1));
    const PetscInt64 step_anchor = s->step_anchor;
    PetscCall(h5io_put_reals(tmp, fid, "dt_anchor_t", &s->t_anchor, 1));
    PetscCall(h5io_put_int64s(tmp, fid, "dt_anchor_step", &step_anchor, 1));
    const PetscInt64 n_sub = s->substeps.n;
    PetscCall(h5io_put_int64s(tmp, fid, "solid_substeps", &n_sub, 1));
    for (int k = 0; k < s->io->n_kept; k++) /* the driver's next output and progress times */
      PetscCall(h5io_put_reals(tmp, fid, s->io->kept[k].name, s->io->kept[k].value, 1));
    /* which diagnostics sampled at this step: a restart keeps only their rows at its time
     * (a run that ends here samples the others once more after this checkpoint) */
    if (s->n_diagnostics) {
      PetscInt64 sampled[SIM_MAX_DIAGNOSTICS];
      for (int k = 0; k < s->n_diagnostics; k++)
        sampled[k] = s->diagnostics[k]->sampled_step == s->step;
      PetscCall(h5io_put_int64s(tmp, fid, "diagnostics_sampled", sampled, s->n_diagnostics));
    }
  }
  PetscCall(h5io_group_create(tmp, fid, "particles", &grp));
  for (size_t k = 0; k < nf; k++) {
    if (!(t[k].flags & FIELD_CHECKPOINT))
      continue;
    PetscCall(checkpoint_write_rows(s->comm, tmp, grp, &t[k], *fields_member(&s->ps, &t[k]),
                                    s->ps.n_owned, offset, n));
  }
  PetscCall(checkpoint_write_rows(s->comm, tmp, grp, &counts_desc, &my_count, 1, s->rank, s->size));
  PetscCallHDF5(tmp, H5Gclose(grp));
  if (s->topo) /* bonds and angles, made at build or at run time */
    PetscCall(topology_checkpoint_write(s, tmp, fid));

  /* private state of modules and diagnostics */
  PetscCall(h5io_group_create(tmp, fid, "modules", &grp));
  for (int m = 0; m < s->n_modules; m++) {
    module *mod = s->modules[m];
    char owner[80];
    if (!mod->checkpoint_write)
      continue;
    PetscCall(PetscSNPrintf(owner, sizeof(owner), "module %s", mod->name));
    io.owner = owner;
    PetscCall(h5io_group_create(tmp, grp, mod->name, &io.group));
    PetscCall(mod->checkpoint_write(mod, s, &io));
    PetscCallHDF5(tmp, H5Gclose(io.group));
  }
  PetscCallHDF5(tmp, H5Gclose(grp));
  /* each diagnostic's state in a group of its own name */
  PetscCall(h5io_group_create(tmp, fid, "diagnostics", &grp));
  for (int k = 0; k < s->n_diagnostics; k++) {
    diagnostic *d = s->diagnostics[k];
    char owner[96];
    if (!d->checkpoint_write)
      continue;
    PetscCall(PetscSNPrintf(owner, sizeof(owner), "diagnostic %s", d->name));
    io.owner = owner;
    PetscCall(h5io_group_create(tmp, grp, d->name, &io.group));
    PetscCall(d->checkpoint_write(d, s, &io));
    PetscCallHDF5(tmp, H5Gclose(io.group));
  }
  PetscCallHDF5(tmp, H5Gclose(grp));
  PetscCall(h5io_close(tmp, &fid));
  PetscCall(h5io_commit(s->comm, tmp, path));
  PetscCall(PetscLogEventEnd(events.checkpoint, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* The physics options of the run that wrote the checkpoint against this run's:
 * a difference is an error naming the options, unless -restart_allow_change
 * (then it is printed and kept for run.json). Options the writer's dmhs did not
 * have, left at their defaults now, continue with a note (kept for run.json too). */
static PetscErrorCode checkpoint_compare_options(sim *s, const char *path, hid_t fid) {
  const size_t len = 65536;
  char *stored, report[2048], added[2048];
  int n_changed, n_added;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(len, &stored));
  PetscCall(h5io_get_string(path, fid, "physics_options", stored, len));
  PetscCall(options_compare_physics(stored, report, sizeof(report), &n_changed, added,
                                    sizeof(added), &n_added));
  PetscCall(PetscFree(stored));
  if (n_added) {
    PetscCall(PetscPrintf(s->comm,
                          "note: -restart %s: %d option(s) unknown to the dmhs that wrote it, "
                          "continued at this run's default(s): %s\n",
                          path, n_added, added));
    PetscCall(PetscStrallocpy(added, &s->io->restart_new_options));
  }
  if (!n_changed)
    PetscFunctionReturn(0);
  PetscCheck(
      s->io->restart_allow_change, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP,
      "-restart %s: %d physics option(s) differ from the run that wrote it: %s; restart with the "
      "checkpoint's options (its 'options' attribute), or add -restart_allow_change to continue "
      "with "
      "the new ones",
      path, n_changed, report);
  PetscCall(PetscPrintf(
      s->comm,
      "WARNING: -restart_allow_change: continuing %s with %d changed physics option(s): %s\n", path,
      n_changed, report));
  PetscCall(PetscStrallocpy(report, &s->io->restart_changes));
  PetscFunctionReturn(0);
}

/* Which diagnostics sampled at the checkpoint's step (diagnostic.h: restart_sampled); a
 * checkpoint without the record: all of them, as before it was kept. */
static PetscErrorCode checkpoint_read_sampled(sim *s, const char *path, hid_t fid) {
  PetscInt64 sampled[SIM_MAX_DIAGNOSTICS];
  PetscBool has;
  PetscFunctionBeginUser;
  PetscCall(h5io_has_attr(path, fid, "diagnostics_sampled", &has));
  if (has && s->n_diagnostics)
    PetscCall(h5io_get_int64s(path, fid, "diagnostics_sampled", sampled, s->n_diagnostics));
  for (int k = 0; k < s->n_diagnostics; k++) {
    diagnostic *d = s->diagnostics[k];
    d->restart_sampled = !has || sampled[k] ? PETSC_TRUE : PETSC_FALSE;
    d->sampled_step = d->restart_sampled ? s->step : -1;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode checkpoint_read(sim *s, const char *path) {
  char text[256];
  size_t nf;
  const field_desc *t = fields_table(&nf);
  const field_desc counts_desc = checkpoint_array_desc("rank_counts", FIELD_INT64);
  PetscInt64 version, ranks, n_file, n_built, offset, n_check, step, snapshot_index;
  PetscInt n_local;
  PetscBool has;
  hid_t fid, grp;
  checkpoint_io io = {s->comm, s->rank, path, -1, NULL, ""};
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.checkpoint, 0, 0, 0, 0));
  PetscCall(h5io_open(s->comm, path, &fid));

  /* is it ours, and of this format? */
  PetscCall(h5io_has_attr(path, fid, "magic", &has));
  PetscCheck(has, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "-restart %s: not a dmhs checkpoint (an HDF5 file without the 'magic' attribute)",
             path);
  PetscCall(h5io_get_string(path, fid, "magic", text, sizeof(text)));
  PetscCheck(!strcmp(text, CHECKPOINT_MAGIC), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "-restart %s: not a dmhs checkpoint (magic '%s', expected '%s')", path, text,
             CHECKPOINT_MAGIC);
  PetscCall(h5io_get_int64s(path, fid, "format_version", &version, 1));
  PetscCall(h5io_get_string(path, fid, "dmhs_version", text, sizeof(text)));
  PetscCheck(version == CHECKPOINT_FORMAT_VERSION, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "-restart %s: checkpoint format version %" PetscInt64_FMT
             " (written by dmhs %s); dmhs %s reads version %d only: continue it with the dmhs "
             "that wrote it, or start the run afresh",
             path, version, text, DMHS_VERSION, CHECKPOINT_FORMAT_VERSION);
  PetscCall(h5io_get_string(path, fid, "scene", text, sizeof(text)));
  PetscCheck(!strcmp(text, s->scene_name), PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP,
             "-restart %s: written by scene '%s' but this run builds scene '%s'", path, text,
             s->scene_name);
  PetscCall(checkpoint_compare_options(s, path, fid));

  /* the scene was built with the current options: it must hold as many particles */
  PetscCall(h5io_get_int64s(path, fid, "n_particles", &n_file, 1));
  PetscCall(h5io_get_int64s(path, fid, "n_ranks", &ranks, 1));
  PetscCall(h5io_offsets(s->comm, s->ps.n_owned, &offset, &n_built));
  PetscCheck(n_file == n_built, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP,
             "-restart %s holds %" PetscInt64_FMT " particles but scene '%s' built %" PetscInt64_FMT
             " with the current options: restart with the options of the run that wrote it (its "
             "'options' attribute)",
             path, n_file, s->scene_name, n_built);

  /* rows per rank: as written on the same rank count (bitwise continuation), else
   * an even split that migration then hands to the owners */
  PetscCall(checkpoint_open_group(path, fid, "particles", "particle fields", &grp));
  if (ranks == s->size) {
    PetscInt64 mine;
    PetscCall(checkpoint_read_rows(s->comm, path, grp, "particles", &counts_desc, &mine, 1, s->rank,
                                   s->size, PETSC_TRUE));
    PetscCheck(mine >= 0 && mine <= n_file, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
               "checkpoint %s: rank_counts[%d] = %" PetscInt64_FMT " is out of range", path,
               (int)s->rank, mine);
    n_local = (PetscInt)mine;
  } else {
    n_local = (PetscInt)(n_file / s->size + (s->rank < n_file % s->size ? 1 : 0));
  }
  PetscCall(h5io_offsets(s->comm, n_local, &offset, &n_check));
  PetscCheck(n_check == n_file, s->comm, PETSC_ERR_FILE_UNEXPECTED,
             "checkpoint %s: rank_counts add up to %" PetscInt64_FMT
             ", not n_particles = %" PetscInt64_FMT,
             path, n_check, n_file);

  /* replace the owned particles */
  s->ps.n_ghost = 0;
  s->ps.n_owned = 0;
  PetscCall(particles_reserve(&s->ps, n_local));
  for (size_t k = 0; k < nf; k++) {
    if (!(t[k].flags & FIELD_CHECKPOINT))
      continue;
    PetscCall(h5io_read_rows(s->comm, path, grp, &t[k], *fields_member(&s->ps, &t[k]), n_local,
                             offset, n_file));
  }
  s->ps.n_owned = n_local;
  /* a duplicated particle first (the precise complaint), then every dataset's checksum */
  PetscCall(checkpoint_check_gids(s, path, n_file));
  for (size_t k = 0; k < nf; k++) {
    if (!(t[k].flags & FIELD_CHECKPOINT))
      continue;
    PetscCall(checkpoint_verify(s->comm, path, grp, "particles", &t[k],
                                *fields_member(&s->ps, &t[k]), n_local, offset, PETSC_TRUE));
  }
  PetscCallHDF5(path, H5Gclose(grp));

  /* run control */
  PetscCall(h5io_get_int64s(path, fid, "step", &step, 1));
  PetscCall(h5io_get_int64s(path, fid, "snapshot_index", &snapshot_index, 1));
  PetscCall(h5io_get_reals(path, fid, "dt", &s->dt, 1));
  PetscCall(h5io_get_reals(path, fid, "t", &s->t, 1));
  PetscInt64 step_anchor;
  PetscCall(h5io_get_reals(path, fid, "dt_anchor_t", &s->t_anchor, 1));
  PetscCall(h5io_get_int64s(path, fid, "dt_anchor_step", &step_anchor, 1));
  s->step_anchor = (PetscInt)step_anchor;
  PetscInt64 n_sub;
  PetscCall(h5io_get_int64s(path, fid, "solid_substeps", &n_sub, 1));
  PetscCheck(n_sub >= 1 && n_sub <= SUBSTEPS_MAX, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "checkpoint %s: invalid solid_substeps %" PetscInt64_FMT, path, n_sub);
  /* the sub-steps of the step that wrote it, for the record of changes (dt.csv) */
  s->substeps.n = (PetscInt)n_sub;
  for (int k = 0; k < s->io->n_kept; k++)
    PetscCall(h5io_get_reals(path, fid, s->io->kept[k].name, s->io->kept[k].value, 1));
  PetscCheck(s->step_anchor >= 0 && s->step_anchor <= step, PETSC_COMM_SELF,
             PETSC_ERR_FILE_UNEXPECTED,
             "checkpoint %s: invalid dt_anchor_step %" PetscInt_FMT " (step %" PetscInt64_FMT ")",
             path, s->step_anchor, step);
  PetscCheck(step >= 0 && s->dt > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "checkpoint %s: invalid step %" PetscInt64_FMT " or dt %g", path, step, s->dt);
  s->step = (PetscInt)step;
  s->io->snapshot_index = (PetscInt)snapshot_index;
  PetscCall(checkpoint_read_sampled(s, path, fid));

  /* the structure (before the modules' state, which may refer to it) */
  if (s->topo)
    PetscCall(topology_checkpoint_read(s, path, fid));

  /* private state */
  for (int m = 0; m < s->n_modules; m++) {
    module *mod = s->modules[m];
    char owner[80];
    hid_t modules;
    if (!mod->checkpoint_read)
      continue;
    PetscCall(PetscSNPrintf(owner, sizeof(owner), "module %s", mod->name));
    io.owner = owner;
    PetscCall(PetscSNPrintf(io.where, sizeof(io.where), "modules/%s", mod->name));
    PetscCall(checkpoint_open_group(path, fid, "modules", "module state", &modules));
    PetscCall(checkpoint_open_group(path, modules, mod->name, owner, &io.group));
    PetscCall(mod->checkpoint_read(mod, s, &io));
    PetscCallHDF5(path, H5Gclose(io.group));
    PetscCallHDF5(path, H5Gclose(modules));
  }
  for (int k = 0; k < s->n_diagnostics; k++) {
    diagnostic *d = s->diagnostics[k];
    char owner[96];
    hid_t diagnostics;
    if (!d->checkpoint_read)
      continue;
    PetscCall(PetscSNPrintf(owner, sizeof(owner), "diagnostic %s", d->name));
    io.owner = owner;
    PetscCall(PetscSNPrintf(io.where, sizeof(io.where), "diagnostics/%s", d->name));
    PetscCall(checkpoint_open_group(path, fid, "diagnostics", "diagnostics' state", &diagnostics));
    PetscCall(checkpoint_open_group(path, diagnostics, d->name, owner, &io.group));
    PetscCall(d->checkpoint_read(d, s, &io));
    PetscCallHDF5(path, H5Gclose(io.group));
    PetscCallHDF5(path, H5Gclose(diagnostics));
  }
  PetscCall(h5io_close(path, &fid));
  PetscCall(PetscLogEventEnd(events.checkpoint, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
