/* The diagnostic "flap": flap.csv at output times, the end-of-run report and
 * flap-particles.csv (flap_metrics.h). */
#include <math.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "dmhs/gather.h"
#include "dmhs/diagnostics.h"
#include "dmhs/io.h"
#include "dmhs/csv.h"
#include "flap_strip.h"

typedef struct {
  flap_strip st;
  const diagnostic *crossings;
  FILE *csv;
} flap_rows;

/* rows at step 0 and at output times; a restarted run continues the file */
static PetscErrorCode flap_rows_sample(diagnostic *self, sim *s) {
  flap_rows *f = self->data;
  double tip[2], slip, near, umax;
  PetscFunctionBeginUser;
  PetscCall(flap_strip_gather(&f->st, s));
  if (s->rank == 0 && !f->csv) { /* mpi: rank 0 writes */
    char header[160];
    snprintf(header, sizeof(header),
             "# flap: height %g m, dx %g m\nt,tip_dx,tip_dy,crossings,slip,near,u_max\n",
             f->st.lay.height_rows * f->st.lay.dx, f->st.lay.dx);
    PetscCall(csv_open(s, "flap.csv", header, &f->csv));
  }
  flap_strip_tip(&f->st, tip);
  PetscCall(flap_slip(&f->st, s, &slip, &near, &umax));
  if (s->rank == 0) { /* mpi: rank 0 writes */
    /* slip is undefined while the liquid is at rest (u_max = 0): an empty cell, never NaN */
    char slip_s[32] = "", near_s[32] = "";
    if (isfinite(slip))
      snprintf(slip_s, sizeof(slip_s), "%.6g", slip);
    if (isfinite(near))
      snprintf(near_s, sizeof(near_s), "%.6g", near);
    PetscCall(csv_row(f->csv, "flap.csv", "%.8g,%.8g,%.8g,%" PetscInt_FMT ",%s,%s,%.6g\n", s->t,
                      tip[0], tip[1], flap_crossings_count(f->crossings), slip_s, near_s, umax));
  }
  PetscFunctionReturn(0);
}

#define FLAP_ROW 6 /* gid, x, y, vx, vy, type */

static int flap_compare_gid(const void *a, const void *b) {
  const double ga = ((const double *)a)[0], gb = ((const double *)b)[0];
  return (ga > gb) - (ga < gb);
}

static PetscErrorCode flap_rows_finish(diagnostic *self, sim *s) {
  flap_rows *f = self->data;
  const particles *ps = &s->ps;
  char path[PETSC_MAX_PATH_LEN];
  double tip[2], slip, near, umax;
  PetscFunctionBeginUser;
  PetscCall(flap_strip_gather(&f->st, s));
  flap_strip_tip(&f->st, tip);
  PetscCall(flap_slip(&f->st, s, &slip, &near, &umax));
  PetscCall(PetscPrintf(
      s->comm,
      "flap: tip displacement (%g, %g) m (%.3g of the height), fluid crossings %" PetscInt_FMT
      ", slip on the faces |u(d=0) - v_flap|/u_max = %.3g (first fluid layer %.3g), u_max = %g "
      "m/s\n",
      tip[0], tip[1], tip[0] / (f->st.lay.height_rows * f->st.lay.dx),
      flap_crossings_count(f->crossings), slip, near, umax));
  PetscCall(csv_close(&f->csv, "flap.csv"));
  /* mpi: rows of every rank gathered to rank 0 and sorted by gid (independent of the rank count) */
  const size_t n_mine = FLAP_ROW * (size_t)ps->n_owned;
  size_t n_all;
  double *mine, *all = NULL;
  PetscCall(PetscMalloc1(n_mine + 1, &mine));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    double *r = mine + FLAP_ROW * i;
    r[0] = (double)ps->gid[i]; /* exact below 2^53 */
    r[1] = ps->x[i][0];
    r[2] = ps->x[i][1];
    r[3] = ps->v[i][0];
    r[4] = ps->v[i][1];
    r[5] = (double)ps->type[i];
  }
  PetscCall(gather_to_root(s->comm, mine, n_mine, &all, &n_all));
  PetscCall(PetscFree(mine));
  if (s->rank == 0) {
    qsort(all, n_all / FLAP_ROW, FLAP_ROW * sizeof(double), flap_compare_gid);
    PetscCall(io_output_path(s, "flap-particles.csv", path, sizeof(path)));
    FILE *out = fopen(path, "w");
    PetscCheck(out, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write %s: %s", path,
               strerror(errno));
    int ok = fprintf(out, "x,y,vx,vy,type\n") > 0;
    for (size_t k = 0; k < n_all && ok; k += FLAP_ROW)
      ok = fprintf(out, "%.6g,%.6g,%.6g,%.6g,%d\n", all[k + 1], all[k + 2], all[k + 3], all[k + 4],
                   (int)all[k + 5]) > 0;
    ok = fclose(out) == 0 && ok;
    PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot write %s (disk full?)", path);
    PetscCall(PetscFree(all));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode flap_rows_destroy(diagnostic *self) {
  flap_rows *f = self->data;
  PetscFunctionBeginUser;
  if (f->csv)
    fclose(f->csv);
  PetscCall(flap_strip_destroy(&f->st));
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode flap_rows_register(sim *s, const flap_layout *lay, const diagnostic *crossings) {
  diagnostic *d;
  flap_rows *f;
  PetscFunctionBeginUser;
  PetscCall(diagnostic_create("flap", &d));
  PetscCall(PetscNew(&f));
  d->data = f;
  PetscCall(flap_strip_create(lay, &f->st));
  f->crossings = crossings;
  d->output = "flap.csv";
  d->when.at_outputs = PETSC_TRUE;
  d->sample = flap_rows_sample;
  d->finish = flap_rows_finish;
  d->destroy = flap_rows_destroy;
  PetscCall(diagnostics_add(s, d));
  PetscFunctionReturn(0);
}
