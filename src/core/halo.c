/* Ghost particles. On one rank these are the periodic images of owned
 * particles within `width` of a periodic boundary; the MPI halo extends the
 * same list with copies from neighbouring ranks. Ghost rows follow owned rows. */
#include <string.h>
#include "dmhs/halo.h"
#include "dmhs/fields.h"
#include "dmhs/events.h"

PetscErrorCode halo_create(halo *h, double width) {
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(h, sizeof(*h)));
  h->width = width;
  PetscFunctionReturn(0);
}

PetscErrorCode halo_destroy(halo *h) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(h->source, h->shift));
  PetscCall(PetscMemzero(h, sizeof(*h)));
  PetscFunctionReturn(0);
}

static PetscErrorCode halo_push(halo *h, PetscInt src, double sx, double sy) {
  PetscFunctionBeginUser;
  if (h->n == h->n_alloc) {
    PetscInt grown = PetscMax(256, 2 * h->n_alloc);
    PetscInt *source;
    double(*shift)[DMHS_DIM];
    PetscCall(PetscMalloc2(grown, &source, grown, &shift));
    if (h->n) {
      PetscCall(PetscArraycpy(source, h->source, h->n));
      PetscCall(PetscArraycpy(shift, h->shift, h->n));
    }
    PetscCall(PetscFree2(h->source, h->shift));
    h->source = source;
    h->shift = shift;
    h->n_alloc = grown;
  }
  h->source[h->n] = src;
  h->shift[h->n][0] = sx;
  h->shift[h->n][1] = sy;
  h->n++;
  PetscFunctionReturn(0);
}

PetscErrorCode halo_build(halo *h, const domain *d, particles *ps) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.halo_build, 0, 0, 0, 0));
  h->n = 0;
  ps->n_ghost = 0;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    /* candidate shifts per axis: none, and +L / -L when near the low / high side */
    double shifts[DMHS_DIM][3];
    int n_shift[DMHS_DIM];
    for (int k = 0; k < DMHS_DIM; k++) {
      n_shift[k] = 1;
      shifts[k][0] = 0.0;
      if (!d->periodic[k]) continue;
      const double L = domain_length(d, k);
      if (ps->x[i][k] - d->lo[k] < h->width) shifts[k][n_shift[k]++] = L;
      if (d->hi[k] - ps->x[i][k] <= h->width) shifts[k][n_shift[k]++] = -L;
    }
    for (int a = 0; a < n_shift[0]; a++)
      for (int b = 0; b < n_shift[1]; b++)
        if (a || b) PetscCall(halo_push(h, i, shifts[0][a], shifts[1][b]));
  }
  PetscCall(particles_reserve(ps, ps->n_owned + h->n));
  for (PetscInt g = 0; g < h->n; g++) {
    const PetscInt dst = ps->n_owned + g;
    particles_copy_row(ps, dst, h->source[g], FIELD_GHOST);
    ps->x[dst][0] += h->shift[g][0];
    ps->x[dst][1] += h->shift[g][1];
  }
  ps->n_ghost = h->n;
  PetscCall(PetscLogEventEnd(events.halo_build, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode halo_forward(const halo *h, particles *ps, const char *const field_names[],
                            int n_fields) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.halo_forward, 0, 0, 0, 0));
  for (int f = 0; f < n_fields; f++) {
    const field_desc *fd = fields_find(field_names[f]);
    PetscCheck(fd, PETSC_COMM_SELF, PETSC_ERR_PLIB, "halo_forward: no field named '%s'",
               field_names[f]);
    PetscCheck(fd->flags & FIELD_GHOST, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "halo_forward: field '%s' is not a ghost field", field_names[f]);
    const size_t row = fields_row_bytes(fd);
    char *base = *fields_member(ps, fd);
    for (PetscInt g = 0; g < h->n; g++)
      memcpy(base + row * (size_t)(ps->n_owned + g), base + row * (size_t)h->source[g], row);
    if (!strcmp(fd->name, "x"))
      for (PetscInt g = 0; g < h->n; g++) {
        ps->x[ps->n_owned + g][0] += h->shift[g][0];
        ps->x[ps->n_owned + g][1] += h->shift[g][1];
      }
  }
  PetscCall(PetscLogEventEnd(events.halo_forward, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
