/* The diagnostic "peristaltic_flux": period means of the peristaltic channel's
 * volume flux (peristaltic_flux.h).
 *
 * Rank invariance: the sum over particles is exact, in fixed point (a unit of
 * 2^-40 of 2 a lambda c, the channel's volume times the wave speed, so rounding
 * is 1e-12 of the scale at any size); the maxima are order independent. */
#include <math.h>
#include "peristaltic_flux.h"
#include "dmhs/diagnostics.h"
#include "dmhs/analytic.h"
#include "dmhs/checkpoint.h"
#include "dmhs/csv.h"
#include "dmhs/liquid_state.h"

#define FLUX_CSV "flux.csv"

typedef struct {
  peristaltic_flux_layout lay;
  double period, Q_theory; /* T = lambda/c [s], the theory's mean flux [m^2/s] */
  double unit;             /* fixed-point unit of sum V v_x [m^3/s] */
  /* the running state a restart continues (checkpointed) */
  PetscInt64 sampled;           /* 1 once a sample exists */
  PetscInt64 cycles;            /* completed periods */
  double t_prev, Q_prev;        /* the last sample */
  double t_acc, Q_acc;          /* where the integral stands, and Q there */
  double integral;              /* of Q dt from the current period's start to t_acc [m^2] */
  double last_mean;             /* Q_mean of the last completed period [m^2/s] */
  double rho_dev_max, mach_max; /* the liquid's bounds over the run */
  FILE *csv;                    /* rank 0 */
} peristaltic_flux;

/* Q(t) = sum_j V_j v_x,j / lambda over the liquid of every rank. */
static PetscErrorCode flux_now(peristaltic_flux *f, sim *s, double *Q) {
  const particles *ps = &s->ps;
  PetscInt64 sum = 0;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (ps->type[i] == PTYPE_FLUID)
      sum += (PetscInt64)llround(ps->mass[i] / ps->rho[i] * ps->v[i][0] / f->unit);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPIU_INT64, MPI_SUM, s->comm));
  *Q = (double)sum * f->unit / f->lay.lambda;
  PetscFunctionReturn(0);
}

static PetscErrorCode flux_open_csv(peristaltic_flux *f, sim *s) {
  PetscFunctionBeginUser;
  /* a restart keeps the rows of the periods completed before its checkpoint */
  PetscCall(
      csv_open_keeping(s, FLUX_CSV, "cycle,t,Q_mean,Q_theory\n", (double)f->cycles + 0.5, &f->csv));
  PetscFunctionReturn(0);
}

static PetscErrorCode flux_period_done(peristaltic_flux *f) {
  PetscFunctionBeginUser;
  f->cycles++;
  f->last_mean = f->integral / f->period;
  f->integral = 0;
  if (f->csv)
    PetscCall(csv_row(f->csv, FLUX_CSV, "%" PetscInt64_FMT ",%.10g,%.10g,%.10g\n", f->cycles,
                      (double)f->cycles * f->period, f->last_mean, f->Q_theory));
  PetscFunctionReturn(0);
}

static PetscErrorCode flux_sample(diagnostic *self, sim *s) {
  peristaltic_flux *f = self->data;
  double Q, rho_dev, mach;
  PetscFunctionBeginUser;
  if (s->rank == 0 && !f->csv)
    PetscCall(flux_open_csv(f, s));
  PetscCall(flux_now(f, s, &Q));
  PetscCall(liquid_state_bounds(s, &rho_dev, &mach));
  f->rho_dev_max = PetscMax(f->rho_dev_max, rho_dev);
  f->mach_max = PetscMax(f->mach_max, mach);
  if (f->sampled) {
    /* trapezoids from where the integral stands, cut at every period end the step
     * reaches, Q interpolated linearly between the samples; the run stops at the step
     * nearest -t_end, so a step within dt/2 of a period's end completes it (Q held over
     * the rest) */
    const double t1 = s->t, span = t1 - f->t_prev;
    for (double end = (double)(f->cycles + 1) * f->period; t1 >= end - 0.5 * s->dt;
         end = (double)(f->cycles + 1) * f->period) {
      const double u = span > 0 ? PetscMin(1.0, PetscMax(0.0, (end - f->t_prev) / span)) : 1.0;
      const double Q_end = f->Q_prev + u * (Q - f->Q_prev);
      f->integral += 0.5 * (f->Q_acc + Q_end) * (end - f->t_acc);
      PetscCall(flux_period_done(f));
      f->t_acc = end;
      f->Q_acc = Q_end;
    }
    if (t1 > f->t_acc) {
      f->integral += 0.5 * (f->Q_acc + Q) * (t1 - f->t_acc);
      f->t_acc = t1;
      f->Q_acc = Q;
    }
  } else {
    f->t_acc = s->t;
    f->Q_acc = Q;
  }
  f->sampled = 1;
  f->t_prev = s->t;
  f->Q_prev = Q;
  PetscFunctionReturn(0);
}

static PetscErrorCode flux_finish(diagnostic *self, sim *s) {
  peristaltic_flux *f = self->data;
  PetscFunctionBeginUser;
  if (f->cycles > 0)
    PetscCall(
        PetscPrintf(s->comm,
                    "peristaltic_flux: period %" PetscInt64_FMT
                    " (t = %g s): Q_mean = %.6g m^2/s, Q_theory = %.6g m^2/s, "
                    "relative error %.3g %%\n",
                    f->cycles, (double)f->cycles * f->period, f->last_mean, f->Q_theory,
                    f->Q_theory != 0 ? 100.0 * (f->last_mean - f->Q_theory) / f->Q_theory : 0.0));
  else
    PetscCall(PetscPrintf(s->comm,
                          "peristaltic_flux: no wave period completed (T = %g s, t = %g s): "
                          "nothing to compare with Q_theory = %.6g m^2/s\n",
                          f->period, s->t, f->Q_theory));
  PetscCall(PetscPrintf(
      s->comm, "peristaltic_flux: over the run max |rho/rho0 - 1| = %.3g, max Mach = %.3g\n",
      f->rho_dev_max, f->mach_max));
  PetscCall(csv_close(&f->csv, FLUX_CSV));
  PetscFunctionReturn(0);
}

static PetscErrorCode flux_checkpoint_write(diagnostic *self, sim *s, checkpoint_io *io) {
  peristaltic_flux *f = self->data;
  const PetscInt64 counts[2] = {f->sampled, f->cycles};
  const double state[8] = {f->t_prev,   f->Q_prev,    f->t_acc,       f->Q_acc,
                           f->integral, f->last_mean, f->rho_dev_max, f->mach_max};
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(checkpoint_put_ints(io, "counts", counts, 2));
  PetscCall(checkpoint_put_reals(io, "state", state, 8));
  PetscFunctionReturn(0);
}

static PetscErrorCode flux_checkpoint_read(diagnostic *self, sim *s, checkpoint_io *io) {
  peristaltic_flux *f = self->data;
  PetscInt64 counts[2];
  double state[8];
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(checkpoint_get_ints(io, "counts", counts, 2));
  PetscCall(checkpoint_get_reals(io, "state", state, 8));
  f->sampled = counts[0];
  f->cycles = counts[1];
  f->t_prev = state[0];
  f->Q_prev = state[1];
  f->t_acc = state[2];
  f->Q_acc = state[3];
  f->integral = state[4];
  f->last_mean = state[5];
  f->rho_dev_max = state[6];
  f->mach_max = state[7];
  PetscFunctionReturn(0);
}

static PetscErrorCode flux_destroy(diagnostic *self) {
  peristaltic_flux *f = self->data;
  PetscFunctionBeginUser;
  if (f->csv)
    fclose(f->csv);
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode peristaltic_flux_register(sim *s, const peristaltic_flux_layout *lay) {
  diagnostic *d;
  peristaltic_flux *f;
  PetscFunctionBeginUser;
  PetscCheck(lay->a > 0 && lay->lambda > 0 && lay->c > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "peristaltic_flux: a, lambda and c must be > 0 (got %g, %g, %g)", lay->a, lay->lambda,
             lay->c);
  PetscCall(diagnostic_create("peristaltic_flux", &d));
  PetscCall(PetscNew(&f));
  f->lay = *lay;
  f->period = lay->lambda / lay->c;
  f->Q_theory = analytic_peristaltic_flux(lay->a, lay->b, lay->c);
  f->unit = ldexp(2.0 * lay->a * lay->lambda * lay->c, -40);
  d->data = f;
  d->output = FLUX_CSV;
  d->when.every_steps = 1;
  d->sample = flux_sample;
  d->finish = flux_finish;
  d->destroy = flux_destroy;
  d->checkpoint_write = flux_checkpoint_write;
  d->checkpoint_read = flux_checkpoint_read;
  PetscCall(diagnostics_add(s, d));
  PetscFunctionReturn(0);
}
