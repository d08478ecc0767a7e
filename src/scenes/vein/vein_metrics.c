/* The diagnostic "vein" of the deep-vein valve (header: vein_metrics.h; the
 * crossings are counted by "vein_crossings", vein_crossings.c).
 *
 * At every output time (and t = 0), a row of <output_dir>/vein.csv:
 *   t; u_mean, u_centre: the liquid's mean v_x over the cross-section at the
 *   inlet station (x = 0, the middle of the straight part, |x| < dx) and its
 *   mean v_x within dx of the axis there [m/s]; u_flux: the liquid's volume
 *   flux (sum of V v_x over the whole period, V = m/rho, divided by the period
 *   length) over the width W, the station's mean for an incompressible liquid,
 *   without the sampling noise and acoustic pulses of a slab [m/s]; the tips (mid-point of each
 *   leaflet's last column) and the gap between them [m]; crossings; the
 *   sinus-side peak: the largest total stress |sigma| (stress.c) among the
 *   liquid that started in the sinus and now lies within 2 dx of a leaflet's
 *   sinus face (its nearest leaflet particle is on the sinus layer), its gid;
 *   the measurement point (the thesis's): the particle holding that peak at
 *   -vein_probe_time (a quarter period: the forward peak), followed by gid
 *   from then on, with its |sigma| and displacement |x - x0| [m] (empty before
 *   it is chosen); max |rho/rho0 - 1| and max |v|/c0 over the liquid.
 * Once per drive period (first output at or after t = k T): the liquid that
 * started in the sinus, one row per particle (gid order) in vein-sinus.csv:
 *   t, cycle, gid, x, y, displacement.
 * At the end, vein-summary.csv (key,value) and the report: the peak inlet
 * velocities over the first cycle and the run, the measurement point's
 * time-averaged displacement and its peak stress per completed cycle, each
 * with its standard deviation, the gap's range and the crossings.
 *
 * Rank invariance: sums over particles are exact (fixed point or a single
 * contribution per entry), maxima are order independent, tied maxima go to
 * the lowest gid, and per-particle rows are sorted by gid. */
#include <errno.h>
#include <math.h>
#include <string.h>
#include "vein_metrics.h"
#include "dmhs/diagnostics.h"
#include "dmhs/io.h"
#include "dmhs/sph.h"
#include "dmhs/stress.h"
#include "dmhs/gather.h"
#include "dmhs/extreme.h"
#include "dmhs/checkpoint.h"
#include "vein_cycle_peaks.h"
#include "dmhs/csv.h"
#include "dmhs/whole_file.h"
#include "dmhs/liquid_state.h"
#include "vein_leaflets.h"

#define VEIN_FIXED      1e-12 /* fixed-point unit of velocity sums [m/s] */
#define VEIN_FIXED_FLUX 1e-15 /* fixed-point unit of one particle's share of u_flux [m/s] */

typedef struct vein_metrics {
  vein_layout lay;
  vein_leaflets leaves;
  const diagnostic *crossings_check; /* "vein_crossings" */
  PetscInt64 crossings;              /* its count over all ranks, at the last output */
  PetscInt64 probe_gid;              /* -1 until chosen */
  PetscInt next_cycle;               /* next cycle whose sinus rows are due */
  /* history (replicated) of the measurement point, for the statistics */
  PetscInt n_hist, cap_hist;
  double (*hist)[3]; /* per output row after the choice: t, |sigma|, |x - x0| */
  /* running extremes (replicated) */
  double u_mean_peak1, u_centre_peak1, u_mean_peak, u_centre_peak, u_flux_peak1, u_flux_peak;
  double gap_min, gap_max, rho_dev_max, mach_max;
  FILE *csv, *sinus;
} vein_metrics;

/* Inlet station: fixed-point sums of v_x over the cross-section and near the axis. */
static PetscErrorCode vein_station(vein_metrics *v, sim *s, double *u_mean, double *u_centre) {
  const particles *ps = &s->ps;
  const double dx = v->lay.dx;
  PetscInt64 acc[4] = {0, 0, 0, 0}; /* n, sum, n_axis, sum_axis */
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID)
      continue;
    double d[2] = {ps->x[i][0] - v->lay.x_station, 0};
    domain_min_image(&s->dom, d);
    if (fabs(d[0]) >= dx)
      continue;
    const PetscInt64 q = (PetscInt64)llround(ps->v[i][0] / VEIN_FIXED);
    acc[0]++;
    acc[1] += q;
    if (fabs(ps->x[i][1]) < dx) {
      acc[2]++;
      acc[3] += q;
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, acc, 4, MPIU_INT64, MPI_SUM, s->comm));
  *u_mean = acc[0] ? (double)acc[1] * VEIN_FIXED / (double)acc[0] : 0;
  *u_centre = acc[2] ? (double)acc[3] * VEIN_FIXED / (double)acc[2] : 0;
  PetscFunctionReturn(0);
}

/* The liquid's volume flux over the period as a mean velocity across the channel's width. */
static PetscErrorCode vein_flux(vein_metrics *v, sim *s, double *u_flux) {
  const particles *ps = &s->ps;
  const double scale = 1.0 / ((s->dom.hi[0] - s->dom.lo[0]) * v->lay.width * VEIN_FIXED_FLUX);
  PetscInt64 acc = 0;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (ps->type[i] == PTYPE_FLUID)
      acc += (PetscInt64)llround(ps->mass[i] / ps->rho[i] * ps->v[i][0] * scale);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &acc, 1, MPIU_INT64, MPI_SUM, s->comm));
  *u_flux = (double)acc * VEIN_FIXED_FLUX;
  PetscFunctionReturn(0);
}

/* The sinus-side peak of |sigma| (value, gid; lowest gid on ties) over all ranks. */
static PetscErrorCode vein_sinus_peak(vein_metrics *v, sim *s, double *peak, PetscInt64 *gid) {
  const particles *ps = &s->ps;
  const double dx = v->lay.dx, reach2 = 4 * dx * dx;
  const PetscInt n = v->leaves.n_leaf[0] + v->leaves.n_leaf[1];
  extreme_value mine = EXTREME_NONE, best;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID || ps->tracer[i] != VEIN_TRACER_SINUS)
      continue;
    if (ps->stress_mag[i] < mine.value)
      continue;
    double best = INFINITY;
    PetscInt kb = -1;
    for (PetscInt k = 0; k < n; k++) {
      double d[2] = {ps->x[i][0] - v->leaves.x[k][0], ps->x[i][1] - v->leaves.x[k][1]};
      if (fabs(d[1]) > 3 * dx)
        continue;
      domain_min_image(&s->dom, d);
      const double r2 = d[0] * d[0] + d[1] * d[1];
      if (r2 < best) {
        best = r2;
        kb = k;
      }
    }
    if (kb < 0 || best >= reach2)
      continue;
    const int w = kb >= v->leaves.n_leaf[0];
    const PetscInt local = kb - (w ? v->leaves.n_leaf[0] : 0);
    if (local % 2 != v->lay.leaflet[w].sinus_layer || local < 2)
      continue; /* the sinus face, not the clamp */
    extreme_consider(&mine, ps->stress_mag[i], ps->gid[i]);
  }
  PetscCall(extreme_max(s->comm, mine, &best));
  *peak = best.gid >= 0 ? best.value : -1.0;
  *gid = best.gid;
  PetscFunctionReturn(0);
}

/* |sigma| and |x - x0| of one particle by gid (its owner contributes; exact SUM). */
static PetscErrorCode vein_particle_values(sim *s, PetscInt64 gid, double *stress, double *disp) {
  double buf[3] = {0, 0, 0};
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < s->ps.n_owned; i++)
    if (s->ps.gid[i] == gid) {
      buf[0] = s->ps.stress_mag[i];
      buf[1] = s->ps.displacement[i];
      buf[2] = 1;
    }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, buf, 3, MPI_DOUBLE, MPI_SUM, s->comm));
  PetscCheck(buf[2] == 1, s->comm, PETSC_ERR_PLIB,
             "vein: measurement particle gid %" PetscInt64_FMT " not found", gid);
  *stress = buf[0];
  *disp = buf[1];
  PetscFunctionReturn(0);
}

/* The sinus liquid, one row per particle in gid order, on rank 0. */
static PetscErrorCode vein_write_sinus(vein_metrics *v, sim *s, PetscInt cycle) {
  const particles *ps = &s->ps;
  double *mine, *all = NULL;
  size_t n_mine = 0, n_all;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(4 * (size_t)ps->n_owned + 1, &mine));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID || ps->tracer[i] != VEIN_TRACER_SINUS)
      continue;
    mine[n_mine++] = (double)ps->gid[i];
    mine[n_mine++] = ps->x[i][0];
    mine[n_mine++] = ps->x[i][1];
    mine[n_mine++] = ps->displacement[i];
  }
  PetscCall(gather_to_root(s->comm, mine, n_mine, &all, &n_all));
  PetscCall(PetscFree(mine));
  if (s->rank == 0) {
    const PetscInt n = (PetscInt)(n_all / 4);
    PetscInt *order;
    PetscReal *key;
    PetscCall(PetscMalloc2(n, &order, n, &key));
    for (PetscInt k = 0; k < n; k++) {
      order[k] = k;
      key[k] = all[4 * k];
    }
    PetscCall(PetscSortRealWithPermutation(n, key, order));
    if (!v->sinus)
      PetscCall(csv_open(s, "vein-sinus.csv", "t,cycle,gid,x,y,displacement\n", &v->sinus));
    for (PetscInt k = 0; k < n; k++) {
      const double *r = all + 4 * order[k];
      PetscCall(csv_row(v->sinus, "vein-sinus.csv", "%.8g,%" PetscInt_FMT ",%.0f,%.9g,%.9g,%.6g\n",
                        s->t, cycle, r[0], r[1], r[2], r[3]));
    }
    PetscCall(PetscFree2(order, key));
    PetscCall(PetscFree(all));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode vein_history_push(vein_metrics *v, double t, double stress, double disp) {
  PetscFunctionBeginUser;
  if (v->n_hist == v->cap_hist) {
    v->cap_hist = 2 * v->cap_hist + 64;
    PetscCall(PetscRealloc(sizeof(*v->hist) * (size_t)v->cap_hist, &v->hist));
  }
  v->hist[v->n_hist][0] = t;
  v->hist[v->n_hist][1] = stress;
  v->hist[v->n_hist++][2] = disp;
  PetscFunctionReturn(0);
}

static void vein_csv_real(char *buf, size_t len, PetscBool have, double x) {
  if (have && isfinite(x))
    snprintf(buf, len, "%.8g", x);
  else
    buf[0] = 0; /* empty cell, never NaN */
}

/* At output times (the schedule). */
static PetscErrorCode vein_metrics_sample(diagnostic *self, sim *s) {
  vein_metrics *v = self->data;
  PetscFunctionBeginUser;
  /* a restarted run continues with the next output time: its step-0 state was written */
  if (s->io->restarted && s->t <= s->io->restart_t + 0.5 * s->dt)
    PetscFunctionReturn(0);
  PetscCall(vein_leaflets_gather(&v->leaves, s));
  PetscCall(stress_compute(s));
  double u_mean = 0, u_centre = 0, u_flux = 0, peak = 0, probe_stress = 0, probe_disp = 0,
         rho_dev = 0, mach = 0, tip[2][2];
  PetscInt64 peak_gid = -1;
  PetscCall(vein_station(v, s, &u_mean, &u_centre));
  PetscCall(vein_flux(v, s, &u_flux));
  PetscCall(vein_sinus_peak(v, s, &peak, &peak_gid));
  PetscCall(liquid_state_bounds(s, &rho_dev, &mach));
  PetscCall(vein_crossings_total(v->crossings_check, s, &v->crossings));
  for (int w = 0; w < 2; w++)
    vein_leaflets_column_mid(&v->leaves, w, v->lay.leaflet[w].n_columns - 1, tip[w]);
  double dtip[2] = {tip[0][0] - tip[1][0], tip[0][1] - tip[1][1]};
  domain_min_image(&s->dom, dtip);
  const double gap = hypot(dtip[0], dtip[1]);
  const double T = v->lay.period_T;
  if (v->probe_gid < 0 && s->t >= v->lay.probe_time - 0.5 * s->dt && peak_gid >= 0)
    v->probe_gid = peak_gid;
  if (v->probe_gid >= 0) {
    PetscCall(vein_particle_values(s, v->probe_gid, &probe_stress, &probe_disp));
    PetscCall(vein_history_push(v, s->t, probe_stress, probe_disp));
  }
  v->gap_min = PetscMin(v->gap_min, gap);
  v->gap_max = PetscMax(v->gap_max, gap);
  v->rho_dev_max = PetscMax(v->rho_dev_max, rho_dev);
  v->mach_max = PetscMax(v->mach_max, mach);
  v->u_mean_peak = PetscMax(v->u_mean_peak, fabs(u_mean));
  v->u_centre_peak = PetscMax(v->u_centre_peak, fabs(u_centre));
  v->u_flux_peak = PetscMax(v->u_flux_peak, fabs(u_flux));
  if (T <= 0 || s->t <= T + 0.5 * s->dt) {
    v->u_mean_peak1 = PetscMax(v->u_mean_peak1, fabs(u_mean));
    v->u_centre_peak1 = PetscMax(v->u_centre_peak1, fabs(u_centre));
    v->u_flux_peak1 = PetscMax(v->u_flux_peak1, fabs(u_flux));
  }
  if (T > 0 && s->t >= v->next_cycle * T - 0.5 * s->dt) {
    PetscCall(vein_write_sinus(v, s, v->next_cycle));
    v->next_cycle = (PetscInt)floor(s->t / T + 0.5 * s->dt / T) + 1;
  }
  if (s->rank == 0) { /* mpi: rank 0 writes */
    if (!v->csv) {
      char header[512];
      PetscCall(PetscSNPrintf(
          header, sizeof(header),
          "# vein: leaflet %g m, g0 %g m/s^2, k_a %g J (at dx = 1e-4 m), T %g s, dx %g m, rest "
          "gap %g m\nt,u_mean,u_centre,tip_upper_x,tip_upper_y,tip_lower_x,tip_lower_y,gap,"
          "crossings,peak_stress,peak_gid,probe_gid,probe_stress,probe_disp,rho_dev,mach,u_flux\n",
          v->lay.leaflet_length, v->lay.g0, v->lay.ka_ref, T, v->lay.dx, v->lay.rest_gap));
      PetscCall(csv_open(s, "vein.csv", header, &v->csv));
    }
    char ps_s[32], pg_s[32], pr_g[32], pr_s[32], pr_d[32];
    vein_csv_real(ps_s, sizeof(ps_s), peak_gid >= 0, peak);
    if (peak_gid >= 0)
      snprintf(pg_s, sizeof(pg_s), "%" PetscInt64_FMT, peak_gid);
    else
      pg_s[0] = 0;
    if (v->probe_gid >= 0)
      snprintf(pr_g, sizeof(pr_g), "%" PetscInt64_FMT, v->probe_gid);
    else
      pr_g[0] = 0;
    vein_csv_real(pr_s, sizeof(pr_s), v->probe_gid >= 0, probe_stress);
    vein_csv_real(pr_d, sizeof(pr_d), v->probe_gid >= 0, probe_disp);
    PetscCall(csv_row(v->csv, "vein.csv",
                      "%.8g,%.8g,%.8g,%.9g,%.9g,%.9g,%.9g,%.8g,%" PetscInt64_FMT
                      ",%s,%s,%s,%s,%s,%.6g,%.6g,%.8g\n",
                      s->t, u_mean, u_centre, tip[0][0], tip[0][1], tip[1][0], tip[1][1], gap,
                      v->crossings, ps_s, pg_s, pr_g, pr_s, pr_d, rho_dev, mach, u_flux));
  }
  PetscFunctionReturn(0);
}

/* Mean and sample standard deviation of x[0], x[stride], ... (n values). */
static void vein_mean_std(const double *x, PetscInt n, PetscInt stride, double *mean, double *std) {
  double m = 0, q = 0;
  for (PetscInt k = 0; k < n; k++)
    m += x[k * stride];
  m = n ? m / n : NAN;
  for (PetscInt k = 0; k < n; k++)
    q += (x[k * stride] - m) * (x[k * stride] - m);
  *mean = m;
  *std = n > 1 ? sqrt(q / (n - 1)) : (n == 1 ? 0 : NAN);
}

/* End of the run: summary (time-averaged displacement and per-cycle peak
 * stress with standard deviations, peak inlet velocities, crossings). */
static PetscErrorCode vein_metrics_finish(diagnostic *self, sim *s) {
  vein_metrics *v = self->data;
  const double T = v->lay.period_T;
  double disp_mean, disp_std, peak_mean = NAN, peak_std = NAN, *peaks;
  PetscInt n_cycles = 0;
  PetscFunctionBeginUser;
  vein_mean_std(v->n_hist ? &v->hist[0][2] : NULL, v->n_hist, 3, &disp_mean, &disp_std);
  /* the peak of the probe's stress in every whole cycle it was followed through */
  PetscCall(PetscMalloc1(vein_cycle_peaks_max(T, s->t) + 1, &peaks));
  n_cycles = vein_cycle_peaks((const double(*)[3])v->hist, v->n_hist, T, s->t, peaks);
  if (n_cycles)
    vein_mean_std(peaks, n_cycles, 1, &peak_mean, &peak_std);
  PetscCall(PetscFree(peaks));
  PetscCall(PetscPrintf(
      s->comm,
      "vein: peak inlet velocity (station x = 0) mean %.4g m/s, centreline %.4g m/s over the first "
      "cycle (%.4g, %.4g m/s over the run); flux mean %.4g m/s (%.4g m/s over the run)\n",
      v->u_mean_peak1, v->u_centre_peak1, v->u_mean_peak, v->u_centre_peak, v->u_flux_peak1,
      v->u_flux_peak));
  PetscCall(PetscPrintf(
      s->comm,
      "vein: gap between the tips %.4g .. %.4g m (rest %.4g m); crossings %" PetscInt64_FMT
      "; max |rho/rho0 - 1| %.3g, max Mach %.3g\n",
      v->gap_min, v->gap_max, v->lay.rest_gap, v->crossings, v->rho_dev_max, v->mach_max));
  if (v->probe_gid >= 0) {
    char peak_s[64] = "n/a: no whole cycle after the point was chosen";
    if (n_cycles)
      PetscCall(PetscSNPrintf(peak_s, sizeof(peak_s), "%.4g +- %.3g Pa", peak_mean, peak_std));
    PetscCall(PetscPrintf(s->comm,
                          "vein: measurement point gid %" PetscInt64_FMT
                          ": displacement %.4g +- %.3g m (time average, "
                          "%" PetscInt_FMT " rows), peak stress per cycle %s (%" PetscInt_FMT
                          " cycles)\n",
                          v->probe_gid, disp_mean, disp_std, v->n_hist, peak_s, n_cycles));
  }
  if (s->rank == 0) {
    char path[PETSC_MAX_PATH_LEN];
    whole_file w;
    PetscCall(io_output_path(s, "vein-summary.csv", path, sizeof(path)));
    PetscCall(whole_file_open(&w, path, NULL));
    FILE *f = w.f;
    char a[32], b[32], c[32], d[32];
    vein_csv_real(a, sizeof(a), v->n_hist > 0, disp_mean);
    vein_csv_real(b, sizeof(b), v->n_hist > 0, disp_std);
    vein_csv_real(c, sizeof(c), n_cycles > 0, peak_mean);
    vein_csv_real(d, sizeof(d), n_cycles > 0, peak_std);
    int ok = fprintf(f,
                     "key,value\nleaflet_length,%.6g\ng0,%.6g\nka_ref,%.6g\nperiod,%.6g\ndx,%."
                     "6g\nnu,%.6g\nt_end,%.8g\n"
                     "u_mean_peak_cycle1,%.6g\nu_centre_peak_cycle1,%.6g\nu_mean_peak,%.6g\nu_"
                     "centre_peak,%.6g\nu_flux_peak_cycle1,%.6g\nu_flux_peak,%.6g\n"
                     "gap_rest,%.6g\ngap_min,%.6g\ngap_max,%.6g\ncrossings,%" PetscInt64_FMT
                     "\nrho_dev_max,%.6g\n"
                     "mach_max,%.6g\nprobe_gid,%" PetscInt64_FMT
                     "\ndisp_mean,%s\ndisp_std,%s\npeak_stress_mean,%s\n"
                     "peak_stress_std,%s\nn_cycles,%" PetscInt_FMT "\n",
                     v->lay.leaflet_length, v->lay.g0, v->lay.ka_ref, T, v->lay.dx,
                     sph_params_get(s)->nu, s->t, v->u_mean_peak1, v->u_centre_peak1,
                     v->u_mean_peak, v->u_centre_peak, v->u_flux_peak1, v->u_flux_peak,
                     v->lay.rest_gap, v->gap_min, v->gap_max, v->crossings, v->rho_dev_max,
                     v->mach_max, v->probe_gid, a, b, c, d, n_cycles) > 0;
    PetscCall(whole_file_commit(&w, ok, NULL));
  }
  if (v->csv)
    fclose(v->csv);
  if (v->sinus)
    fclose(v->sinus);
  v->csv = v->sinus = NULL;
  PetscFunctionReturn(0);
}

static PetscErrorCode vein_metrics_checkpoint_write(diagnostic *self, sim *s, checkpoint_io *io) {
  vein_metrics *v = self->data;
  const PetscInt64 ints[4] = {v->crossings, v->probe_gid, v->next_cycle, v->n_hist};
  const double reals[10] = {v->u_mean_peak1, v->u_centre_peak1, v->u_mean_peak, v->u_centre_peak,
                            v->gap_min,      v->gap_max,        v->rho_dev_max, v->mach_max,
                            v->u_flux_peak1, v->u_flux_peak};
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(checkpoint_put_ints(io, "vein_ints", ints, 4));
  PetscCall(checkpoint_put_reals(io, "vein_reals", reals, 10));
  if (v->n_hist) {
    PetscCall(checkpoint_put_reals(io, "vein_hist", &v->hist[0][0], 3 * v->n_hist));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode vein_metrics_checkpoint_read(diagnostic *self, sim *s, checkpoint_io *io) {
  vein_metrics *v = self->data;
  PetscInt64 ints[4];
  double reals[10];
  PetscFunctionBeginUser;
  PetscCall(checkpoint_get_ints(io, "vein_ints", ints, 4));
  PetscCall(checkpoint_get_reals(io, "vein_reals", reals, 10));
  (void)s;
  v->crossings = ints[0]; /* at the last output (the count itself is "vein_crossings") */
  v->probe_gid = ints[1];
  v->next_cycle = (PetscInt)ints[2];
  const PetscInt n = (PetscInt)ints[3];
  v->u_mean_peak1 = reals[0];
  v->u_centre_peak1 = reals[1];
  v->u_mean_peak = reals[2];
  v->u_centre_peak = reals[3];
  v->gap_min = reals[4];
  v->gap_max = reals[5];
  v->rho_dev_max = reals[6];
  v->mach_max = reals[7];
  v->u_flux_peak1 = reals[8];
  v->u_flux_peak = reals[9];
  PetscCall(PetscFree(v->hist));
  v->n_hist = v->cap_hist = n;
  if (n) {
    PetscCall(PetscMalloc1(n, &v->hist));
    PetscCall(checkpoint_get_reals(io, "vein_hist", &v->hist[0][0], 3 * n));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode vein_metrics_destroy(diagnostic *self) {
  vein_metrics *v = self->data;
  PetscFunctionBeginUser;
  if (v->csv)
    fclose(v->csv);
  if (v->sinus)
    fclose(v->sinus);
  PetscCall(vein_leaflets_destroy(&v->leaves));
  PetscCall(PetscFree(v->hist));
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode vein_metrics_register(sim *s, const vein_layout *lay, const diagnostic *crossings) {
  diagnostic *d;
  vein_metrics *v;
  PetscFunctionBeginUser;
  PetscCall(diagnostic_create("vein", &d));
  PetscCall(PetscNew(&v));
  d->data = v;
  v->lay = *lay;
  PetscCall(vein_leaflets_create(lay, &v->leaves));
  v->crossings_check = crossings;
  v->probe_gid = -1;
  v->gap_min = INFINITY;
  v->gap_max = -INFINITY;
  d->output = "vein.csv, vein-sinus.csv, vein-summary.csv";
  d->when.at_outputs = PETSC_TRUE;
  d->sample = vein_metrics_sample;
  d->finish = vein_metrics_finish;
  d->destroy = vein_metrics_destroy;
  d->checkpoint_write = vein_metrics_checkpoint_write;
  d->checkpoint_read = vein_metrics_checkpoint_read;
  PetscCall(diagnostics_add(s, d));
  PetscFunctionReturn(0);
}
