/* Ghost particles. Ghost rows follow owned rows.
 *
 * One rank: the periodic images of owned particles within `width` of a
 * periodic boundary, copied row to row (no MPI, no packing).
 *
 * Several ranks: every owned particle is sent to each rank owning a coarse
 * cell (partition.c, edge >= width) within `width` of it, itself included when
 * the cell is reached across a periodic boundary; the periodic shift is added
 * to the copy's x. Since owned particles lie in their owner's cells, any
 * particle of rank r within `width` of particle i makes i a ghost on r: the
 * ghosts cover every pair within the reach. Copies travel as packed rows of the
 * FIELD_GHOST fields (field table) in one MPI_Alltoallv; ghosts from rank r
 * land in rank order, each rank's in its send order, and halo_forward repeats
 * exactly that exchange for the named fields.
 *
 * No reverse exchange: a pair across ranks is computed on both sides and each
 * keeps its own half (doc/parallel.md). */
#include <limits.h>
#include <string.h>
#include "dmhs/halo.h"
#include "dmhs/fields.h"
#include "dmhs/events.h"

#define HALO_MAX_FIELDS 32

PetscErrorCode halo_create(halo *h, double width, MPI_Comm comm) {
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(h, sizeof(*h)));
  h->width = width;
  h->comm = comm;
  PetscCallMPI(MPI_Comm_rank(comm, &h->rank));
  PetscCallMPI(MPI_Comm_size(comm, &h->size));
  PetscCall(PetscMalloc2(h->size + 1, &h->send_off, h->size + 1, &h->recv_off));
  PetscCall(PetscMalloc4(h->size, &h->send_cnt, h->size, &h->send_displ, h->size, &h->recv_cnt,
                         h->size, &h->recv_displ));
  PetscFunctionReturn(0);
}

PetscErrorCode halo_destroy(halo *h) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree3(h->source, h->shift, h->dest));
  PetscCall(PetscFree2(h->send_off, h->recv_off));
  PetscCall(PetscFree4(h->send_cnt, h->send_displ, h->recv_cnt, h->recv_displ));
  PetscCall(PetscFree(h->send_buf));
  PetscCall(PetscFree(h->recv_buf));
  PetscCall(PetscMemzero(h, sizeof(*h)));
  PetscFunctionReturn(0);
}

static PetscErrorCode halo_push(halo *h, PetscMPIInt dest, PetscInt src, double sx, double sy) {
  PetscFunctionBeginUser;
  if (h->n == h->n_alloc) {
    PetscInt grown = PetscMax(256, 2 * h->n_alloc);
    PetscInt *source;
    double(*shift)[DMHS_DIM];
    PetscMPIInt *d;
    PetscCall(PetscMalloc3(grown, &source, grown, &shift, grown, &d));
    if (h->n) {
      PetscCall(PetscArraycpy(source, h->source, h->n));
      PetscCall(PetscArraycpy(shift, h->shift, h->n));
      PetscCall(PetscArraycpy(d, h->dest, h->n));
    }
    PetscCall(PetscFree3(h->source, h->shift, h->dest));
    h->source = source;
    h->shift = shift;
    h->dest = d;
    h->n_alloc = grown;
  }
  h->source[h->n] = src;
  h->shift[h->n][0] = sx;
  h->shift[h->n][1] = sy;
  h->dest[h->n] = dest;
  h->n++;
  PetscFunctionReturn(0);
}

/* One rank: periodic images, copied row to row. */
static PetscErrorCode halo_build_serial(halo *h, const domain *d, particles *ps) {
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    /* candidate shifts per axis: none, and +L / -L when near the low / high side */
    double shifts[DMHS_DIM][3];
    int n_shift[DMHS_DIM];
    for (int k = 0; k < DMHS_DIM; k++) {
      n_shift[k] = 1;
      shifts[k][0] = 0.0;
      if (!d->periodic[k])
        continue;
      const double L = domain_length(d, k);
      if (ps->x[i][k] - d->lo[k] < h->width)
        shifts[k][n_shift[k]++] = L;
      if (d->hi[k] - ps->x[i][k] <= h->width)
        shifts[k][n_shift[k]++] = -L;
    }
    for (int a = 0; a < n_shift[0]; a++)
      for (int b = 0; b < n_shift[1]; b++)
        if (a || b)
          PetscCall(halo_push(h, 0, i, shifts[0][a], shifts[1][b]));
  }
  PetscCall(particles_reserve(ps, ps->n_owned + h->n));
  for (PetscInt g = 0; g < h->n; g++) {
    const PetscInt dst = ps->n_owned + g;
    particles_copy_row(ps, dst, h->source[g], FIELD_GHOST);
    ps->x[dst][0] += h->shift[g][0];
    ps->x[dst][1] += h->shift[g][1];
  }
  ps->n_ghost = h->n;
  PetscFunctionReturn(0);
}

/* Several ranks: the send list, grouped by destination (stable: owned order). */
static PetscErrorCode halo_send_list(halo *h, const domain *d, const partition *part,
                                     const particles *ps) {
  const double w2 = h->width * h->width;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    const double *x = ps->x[i];
    PetscInt c[DMHS_DIM];
    for (int k = 0; k < DMHS_DIM; k++) {
      c[k] = (PetscInt)floor((x[k] - part->lo[k]) * part->inv_edge[k]);
      c[k] = PetscMin(PetscMax(c[k], 0), part->nc[k] - 1);
    }
    if (!part->frontier[c[1] * part->nc[0] + c[0]])
      continue; /* deep inside this rank */
    /* distinct (rank, shift) destinations of this particle: at most 9 */
    PetscMPIInt seen_rank[9];
    double seen_shift[9][DMHS_DIM];
    int n_seen = 0;
    for (int dy = -1; dy <= 1; dy++)
      for (int dx = -1; dx <= 1; dx++) {
        const PetscInt u[DMHS_DIM] = {c[0] + dx, c[1] + dy};
        PetscInt wrapped[DMHS_DIM];
        double shift[DMHS_DIM], d2 = 0;
        PetscBool skip = PETSC_FALSE;
        for (int k = 0; k < DMHS_DIM; k++) {
          shift[k] = 0.0;
          wrapped[k] = u[k];
          if (u[k] < 0 || u[k] >= part->nc[k]) {
            if (!d->periodic[k]) {
              skip = PETSC_TRUE;
              break;
            }
            /* the cell lies across the boundary: its owner needs the image on its side */
            shift[k] = u[k] < 0 ? domain_length(d, k) : -domain_length(d, k);
            wrapped[k] = u[k] < 0 ? u[k] + part->nc[k] : u[k] - part->nc[k];
          }
          /* distance from x to the (unwrapped) cell along k */
          const double lo = part->lo[k] + (double)u[k] * part->edge[k], hi = lo + part->edge[k];
          const double gap = x[k] < lo ? lo - x[k] : x[k] > hi ? x[k] - hi : 0.0;
          d2 += gap * gap;
        }
        if (skip || d2 >= w2)
          continue;
        const PetscMPIInt owner = part->owner[wrapped[1] * part->nc[0] + wrapped[0]];
        if (owner == h->rank && shift[0] == 0.0 && shift[1] == 0.0)
          continue; /* the particle itself */
        PetscBool dup = PETSC_FALSE;
        for (int s = 0; s < n_seen && !dup; s++)
          dup =
              seen_rank[s] == owner && seen_shift[s][0] == shift[0] && seen_shift[s][1] == shift[1];
        if (dup)
          continue;
        seen_rank[n_seen] = owner;
        seen_shift[n_seen][0] = shift[0];
        seen_shift[n_seen][1] = shift[1];
        n_seen++;
        PetscCall(halo_push(h, owner, i, shift[0], shift[1]));
      }
  }
  /* counting sort by destination, keeping owned order within each */
  PetscCall(PetscArrayzero(h->send_off, h->size + 1));
  for (PetscInt e = 0; e < h->n; e++)
    h->send_off[h->dest[e] + 1]++;
  for (PetscMPIInt r = 0; r < h->size; r++)
    h->send_off[r + 1] += h->send_off[r];
  {
    PetscInt *fill, *source;
    double(*shift)[DMHS_DIM];
    PetscCall(PetscMalloc3(h->size, &fill, h->n, &source, h->n, &shift));
    PetscCall(PetscArraycpy(fill, h->send_off, h->size));
    for (PetscInt e = 0; e < h->n; e++) {
      const PetscInt at = fill[h->dest[e]]++;
      source[at] = h->source[e];
      shift[at][0] = h->shift[e][0];
      shift[at][1] = h->shift[e][1];
    }
    PetscCall(PetscArraycpy(h->source, source, h->n));
    PetscCall(PetscArraycpy(h->shift, shift, h->n));
    PetscCall(PetscFree3(fill, source, shift));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode halo_ensure(char **buf, size_t *len, size_t need) {
  PetscFunctionBeginUser;
  if (need > *len) {
    PetscCall(PetscFree(*buf));
    *len = need + need / 4 + 64;
    PetscCall(PetscMalloc1(*len, buf));
  }
  PetscFunctionReturn(0);
}

/* Packs the send list with fields f, exchanges, and unpacks into the ghost rows. */
static PetscErrorCode halo_exchange(halo *h, particles *ps, const field_desc *const *f, int nf) {
  const size_t bytes = particles_packed_bytes(f, nf);
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.halo_exchange, 0, 0, 0, 0));
  PetscCheck((size_t)h->n * bytes < INT_MAX && (size_t)h->n_recv * bytes < INT_MAX, PETSC_COMM_SELF,
             PETSC_ERR_SUP, "halo: more than 2 GB of ghost data on one rank; run on more ranks");
  PetscCall(halo_ensure(&h->send_buf, &h->send_buf_len, (size_t)h->n * bytes));
  PetscCall(halo_ensure(&h->recv_buf, &h->recv_buf_len, (size_t)h->n_recv * bytes));
  for (PetscMPIInt r = 0; r < h->size; r++) {
    h->send_cnt[r] = (PetscMPIInt)((h->send_off[r + 1] - h->send_off[r]) * bytes);
    h->send_displ[r] = (PetscMPIInt)(h->send_off[r] * bytes);
    h->recv_cnt[r] = (PetscMPIInt)((h->recv_off[r + 1] - h->recv_off[r]) * bytes);
    h->recv_displ[r] = (PetscMPIInt)(h->recv_off[r] * bytes);
  }
  particles_pack(ps, f, nf, h->source, h->n, (const double(*)[DMHS_DIM])h->shift, h->send_buf);
  PetscCallMPI(MPI_Alltoallv(h->send_buf, h->send_cnt, h->send_displ, MPI_BYTE, h->recv_buf,
                             h->recv_cnt, h->recv_displ, MPI_BYTE, h->comm));
  particles_unpack(ps, f, nf, ps->n_owned, h->n_recv, h->recv_buf);
  PetscCall(PetscLogEventEnd(events.halo_exchange, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode halo_build(halo *h, const domain *d, const partition *part, particles *ps) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.halo_build, 0, 0, 0, 0));
  h->n = 0;
  ps->n_ghost = 0;
  if (h->size == 1) {
    PetscCall(halo_build_serial(h, d, ps));
  } else {
    const field_desc *f[HALO_MAX_FIELDS];
    const int nf = particles_select_fields(FIELD_GHOST, f, HALO_MAX_FIELDS);
    PetscMPIInt *counts_out, *counts_in;
    PetscCall(halo_send_list(h, d, part, ps));
    PetscCall(PetscMalloc2(h->size, &counts_out, h->size, &counts_in));
    for (PetscMPIInt r = 0; r < h->size; r++) {
      const PetscInt c = h->send_off[r + 1] - h->send_off[r];
      PetscCheck(c < INT_MAX, PETSC_COMM_SELF, PETSC_ERR_SUP, "halo: too many ghosts for one rank");
      counts_out[r] = (PetscMPIInt)c;
    }
    PetscCallMPI(MPI_Alltoall(counts_out, 1, MPI_INT, counts_in, 1, MPI_INT, h->comm));
    h->recv_off[0] = 0;
    for (PetscMPIInt r = 0; r < h->size; r++)
      h->recv_off[r + 1] = h->recv_off[r] + counts_in[r];
    PetscCall(PetscFree2(counts_out, counts_in));
    h->n_recv = h->recv_off[h->size];
    PetscCall(particles_reserve(ps, ps->n_owned + h->n_recv));
    PetscCall(halo_exchange(h, ps, f, nf));
    ps->n_ghost = h->n_recv;
  }
  PetscCall(PetscLogEventEnd(events.halo_build, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode halo_forward(halo *h, particles *ps, const char *const field_names[], int n_fields) {
  const field_desc *f[HALO_MAX_FIELDS];
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.halo_forward, 0, 0, 0, 0));
  PetscCheck(n_fields <= HALO_MAX_FIELDS, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "halo_forward: too many fields");
  for (int k = 0; k < n_fields; k++) {
    f[k] = fields_find(field_names[k]);
    PetscCheck(f[k], PETSC_COMM_SELF, PETSC_ERR_PLIB, "halo_forward: no field named '%s'",
               field_names[k]);
    PetscCheck(f[k]->flags & FIELD_GHOST, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "halo_forward: field '%s' is not a ghost field", field_names[k]);
  }
  if (h->size > 1) {
    PetscCall(halo_exchange(h, ps, f, n_fields));
  } else {
    for (int k = 0; k < n_fields; k++) {
      const field_desc *fd = f[k];
      const size_t row = fields_row_bytes(fd);
      char *base = *fields_member(ps, fd);
      for (PetscInt g = 0; g < h->n; g++)
        memcpy(base + row * (size_t)(ps->n_owned + g), base + row * (size_t)h->source[g], row);
      if (fd->offset == offsetof(particles, x))
        for (PetscInt g = 0; g < h->n; g++) {
          ps->x[ps->n_owned + g][0] += h->shift[g][0];
          ps->x[ps->n_owned + g][1] += h->shift[g][1];
        }
    }
  }
  PetscCall(PetscLogEventEnd(events.halo_forward, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
