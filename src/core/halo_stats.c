/* Halo sizes at the last build (include/dmhs/halo.h), for run.json: the
 * numbers a scaling model past one node is fitted to (doc/performance.md,
 * "Past one node"). Read from the exchange pattern halo_build left, so they
 * are those of the last neighbour build: owned rows change only there
 * (migration), and ghost refreshes between builds repeat its exchange. */
#include "dmhs/halo.h"
#include "dmhs/fields.h"

enum { HS_OWNED, HS_GHOST, HS_REMOTE, HS_SENT, HS_PARTNERS, HS_BYTES, HS_N };

PetscErrorCode halo_stats_gather(const halo *h, const particles *ps, const char *const *refresh,
                                 int n, halo_stats *st) {
  const field_desc *f[32];
  PetscInt64 mine[HS_N], lo[HS_N], hi[HS_N], sum[HS_N];
  PetscFunctionBeginUser;
  PetscCheck(n >= 0 && n <= 32, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
             "halo_stats_gather: %d refreshed fields", n);
  for (int k = 0; k < n; k++) {
    f[k] = fields_find(refresh[k]);
    PetscCheck(f[k], PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "halo_stats_gather: no field '%s'",
               refresh[k]);
  }
  const int nf = n;
  PetscCall(PetscMemzero(st, sizeof(*st)));
  st->ranks = h->size;
  st->ghost_bytes = (PetscInt64)particles_packed_bytes(f, nf);
  mine[HS_OWNED] = ps->n_owned;
  mine[HS_GHOST] = ps->n_ghost;
  mine[HS_REMOTE] = mine[HS_SENT] = mine[HS_PARTNERS] = 0;
  if (h->size > 1) {
    /* copies to itself are periodic images: no message, but the same Alltoallv */
    for (PetscMPIInt r = 0; r < h->size; r++) {
      const PetscInt out = h->send_off[r + 1] - h->send_off[r];
      const PetscInt in = h->recv_off[r + 1] - h->recv_off[r];
      if (r == h->rank)
        continue;
      mine[HS_SENT] += out;
      mine[HS_REMOTE] += in;
      mine[HS_PARTNERS] += out > 0 || in > 0;
    }
  }
  mine[HS_BYTES] = mine[HS_REMOTE] * st->ghost_bytes;
  PetscCallMPI(MPI_Allreduce(mine, lo, HS_N, MPIU_INT64, MPI_MIN, h->comm));
  PetscCallMPI(MPI_Allreduce(mine, hi, HS_N, MPIU_INT64, MPI_MAX, h->comm));
  PetscCallMPI(MPI_Allreduce(mine, sum, HS_N, MPIU_INT64, MPI_SUM, h->comm));
  halo_count *out[HS_N] = {&st->owned, &st->ghost,    &st->remote,
                           &st->sent,  &st->partners, &st->forward_bytes};
  for (int k = 0; k < HS_N; k++)
    *out[k] = (halo_count){.min = lo[k], .max = hi[k], .total = sum[k]};
  PetscFunctionReturn(0);
}
