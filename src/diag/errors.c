/* The diagnostic "errors": v_x against an exact solution, as the run goes (see
 * errors.h). Samples at the output times after step 0 (a row of error.csv) and
 * at the report times (a profile and a line of the end-of-run table). */
#include <math.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/diagnostics.h"
#include "dmhs/io.h"
#include "dmhs/errors.h"
#include "dmhs/gather.h"
#include "dmhs/whole_file.h"
#include "dmhs/checkpoint.h"

typedef struct errors {
  errors_exact_fn exact;
  const void *ctx;
  double v_ref; /* normalisation [m/s], fixed for the run */
  FILE *csv;    /* rank 0 only */
  PetscInt n_reports, next_report;
  double report_t[ERRORS_MAX_REPORTS];
  double reached_t[ERRORS_MAX_REPORTS], l2[ERRORS_MAX_REPORTS], linf[ERRORS_MAX_REPORTS],
      wall_s[ERRORS_MAX_REPORTS];
} errors;

PetscErrorCode errors_set_from_options(errors_times *times, sim *s) {
  PetscInt n = ERRORS_MAX_REPORTS;
  PetscBool set;
  PetscFunctionBeginUser;
  if (times->n == 0) {
    times->t[0] = 0.01;
    times->t[1] = 0.1;
    times->t[2] = 1.0;
    times->n = 3;
  }
  PetscOptionsBegin(s->comm, NULL, "Error against the series solution", NULL);
  PetscCall(options_read_real_array("-error_report_times",
                                    "Times at which errors and profiles are reported [s]", NULL,
                                    times->t, &n, &set));
  PetscOptionsEnd();
  if (set)
    times->n = n;
  for (PetscInt k = 0; k < times->n; k++)
    PetscCheck(times->t[k] > 0 && (k == 0 || times->t[k] > times->t[k - 1]), s->comm,
               PETSC_ERR_ARG_OUTOFRANGE,
               "-error_report_times must be positive and increasing (entry %d = %g)", (int)k,
               times->t[k]);
  PetscFunctionReturn(0);
}

/* <output_dir>/profile_t<t>.csv; C formatting of t (PETSc's would write "1.") */
static PetscErrorCode errors_profile_path(const sim *s, double t, char *path, size_t len) {
  char name[64];
  PetscFunctionBeginUser;
  snprintf(name, sizeof(name), "profile_t%g.csv", t);
  PetscCall(io_output_path(s, name, path, len));
  PetscFunctionReturn(0);
}

static PetscErrorCode errors_setup(errors *e, sim *s, errors_exact_fn exact, const void *ctx,
                                   double v_ref) {
  char path[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  PetscCheck(v_ref > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "errors: the reference speed must be > 0 (got %g): is the flow driven at all?", v_ref);
  e->exact = exact;
  e->ctx = ctx;
  e->v_ref = v_ref;
  e->next_report = 0;
  if (s->rank == 0) {
    /* a restart continues the file (errors_checkpoint_read drops rows past the checkpoint) */
    const PetscBool append = s->io->restart_file[0] ? PETSC_TRUE : PETSC_FALSE;
    PetscCall(io_output_path(s, "error.csv", path, sizeof(path)));
    e->csv = fopen(path, append ? "a" : "w");
    PetscCheck(e->csv, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write %s: %s", path,
               strerror(errno));
    if (!append) {
      PetscCheck(fprintf(e->csv, "step,t,wall_s,l2,linf\n") > 0, PETSC_COMM_SELF,
                 PETSC_ERR_FILE_WRITE, "cannot write %s", path);
      /* profiles of an earlier run in this directory would pass for this run's */
      for (PetscInt k = 0; k < e->n_reports; k++) {
        PetscCall(errors_profile_path(s, e->report_t[k], path, sizeof(path)));
        (void)remove(path); /* absent is fine */
      }
    }
  }
  PetscFunctionReturn(0);
}

/* Normalised RMS and max error over owned fluid particles, reduced over ranks. */
static PetscErrorCode errors_compute(errors *e, sim *s, double *l2, double *linf) {
  const particles *ps = &s->ps;
  double local[3] = {0, 0, 0}, global[3];
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID)
      continue;
    const double d = (ps->v[i][0] - e->exact(ps->x[i][1], s->t, e->ctx)) / e->v_ref;
    local[0] += d * d;
    local[1] += 1.0;
    local[2] = PetscMax(local[2], fabs(d));
  }
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, s->comm));
  PetscCallMPI(MPI_Allreduce(&local[2], &global[2], 1, MPI_DOUBLE, MPI_MAX, s->comm));
  *l2 = global[1] > 0 ? sqrt(global[0] / global[1]) : 0.0;
  *linf = global[2];
  PetscFunctionReturn(0);
}

/* profile_t<t>.csv: one row per fluid particle, written to a temporary name
 * and renamed so that a reader never sees half a file. Rank 0 writes the rows
 * of every rank, gathered with MPI_Gatherv and sorted by global id, so that the
 * file does not depend on the rank count. */
static int errors_compare_gid(const void *a, const void *b) {
  const double ga = ((const double *)a)[0], gb = ((const double *)b)[0];
  return (ga > gb) - (ga < gb);
}

static PetscErrorCode errors_write_profile(errors *e, sim *s, double t_report) {
  const particles *ps = &s->ps;
  char path[PETSC_MAX_PATH_LEN];
  double *mine, *all = NULL;
  size_t n_mine = 0, n_all;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(4 * particles_count_type(ps, PTYPE_FLUID) + 1, &mine));
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (ps->type[i] == PTYPE_FLUID) {
      mine[n_mine++] = (double)ps->gid[i];
      mine[n_mine++] = ps->x[i][1];
      mine[n_mine++] = ps->v[i][0];
      mine[n_mine++] = e->exact(ps->x[i][1], s->t, e->ctx);
    }
  PetscCall(gather_to_root(s->comm, mine, n_mine, &all, &n_all));
  PetscCall(PetscFree(mine));
  if (s->rank != 0)
    PetscFunctionReturn(0);
  qsort(all, n_all / 4, 4 * sizeof(double), errors_compare_gid);
  PetscCall(errors_profile_path(s, t_report, path, sizeof(path)));
  whole_file w;
  PetscCall(whole_file_open(&w, path, NULL));
  int ok = fprintf(w.f, "# t = %.9g s, v_ref = %.9g m/s\ny,vx,vx_exact\n", s->t, e->v_ref) > 0;
  for (size_t k = 0; k < n_all && ok; k += 4)
    ok = fprintf(w.f, "%.9e,%.9e,%.9e\n", all[k + 1], all[k + 2], all[k + 3]) > 0;
  PetscCall(PetscFree(all));
  PetscCall(whole_file_commit(&w, ok, NULL));
  PetscFunctionReturn(0);
}

/* The next report time is reached (within dt/2). */
static PetscBool errors_report_due(const errors *e, const sim *s) {
  return e->next_report < e->n_reports && s->t >= e->report_t[e->next_report] - 0.5 * s->dt
             ? PETSC_TRUE
             : PETSC_FALSE;
}

static PetscBool errors_due(const diagnostic *self, const sim *s) {
  return errors_report_due(self->data, s);
}

/* A row at output times (the schedule), a profile at report times (errors_due). */
static PetscErrorCode errors_sample(diagnostic *self, sim *s) {
  errors *e = self->data;
  const PetscBool output_step = s->step > 0 && diagnostic_output_time(s) ? PETSC_TRUE : PETSC_FALSE;
  const PetscBool report_step = errors_report_due(e, s);
  double l2, linf;
  PetscFunctionBeginUser;
  if (!output_step && !report_step)
    PetscFunctionReturn(0);
  PetscCall(errors_compute(e, s, &l2, &linf));
  const double wall = s->step > 0 ? MPI_Wtime() - s->loop_start_wtime : 0.0;
  if (output_step && s->rank == 0) {
    PetscCheck(fprintf(e->csv, "%" PetscInt_FMT ",%.9g,%.6g,%.6e,%.6e\n", s->step, s->t, wall, l2,
                       linf) > 0 &&
                   fflush(e->csv) == 0,
               PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "writing error.csv failed (disk full?)");
  }
  if (report_step) {
    const PetscInt k = e->next_report++;
    e->reached_t[k] = s->t;
    e->l2[k] = l2;
    e->linf[k] = linf;
    e->wall_s[k] = wall;
    PetscCall(errors_write_profile(e, s, e->report_t[k]));
  }
  PetscFunctionReturn(0);
}

/* The errors at the report times reached and the wall-clock time. */
static PetscErrorCode errors_finish(diagnostic *self, sim *s) {
  errors *e = self->data;
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(
      s->comm, "Error of v_x against the series solution (normalised by %.4g m/s):\n", e->v_ref));
  PetscCall(
      PetscPrintf(s->comm, "  %10s  %12s  %12s  %10s\n", "t [s]", "L2 (RMS)", "Linf", "wall [s]"));
  for (PetscInt k = 0; k < e->next_report; k++)
    PetscCall(PetscPrintf(s->comm, "  %10.4g  %11.4f%%  %11.4f%%  %10.3f\n", e->reached_t[k],
                          100 * e->l2[k], 100 * e->linf[k], e->wall_s[k]));
  for (PetscInt k = e->next_report; k < e->n_reports; k++)
    PetscCall(
        PetscPrintf(s->comm, "  %10.4g  (not reached: t_end = %g s)\n", e->report_t[k], s->t_end));
  PetscCall(PetscPrintf(s->comm, "  wall-clock of the step loop: %.3f s\n", s->loop_seconds));
  PetscFunctionReturn(0);
}

/* The reports done so far; on restart error.csv is continued. */
static PetscErrorCode errors_checkpoint_write(diagnostic *self, sim *s, checkpoint_io *io) {
  errors *e = self->data;
  const PetscInt64 next = e->next_report;
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(checkpoint_put_ints(io, "errors_next_report", &next, 1));
  PetscCall(checkpoint_put_reals(io, "errors_reached_t", e->reached_t, e->next_report));
  PetscCall(checkpoint_put_reals(io, "errors_l2", e->l2, e->next_report));
  PetscCall(checkpoint_put_reals(io, "errors_linf", e->linf, e->next_report));
  PetscCall(checkpoint_put_reals(io, "errors_wall_s", e->wall_s, e->next_report));
  PetscFunctionReturn(0);
}

/* error.csv keeps its header and the rows up to the checkpoint's step: rows the
 * interrupted run wrote after the checkpoint are written again as the run continues. The
 * row at that step stays only if the errors sampled there (at_step): else it is the final
 * output of a run that ended at the checkpoint. */
static PetscErrorCode errors_csv_truncate(errors *e, sim *s, PetscBool at_step) {
  char path[PETSC_MAX_PATH_LEN], line[512];
  whole_file w;
  PetscFunctionBeginUser;
  PetscCall(io_output_path(s, "error.csv", path, sizeof(path)));
  PetscCheck(fclose(e->csv) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "closing %s failed", path);
  e->csv = NULL;
  FILE *in = fopen(path, "r");
  PetscCheck(in, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot rewrite %s: %s", path,
             strerror(errno));
  PetscCall(whole_file_open(&w, path, NULL));
  FILE *out = w.f;
  int ok = 1, first = 1;
  while (ok && fgets(line, sizeof(line), in)) {
    long long step;
    const long long last = (long long)s->step - (at_step ? 0 : 1);
    const int keep = first ? 1 : sscanf(line, "%lld,", &step) == 1 && step <= last;
    if (first && strncmp(line, "step,", 5))
      ok = fprintf(out, "step,t,wall_s,l2,linf\n") > 0;
    if (keep)
      ok = ok && fputs(line, out) >= 0;
    first = 0;
  }
  if (first)
    ok = fprintf(out, "step,t,wall_s,l2,linf\n") > 0;
  fclose(in);
  PetscCall(whole_file_commit(&w, ok, NULL));
  e->csv = fopen(path, "a");
  PetscCheck(e->csv, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write %s: %s", path,
             strerror(errno));
  PetscFunctionReturn(0);
}

static PetscErrorCode errors_checkpoint_read(diagnostic *self, sim *s, checkpoint_io *io) {
  errors *e = self->data;
  PetscInt64 next;
  PetscFunctionBeginUser;
  PetscCall(checkpoint_get_ints(io, "errors_next_report", &next, 1));
  PetscCheck(next >= 0 && next <= e->n_reports, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP,
             "the checkpoint has %" PetscInt64_FMT
             " error reports done but -error_report_times lists %" PetscInt_FMT
             ": restart with the same -error_report_times",
             next, e->n_reports);
  e->next_report = (PetscInt)next;
  PetscCall(checkpoint_get_reals(io, "errors_reached_t", e->reached_t, e->next_report));
  PetscCall(checkpoint_get_reals(io, "errors_l2", e->l2, e->next_report));
  PetscCall(checkpoint_get_reals(io, "errors_linf", e->linf, e->next_report));
  PetscCall(checkpoint_get_reals(io, "errors_wall_s", e->wall_s, e->next_report));
  if (s->rank == 0)
    PetscCall(errors_csv_truncate(e, s, self->restart_sampled));
  PetscFunctionReturn(0);
}

static PetscErrorCode errors_destroy(diagnostic *self) {
  errors *e = self->data;
  PetscFunctionBeginUser;
  if (e->csv) {
    PetscCheck(fclose(e->csv) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
               "closing error.csv failed");
    e->csv = NULL;
  }
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode errors_register(sim *s, const errors_times *times, errors_exact_fn exact,
                               const void *ctx, double v_ref) {
  diagnostic *d;
  errors *e;
  PetscFunctionBeginUser;
  PetscCall(diagnostic_create("errors", &d));
  PetscCall(PetscNew(&e));
  d->data = e;
  d->output = "error.csv";
  d->when.at_outputs = PETSC_TRUE;
  d->when.not_at_start = PETSC_TRUE; /* the error of the exact initial state says nothing */
  d->due = errors_due;
  d->sample = errors_sample;
  d->finish = errors_finish;
  d->destroy = errors_destroy;
  d->checkpoint_write = errors_checkpoint_write;
  d->checkpoint_read = errors_checkpoint_read;
  PetscCall(diagnostics_add(s, d));
  e->n_reports = times->n;
  PetscCall(PetscArraycpy(e->report_t, times->t, times->n));
  PetscCall(errors_setup(e, s, exact, ctx, v_ref));
  PetscFunctionReturn(0);
}
