/* The diagnostic "vein_crossings": no liquid may pass through a leaflet
 * (vein_metrics.h). Every -vein_crossing_interval steps and at output times,
 * fluid particles beside a leaflet (within 3 dx of its mid-line, between its
 * root and tip) record which side they are on in the optional field `side`
 * (+-1 upper, +-2 lower leaflet); a particle seen on the other side of the
 * same leaflet counts as a crossing (must stay 0). */
#include <math.h>
#include "dmhs/checkpoint.h"
#include "dmhs/diagnostics.h"
#include "vein_column_bins.h"

typedef struct {
  vein_leaflets leaves;
  PetscInt64 crossings_local; /* counted on this rank (rank 0 also holds a restart's count) */
  column_bins bins[2];
} vein_crossings;

/* Side of leaflet w a point p is on (+-1), 0 when not beside it: the nearest column
 * mid-point c (d: p relative to the leaflet's box centre), the local tangent from columns
 * c-1 .. c+1, within dx along it and 3 dx across. */
static int vein_side_of(const vein_leaflets *v, const column_bins *b, const domain *dom, int w,
                        const double p[2], const double d_box[2]) {
  const PetscInt nc = v->lay.leaflet[w].n_columns;
  const double dx = v->lay.dx;
  const PetscInt cb = column_bins_nearest(b, d_box, dx);
  if (cb < 0)
    return 0;
  double ma[2], mb[2], mc[2], d[2];
  vein_leaflets_column_mid(v, w, PetscMax(cb - 1, 0), ma);
  vein_leaflets_column_mid(v, w, PetscMin(cb + 1, nc - 1), mb);
  vein_leaflets_column_mid(v, w, cb, mc);
  double t[2] = {mb[0] - ma[0], mb[1] - ma[1]};
  const double tl = hypot(t[0], t[1]);
  t[0] /= tl;
  t[1] /= tl;
  d[0] = p[0] - mc[0];
  d[1] = p[1] - mc[1];
  domain_min_image(dom, d);
  const double along = d[0] * t[0] + d[1] * t[1], across = d[0] * t[1] - d[1] * t[0];
  if (fabs(across) >= 3 * dx)
    return 0;
  if ((cb == 0 && along < 0) || (cb == nc - 1 && along > 0) || fabs(along) > dx)
    return 0;
  return across > 0 ? 1 : -1;
}

/* A particle's side is compared with the one recorded at the previous check
 * (none at step 0: the sides are only recorded). */
static PetscErrorCode vein_crossings_sample(diagnostic *self, sim *s) {
  vein_crossings *c = self->data;
  const vein_leaflets *v = &c->leaves;
  const PetscBool count = s->step > 0 ? PETSC_TRUE : PETSC_FALSE;
  particles *ps = &s->ps;
  double box[2][4]; /* per leaflet: centre x, y and half-widths, 4 dx beyond its particles */
  PetscFunctionBeginUser;
  PetscCall(vein_leaflets_gather(&c->leaves, s));
  for (int w = 0; w < 2; w++) {
    const double(*x)[2] = v->x + (w ? v->n_leaf[0] : 0);
    double lo[2] = {x[0][0], x[0][1]}, hi[2] = {x[0][0], x[0][1]};
    for (PetscInt k = 1; k < v->n_leaf[w]; k++)
      for (int d = 0; d < 2; d++) {
        lo[d] = PetscMin(lo[d], x[k][d]);
        hi[d] = PetscMax(hi[d], x[k][d]);
      }
    for (int d = 0; d < 2; d++) {
      box[w][d] = 0.5 * (lo[d] + hi[d]);
      box[w][2 + d] = 0.5 * (hi[d] - lo[d]) + 4 * v->lay.dx;
    }
    PetscCall(column_bins_build(&c->bins[w], v, &s->dom, w, box[w]));
  }
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID)
      continue;
    PetscInt now = 0;
    for (int w = 0; w < 2 && !now; w++) {
      /* only particles near the leaflet can be beside it: a cheap box test first */
      double d[2] = {ps->x[i][0] - box[w][0], ps->x[i][1] - box[w][1]};
      domain_min_image(&s->dom, d);
      if (fabs(d[0]) > box[w][2] || fabs(d[1]) > box[w][3])
        continue;
      const int sd = vein_side_of(v, &c->bins[w], &s->dom, w, ps->x[i], d);
      if (sd)
        now = (w + 1) * sd;
    }
    if (count && now && ps->side[i] == -now)
      c->crossings_local++;
    ps->side[i] = now;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode vein_crossings_total(const diagnostic *crossings, sim *s, PetscInt64 *total) {
  const vein_crossings *c = crossings->data;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&c->crossings_local, total, 1, MPIU_INT64, MPI_SUM, s->comm));
  PetscFunctionReturn(0);
}

/* The count so far over all ranks (the sides travel in the particle field `side`). */
static PetscErrorCode vein_crossings_checkpoint_write(diagnostic *self, sim *s, checkpoint_io *io) {
  PetscInt64 total;
  PetscFunctionBeginUser;
  PetscCall(vein_crossings_total(self, s, &total));
  PetscCall(checkpoint_put_ints(io, "crossings", &total, 1));
  PetscFunctionReturn(0);
}

static PetscErrorCode vein_crossings_checkpoint_read(diagnostic *self, sim *s, checkpoint_io *io) {
  vein_crossings *c = self->data;
  PetscInt64 total;
  PetscFunctionBeginUser;
  PetscCall(checkpoint_get_ints(io, "crossings", &total, 1));
  /* carried by rank 0; the others count from zero */
  c->crossings_local = s->rank == 0 ? total : 0;
  PetscFunctionReturn(0);
}

static PetscErrorCode vein_crossings_destroy(diagnostic *self) {
  vein_crossings *c = self->data;
  PetscFunctionBeginUser;
  PetscCall(vein_leaflets_destroy(&c->leaves));
  for (int w = 0; w < 2; w++)
    PetscCall(column_bins_destroy(&c->bins[w]));
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode vein_crossings_register(sim *s, const vein_layout *lay, diagnostic **out) {
  diagnostic *d;
  vein_crossings *c;
  PetscFunctionBeginUser;
  PetscCheck(lay->crossing_interval >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "vein: the crossing check interval must be >= 1 step (got %" PetscInt_FMT ")",
             lay->crossing_interval);
  PetscCall(diagnostic_create("vein_crossings", &d));
  PetscCall(PetscNew(&c));
  d->data = c;
  PetscCall(vein_leaflets_create(lay, &c->leaves));
  d->when.every_steps = lay->crossing_interval;
  d->when.at_outputs = PETSC_TRUE; /* the rows of "vein" report an up-to-date count */
  d->sample = vein_crossings_sample;
  d->destroy = vein_crossings_destroy;
  d->checkpoint_write = vein_crossings_checkpoint_write;
  d->checkpoint_read = vein_crossings_checkpoint_read;
  PetscCall(diagnostics_add(s, d));
  *out = d;
  PetscFunctionReturn(0);
}
