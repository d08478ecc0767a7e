/* Migration: keeping owned particles where they belong, after each drift.
 *  1. wrap positions into the periodic box; stop the run, naming the particle,
 *     when one leaves the box along a closed direction;
 *  2. (several ranks) every -partition_interval steps, repartition if the load
 *     is imbalanced (partition.c);
 *  3. (several ranks) send each owned particle whose coarse cell belongs to
 *     another rank to that rank with every FIELD_MIGRATE field (field table),
 *     compact the owned range, append the arrivals (in source-rank order);
 *     and the bond/angle store entries of the leaving ones (topology_migrate);
 *  4. with -debug_migration, check that the global particle count and the set
 *     of global ids are unchanged (count, sum of gids and sum of a 64-bit hash
 *     of each gid, modulo 2^64). */
#include <limits.h>
#include <stdint.h>
#include "dmhs/sim.h"
#include "dmhs/migrate.h"
#include "dmhs/fields.h"
#include "dmhs/events.h"

#define MIGRATE_MAX_FIELDS 32

PetscErrorCode migrate_set_from_options(migrate_check *m, sim *s) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Migration", NULL);
  PetscCall(
      options_read_bool("-debug_migration",
                        "Check every step that the global particle count and id set are unchanged",
                        NULL, m->enabled, &m->enabled, NULL));
  PetscCall(options_run_control("-debug_migration"));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

/* splitmix64 finaliser: a well-mixed 64-bit image of a gid */
static inline uint64_t migrate_hash(uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

static PetscErrorCode migrate_fingerprint(sim *s, uint64_t out[3]) {
  const particles *ps = &s->ps;
  uint64_t local[3] = {(uint64_t)ps->n_owned, 0, 0};
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    local[1] += (uint64_t)ps->gid[i];
    local[2] += migrate_hash((uint64_t)ps->gid[i]);
  }
  PetscCallMPI(MPI_Allreduce(local, out, 3, MPI_UINT64_T, MPI_SUM, s->comm));
  PetscFunctionReturn(0);
}

PetscErrorCode migrate_check_ids(migrate_check *m, sim *s) {
  uint64_t now[3];
  PetscFunctionBeginUser;
  if (!m->enabled)
    PetscFunctionReturn(0);
  PetscCall(migrate_fingerprint(s, now));
  if (!m->have_reference) {
    for (int k = 0; k < 3; k++)
      m->reference[k] = now[k];
    m->have_reference = PETSC_TRUE;
    PetscFunctionReturn(0);
  }
  PetscCheck(now[0] == m->reference[0], s->comm, PETSC_ERR_PLIB,
             "-debug_migration: step %" PetscInt_FMT ": %" PetscInt64_FMT
             " particles over the ranks, expected %" PetscInt64_FMT " (particles were %s)",
             s->step, (PetscInt64)now[0], (PetscInt64)m->reference[0],
             now[0] < m->reference[0] ? "lost" : "duplicated");
  PetscCheck(now[1] == m->reference[1] && now[2] == m->reference[2], s->comm, PETSC_ERR_PLIB,
             "-debug_migration: step %" PetscInt_FMT
             ": the particle count is right but the set of global ids changed "
             "(a particle was duplicated and another lost)",
             s->step);
  PetscFunctionReturn(0);
}

PetscErrorCode migrate_report(migrate_check *m, sim *s) {
  PetscInt64 moved;
  PetscFunctionBeginUser;
  if (!m->enabled)
    PetscFunctionReturn(0);
  PetscCallMPI(MPI_Allreduce(&m->moved, &moved, 1, MPIU_INT64, MPI_SUM, s->comm));
  PetscCall(PetscPrintf(s->comm,
                        "-debug_migration: %" PetscInt64_FMT
                        " particles, count and ids unchanged at every step; %" PetscInt64_FMT
                        " moves between ranks, %" PetscInt_FMT " repartition(s)\n",
                        (PetscInt64)m->reference[0], moved, s->part.n_repartitions));
  PetscFunctionReturn(0);
}

/* Several ranks: move owned particles to the owners of their cells. */
static PetscErrorCode migrate_exchange(sim *s) {
  particles *ps = &s->ps;
  const partition *part = &s->part;
  const PetscMPIInt size = s->size, me = s->rank;
  const field_desc *f[MIGRATE_MAX_FIELDS];
  const int nf = particles_select_fields(FIELD_MIGRATE, f, MIGRATE_MAX_FIELDS);
  const size_t bytes = particles_packed_bytes(f, nf);
  PetscMPIInt *dest, *cnt_out, *cnt_in, *b_out, *d_out, *b_in, *d_in;
  PetscInt *leaving, *fill;
  char *send_buf, *recv_buf;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(ps->n_owned, &dest));
  PetscCall(PetscCalloc4(size, &cnt_out, size, &cnt_in, size, &b_out, size, &d_out));
  PetscCall(PetscMalloc3(size, &b_in, size, &d_in, size + 1, &fill));
  PetscInt n_leave = 0;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    dest[i] = part->owner[partition_cell_of(part, ps->x[i])];
    if (dest[i] != me) {
      cnt_out[dest[i]]++;
      n_leave++;
    }
  }
  s->mig.moved += n_leave;
  PetscCallMPI(MPI_Alltoall(cnt_out, 1, MPI_INT, cnt_in, 1, MPI_INT, s->comm));
  /* leaving rows grouped by destination, in owned order */
  PetscCall(PetscMalloc1(n_leave, &leaving));
  fill[0] = 0;
  for (PetscMPIInt r = 0; r < size; r++)
    fill[r + 1] = fill[r] + cnt_out[r];
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (dest[i] != me)
      leaving[fill[dest[i]]++] = i;
  PetscInt n_arrive = 0;
  for (PetscMPIInt r = 0; r < size; r++)
    n_arrive += cnt_in[r];
  PetscCheck((size_t)PetscMax(n_leave, n_arrive) * bytes < INT_MAX, PETSC_COMM_SELF, PETSC_ERR_SUP,
             "migrate: more than 2 GB of particles moving at once");
  size_t off_out = 0, off_in = 0;
  for (PetscMPIInt r = 0; r < size; r++) {
    b_out[r] = (PetscMPIInt)(cnt_out[r] * bytes);
    d_out[r] = (PetscMPIInt)off_out;
    off_out += (size_t)b_out[r];
    b_in[r] = (PetscMPIInt)(cnt_in[r] * bytes);
    d_in[r] = (PetscMPIInt)off_in;
    off_in += (size_t)b_in[r];
  }
  PetscCall(PetscMalloc2(off_out + 1, &send_buf, off_in + 1, &recv_buf));
  particles_pack(ps, f, nf, leaving, n_leave, NULL, send_buf);
  /* bonds and angles go with their leaving ends (the receivers merge them by id) */
  if (s->topo)
    PetscCall(topology_migrate(s->topo, ps, s->comm, leaving, dest, n_leave));
  PetscCallMPI(
      MPI_Alltoallv(send_buf, b_out, d_out, MPI_BYTE, recv_buf, b_in, d_in, MPI_BYTE, s->comm));
  /* compact the staying particles (every field: they stay whole), then append arrivals */
  PetscInt kept = 0;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (dest[i] != me)
      continue;
    if (kept != i)
      particles_copy_row(ps, kept, i, ~0u);
    kept++;
  }
  PetscCall(particles_reserve(ps, kept + n_arrive));
  particles_unpack(ps, f, nf, kept, n_arrive, recv_buf);
  ps->n_owned = kept + n_arrive;
  PetscCall(PetscFree2(send_buf, recv_buf));
  PetscCall(PetscFree(leaving));
  PetscCall(PetscFree(dest));
  PetscCall(PetscFree4(cnt_out, cnt_in, b_out, d_out));
  PetscCall(PetscFree3(b_in, d_in, fill));
  PetscFunctionReturn(0);
}

PetscErrorCode migrate_particles(sim *s) {
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.migrate, 0, 0, 0, 0));
  ps->n_ghost = 0;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    domain_wrap(&s->dom, ps->x[i]);
    PetscCheck(
        domain_contains(&s->dom, ps->x[i]), PETSC_COMM_SELF, PETSC_ERR_FP,
        "particle gid %" PetscInt64_FMT " escaped the domain at step %" PetscInt_FMT
        ", t = %g s: x = (%g, %g) outside [%g, %g] x [%g, %g]; the run is unstable or a wall leaks "
        "(try a smaller -dt)",
        ps->gid[i], s->step, s->t, ps->x[i][0], ps->x[i][1], s->dom.lo[0], s->dom.hi[0],
        s->dom.lo[1], s->dom.hi[1]);
  }
  if (s->size > 1) {
    PetscCall(partition_check(&s->part, s));
    PetscCall(migrate_exchange(s));
  }
  PetscCall(migrate_check_ids(&s->mig, s));
  PetscCall(PetscLogEventEnd(events.migrate, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
