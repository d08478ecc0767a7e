/* Scene vein: a deep-vein valve (the thesis's chapter 4). A 2D channel of
 * width W, periodic in x over -vein_length, with a valve chamber (sinus)
 * where both walls bulge outward over -vein_sinus_length to the diameter D,
 * and two symmetric flexible leaflets that root at the upstream end of the
 * sinus and point downstream toward the axis, so that the reverse flow
 * closes the valve. The liquid is driven by g0 sin(2 pi t/T) on every fluid
 * particle (module body_force).
 *
 * Geometry (x along the channel, y = 0 on its axis):
 *   wall surface  y = +-Y(x),  Y = W/2 + B sqrt(1 - ((x - x_c)/A)^2) over the
 *                 sinus |x - x_c| < A = sinus_length/2 (half-ellipses of
 *                 semi-axes A along x and B = (D - W)/2 across), W/2 elsewhere;
 *   liquid        the lattice (i + 1/2, j + 1/2) dx inside, at least dx/2 from
 *                 the surface;
 *   walls         -vein_wall_layers layers: lattice points outside, between
 *                 0.45 dx and (layers + 0.45) dx from the surface (on a
 *                 straight wall exactly the layers at dx/2, 3dx/2, ...). Along
 *                 the sinus's curve this leaves about one lattice row empty
 *                 (liquid and walls 2 dx apart); walls reaching the surface,
 *                 or the liquid, made the liquid's mean pressure grow until
 *                 the flow stopped (doc/validation.md, "Vein");
 *   leaflets      two-layer mass-spring strips (solid_strip.h) of
 *                 round(L/dx) free columns, whose mid-plane starts at the
 *                 root (x_c - A, +-W/2) at the angle theta to the axis, with
 *                 sin(theta) = (W/2 - gap/2)/L (-vein_leaflet_gap: the tips'
 *                 rest distance at dx = 1e-4 m, below) unless
 *                 -vein_leaflet_angle gives theta; one
 *                 clamped column (fixed particles) at the root. Liquid and wall
 *                 lattice points closer than dx to a leaflet particle are left
 *                 out (no repulsion at t = 0).
 * Resolution: every length and mass follows -vein_dx from the published
 * dx_ref = 1e-4 m so that a coarse run is the same valve: h = 2.5 dx, masses
 * ~ dx^2, repulsion r* = dx and K ~ dx^2 (repulsion balances pressure x dx),
 * bonds r0 = dx and K ~ dx^-3, angles k_a ~ dx^-1 (both keep the leaflet's
 * bending stiffness EI = K r0^3 + 2 k_a r0, doc/theory.md). A leaflet is two
 * layers, 2 dx thick: the tips' rest distance grows by 2 (dx - dx_ref) so that
 * the clear opening between their faces is the published one at every dx (at
 * dx = 4e-4 m a 1 mm gap left 0.2 mm, and the valve opened 0.3 s later than
 * at 2e-4 m). -bond_k, -angle_k, -repulsion_k given explicitly are used as
 * they are.
 * Diagnostics: "vein_crossings" and "vein" (vein_metrics.h). */
#include <math.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/sph.h"
#include "dmhs/modules.h"
#include "dmhs/neighbours.h"
#include "dmhs/scenes.h"
#include "dmhs/fields.h"
#include "dmhs/bond.h"
#include "dmhs/angle_harmonic.h"
#include "dmhs/repulsion.h"
#include "dmhs/body_force.h"
#include "dmhs/stress.h"
#include "vein_metrics.h"
#include "dmhs/solid_load.h"
#include "dmhs/agglomeration.h"
#include "dmhs/extreme.h"
#include "scenes/solid_strip.h"

#define VEIN_DX_REF 1e-4 /* the published resolution [m] */

typedef struct {
  double dx, width, diameter, sinus_length, length;
  double leaflet_length, leaflet_gap, leaflet_angle_deg, ka_ref;
  double fluid_mass_ref, solid_mass_ref;
  PetscInt wall_layers, crossing_interval;
  double probe_time;
  PetscBool clots;  /* -vein_clots: module agglomeration */
  PetscBool hinged; /* -vein_leaflet_root hinged: the leaflets turn freely at the root */
  module *body, *rep, *agg;
  vein_layout lay;
} vein_data;

/* The extreme (largest when sign = +1, smallest when -1) of value[] over the
 * owned liquid particles that started in the sinus, over all ranks (ties: the
 * lower gid), skipping gid `skip`; -1 when there is none. */
static PetscErrorCode vein_extreme_sinus(sim *s, const double *value, int sign, PetscInt64 skip,
                                         PetscInt64 *gid) {
  extreme_value mine = EXTREME_NONE, best;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < s->ps.n_owned; i++) {
    if (s->ps.type[i] != PTYPE_FLUID || s->ps.tracer[i] != VEIN_TRACER_SINUS ||
        s->ps.gid[i] == skip)
      continue;
    extreme_consider(&mine, sign * value[i], s->ps.gid[i]);
  }
  PetscCall(extreme_max(s->comm, mine, &best));
  *gid = best.gid;
  PetscFunctionReturn(0);
}

/* The thesis's two seeds after the warm-up: P1, the sinus-side liquid
 * particle of peak total stress |sigma|; P2, the one of longest residence,
 * the smallest displacement |x - x0| among those that started between
 * leaflet and wall. */
static PetscErrorCode vein_choose_seeds(sim *s, void *ctx, PetscInt *n, PetscInt64 gids[]) {
  PetscFunctionBeginUser;
  (void)ctx;
  /* current neighbour values (ghosts are refreshed only at the next step's
   * start): the stresses, hence the seeds, are then the same on any rank count */
  PetscCall(neighbours_refresh_ghosts(s));
  PetscCall(stress_compute(s));
  PetscCall(vein_extreme_sinus(s, s->ps.stress_mag, +1, -1, &gids[0]));
  PetscCall(vein_extreme_sinus(s, s->ps.displacement, -1, gids[0], &gids[1]));
  PetscCheck(
      gids[0] >= 0 && gids[1] >= 0, s->comm, PETSC_ERR_ARG_WRONG,
      "vein: no liquid left in the sinus to seed clots (give -agglomeration_seeds x1,y1,...)");
  *n = 2;
  PetscFunctionReturn(0);
}

static PetscErrorCode vein_set_from_options(scene *self, sim *s) {
  vein_data *v = self->data;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Scene vein (deep-vein valve with two flexible leaflets)", NULL);
  PetscCall(options_read_real("-vein_dx",
                              "Particle spacing dx [m] (lengths and masses scale from dx = 1e-4 m)",
                              NULL, v->dx, &v->dx, NULL));
  PetscCall(
      options_read_real("-vein_width", "Channel width W [m]", NULL, v->width, &v->width, NULL));
  PetscCall(options_read_real("-vein_sinus_diameter", "Sinus (valve chamber) diameter D [m]", NULL,
                              v->diameter, &v->diameter, NULL));
  PetscCall(options_read_real("-vein_sinus_length", "Sinus length along x [m]", NULL,
                              v->sinus_length, &v->sinus_length, NULL));
  PetscCall(options_read_real("-vein_length", "Periodic length of the channel [m]", NULL, v->length,
                              &v->length, NULL));
  PetscCall(options_read_real("-vein_leaflet_length",
                              "Leaflet length L [m] (0.0256, 0.0175, 0.01 in the study)", NULL,
                              v->leaflet_length, &v->leaflet_length, NULL));
  PetscCall(options_read_real("-vein_leaflet_gap",
                              "Rest distance between the two leaflet tips at dx = 1e-4 m [m] (plus "
                              "2 (dx - 1e-4 m): the same clear opening at every dx)",
                              NULL, v->leaflet_gap, &v->leaflet_gap, NULL));
  PetscCall(options_read_real("-vein_leaflet_angle",
                              "Leaflet root angle to the axis [deg] (0 = from -vein_leaflet_gap)",
                              NULL, v->leaflet_angle_deg, &v->leaflet_angle_deg, NULL));
  {
    const char *const roots[] = {"clamped", "hinged", "vein_leaflet_root", "VEIN_ROOT_", NULL};
    PetscEnum root = v->hinged ? 1 : 0;
    PetscCall(options_read_enum("-vein_leaflet_root",
                                "Leaflet root: clamped (its direction held by the angles) or "
                                "hinged (free to turn about its sinus-side particle)",
                                NULL, roots, root, &root, NULL));
    v->hinged = root == 1 ? PETSC_TRUE : PETSC_FALSE;
  }
  PetscCall(options_read_real(
      "-vein_leaflet_ka",
      "Leaflet angle stiffness k_a at dx = 1e-4 m [J] (scaled by 1e-4/dx; -angle_k sets it "
      "directly)",
      NULL, v->ka_ref, &v->ka_ref, NULL));
  PetscCall(options_read_real("-vein_fluid_mass",
                              "Fluid particle mass at dx = 1e-4 m [kg] (scaled by dx^2)", NULL,
                              v->fluid_mass_ref, &v->fluid_mass_ref, NULL));
  PetscCall(options_read_real("-vein_solid_mass",
                              "Wall and leaflet particle mass at dx = 1e-4 m [kg] (scaled by dx^2)",
                              NULL, v->solid_mass_ref, &v->solid_mass_ref, NULL));
  PetscCall(options_read_int("-vein_wall_layers", "Wall particle layers [1]", NULL, v->wall_layers,
                             &v->wall_layers, NULL));
  PetscCall(options_read_int("-vein_crossing_interval",
                             "Steps between checks that no liquid crosses a leaflet [1]", NULL,
                             v->crossing_interval, &v->crossing_interval, NULL));
  PetscCall(options_read_real(
      "-vein_probe_time",
      "Time at which the measurement point (peak stress, sinus side) is chosen [s] "
      "(0 = a quarter period, the forward peak)",
      NULL, v->probe_time, &v->probe_time, NULL));
  PetscCall(options_read_bool(
      "-vein_clots",
      "Grow clots from seed particles (module agglomeration, -agglomeration_*; seeds by "
      "default P1, the sinus-side peak stress, and P2, the longest residence)",
      NULL, v->clots, &v->clots, NULL));
  PetscOptionsEnd();
  PetscCheck(v->dx > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE, "-vein_dx must be > 0 m (got %g)",
             v->dx);
  PetscCheck(v->width > 10 * v->dx, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-vein_width must be > %g m (10 -vein_dx; got %g)", 10 * v->dx, v->width);
  PetscCheck(v->diameter >= v->width, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-vein_sinus_diameter (%g m) must be >= -vein_width (%g m)", v->diameter, v->width);
  PetscCheck(
      v->sinus_length > 4 * v->dx && v->length > v->sinus_length + 10 * v->dx, s->comm,
      PETSC_ERR_ARG_OUTOFRANGE,
      "-vein_length (%g m) must exceed -vein_sinus_length (%g m) by 10 dx, and the sinus 4 dx",
      v->length, v->sinus_length);
  PetscCheck(v->leaflet_length >= 3 * v->dx && v->leaflet_length < v->sinus_length, s->comm,
             PETSC_ERR_ARG_OUTOFRANGE,
             "-vein_leaflet_length must lie in [3 dx, sinus length) (got %g m)", v->leaflet_length);
  PetscCheck(v->leaflet_gap >= 0 && v->leaflet_gap < v->width, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-vein_leaflet_gap must lie in [0, W) (got %g m)", v->leaflet_gap);
  PetscCheck(v->leaflet_angle_deg >= 0 && v->leaflet_angle_deg < 90, s->comm,
             PETSC_ERR_ARG_OUTOFRANGE, "-vein_leaflet_angle must lie in [0, 90) deg (got %g)",
             v->leaflet_angle_deg);
  PetscCheck(v->ka_ref >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-vein_leaflet_ka must be >= 0 J (got %g)", v->ka_ref);
  PetscCheck(v->fluid_mass_ref > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-vein_fluid_mass must be > 0 kg (got %g)", v->fluid_mass_ref);
  PetscCheck(v->solid_mass_ref > 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-vein_solid_mass must be > 0 kg (got %g)", v->solid_mass_ref);
  PetscCheck(v->wall_layers >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-vein_wall_layers must be >= 1 (got %" PetscInt_FMT ")", v->wall_layers);
  PetscCheck(v->crossing_interval >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-vein_crossing_interval must be >= 1 step (got %" PetscInt_FMT ")",
             v->crossing_interval);
  PetscCheck(v->probe_time >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-vein_probe_time must be >= 0 s (got %g)", v->probe_time);
  const double r = v->dx / VEIN_DX_REF;
  s->dx = v->dx;
  /* the thesis's blood (Lucy, h = 2.5 dx, c0 = 10 m/s, rho0 = 1056 kg/m^3, Tait,
   * continuity); its viscosity is not stated: blood's nu = 3.3e-6 m^2/s
   * (doc/validation.md, "Vein: peak inlet velocity", judges the choice) */
  module *sph;
  PetscCall(modules_enable(s, "sph", &sph));
  sph_params *sp = sph_defaults(sph);
  PetscCall(sph_set_liquid(sph, 2.5 * v->dx, 1056.0, 10.0, 3.3e-6)); /* h, rho0, c0, nu */
  /* at this low viscosity (cell Reynolds number c0 h/nu ~ 10^3) the continuity
   * density keeps acoustic noise that grows until the run blows up (measured:
   * a plain channel at rest, dt = 0.47 of the sound-speed limit, at t ~ 0.08 s);
   * delta-SPH diffusion damps it without adding shear viscosity (doc/theory.md) */
  sp->delta = 0.1;
  /* a liquid particle drawn into the gap between the sinus's curved wall and the
   * liquid (the lattice row left empty there) keeps one or two liquid
   * neighbours among eight walls: it rings against the walls' pressure (omega
   * ~ 2e4 rad/s at dx = 5e-4 m) without
   * the diffusion above, which does not act on wall pairs, and the half-step
   * density of the kick amplifies that at omega^2 dt/4 (measured at dt = 4e-6 s:
   * |rho/rho0 - 1| 6.5 % at t = 0.17 s, a pressure pulse that moved the tips by
   * 5 % of their range); the density predicted for the end of the step does not
   * (doc/stability.md, "Vein") */
  sp->density_predict = PETSC_TRUE;
  /* behind the valve the jet's shear brings liquid particles together faster
   * than the blood's viscosity resolves at these spacings (pairs at 0.12 dx and
   * +-1e4 Pa spikes measured at dx = 5e-4 m); a weak Monaghan viscosity stops
   * it. Its effective viscosity alpha c0 h/8 grows with h: alpha falls as 1/dx
   * so that it stays 3e-6 m^2/s at every dx, as at the published dx = 1e-4 m
   * with alpha = 0.01 (a fixed alpha took 20 % off the peak inlet velocity at
   * dx = 4e-4 m, where it is 4x stronger: doc/validation.md, "Vein") */
  sp->av_alpha = 0.01 / r;
  PetscCall(fields_enable("body"));
  PetscCall(fields_enable("side"));
  PetscCall(fields_enable("tracer")); /* the liquid that starts in the sinus */
  PetscCall(stress_enable());
  PetscCall(modules_enable(s, "body_force", &v->body));
  PetscCall(body_force_set_default(v->body, 0.1, 0.0));
  PetscCall(body_force_set_default_period(v->body, 4.0));
  PetscCall(solid_modules_enable(s, BOND_HARMONIC));
  PetscCall(bond_set_default(s, 1e6 / (r * r * r), v->dx, 0.5 * v->dx));
  PetscCall(angle_set_default(s, v->ka_ref / r, 90.0));
  PetscCall(modules_enable(s, "repulsion", &v->rep));
  PetscCall(repulsion_set_default(v->rep, 4e-4 * r * r, v->dx, 4, 2));
  PetscCall(repulsion_set_bodies(v->rep, PETSC_TRUE));
  if (v->clots) {
    PetscCall(modules_enable(s, "agglomeration", &v->agg));
    /* R_max = 2.5e-4 m at the published dx, like every length of the scene */
    PetscCall(agglomeration_set_defaults(v->agg, 2.5 * v->dx, -1));
    PetscCall(agglomeration_set_seed_chooser(v->agg, vein_choose_seeds, v));
  }
  PetscFunctionReturn(0);
}

/* The upper wall's surface as a polyline with points at most dx/8 apart,
 * sorted by x over [0, length): straight, the half-ellipse, straight. */
typedef struct {
  PetscInt n;
  double (*p)[2];
} vein_surface;

static double vein_surface_y(const vein_data *v, double xc, double x) {
  const double A = 0.5 * v->sinus_length, B = 0.5 * (v->diameter - v->width), u = (x - xc) / A;
  return 0.5 * v->width + (fabs(u) < 1 ? B * sqrt(1 - u * u) : 0.0);
}

static PetscErrorCode vein_surface_build(const vein_data *v, double xc, vein_surface *sf) {
  const double A = 0.5 * v->sinus_length, B = 0.5 * (v->diameter - v->width), step = v->dx / 8;
  const PetscInt n_line = (PetscInt)ceil((v->length - 2 * A) / step) + 2;
  const PetscInt n_arc = (PetscInt)ceil(M_PI * PetscMax(A, B) / step) + 2;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n_line + n_arc + 4, &sf->p));
  sf->n = 0;
  for (double x = 0; x < xc - A; x += step) {
    sf->p[sf->n][0] = x;
    sf->p[sf->n++][1] = 0.5 * v->width;
  }
  for (PetscInt k = 0; k <= n_arc; k++) { /* x = xc - A cos(phi) rises with phi */
    const double phi = M_PI * k / n_arc;
    sf->p[sf->n][0] = xc - A * cos(phi);
    sf->p[sf->n++][1] = 0.5 * v->width + B * sin(phi);
  }
  for (double x = xc + A + step; x < v->length; x += step) {
    sf->p[sf->n][0] = x;
    sf->p[sf->n++][1] = 0.5 * v->width;
  }
  PetscCheck(sf->n <= n_line + n_arc + 4, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "vein: surface samples overflow");
  PetscFunctionReturn(0);
}

/* Distance from (x, |y|) to the upper surface (periodic in x), within 4 dx + layers. */
static double vein_surface_distance(const vein_data *v, const vein_surface *sf, double x, double y,
                                    double reach) {
  double best = INFINITY;
  for (int image = -1; image <= 1; image++) {
    const double xs = x + image * v->length;
    /* first sample with p.x >= xs - reach (samples sorted by x) */
    PetscInt lo = 0, hi = sf->n;
    while (lo < hi) {
      const PetscInt mid = (lo + hi) / 2;
      if (sf->p[mid][0] < xs - reach)
        lo = mid + 1;
      else
        hi = mid;
    }
    for (PetscInt k = lo; k < sf->n && sf->p[k][0] <= xs + reach; k++)
      best = PetscMin(best, hypot(sf->p[k][0] - xs, sf->p[k][1] - y));
  }
  return best;
}

/* Leaflet strips: upper (sign +1) and lower (-1), mirror images. */
static void vein_leaflet_strip(const vein_data *v, double x_root, double theta, int sign,
                               double mass, double rho, solid_strip *st) {
  const double c = cos(theta), sn = sin(theta);
  st->n = 1 + (PetscInt)floor(v->leaflet_length / v->dx + 0.5);
  st->n_clamp = 1;
  st->hinged = v->hinged;
  st->along[0] = c;
  st->along[1] = -sign * sn;
  /* layer 0 faces the sinus, layer 1 the axis */
  st->across[0] = -sn;
  st->across[1] = -sign * c;
  st->origin[0] = x_root - 0.5 * v->dx * st->across[0];
  st->origin[1] = sign * 0.5 * v->width - 0.5 * v->dx * st->across[1];
  st->spacing = v->dx;
  st->mass = mass;
  st->rho = rho;
}

static PetscBool vein_near_strips(const solid_strip st[2], double x, double y, double dmin) {
  for (int k = 0; k < 2; k++) {
    /* bounding box of the strip, widened by dmin */
    const double ex =
        st[k].spacing * (st[k].n * fabs(st[k].along[0]) + fabs(st[k].across[0])) + dmin;
    const double ey =
        st[k].spacing * (st[k].n * fabs(st[k].along[1]) + fabs(st[k].across[1])) + dmin;
    const double cx =
        st[k].origin[0] + 0.5 * st[k].spacing * (st[k].n * st[k].along[0] + st[k].across[0]);
    const double cy =
        st[k].origin[1] + 0.5 * st[k].spacing * (st[k].n * st[k].along[1] + st[k].across[1]);
    if (fabs(x - cx) > 0.5 * ex + dmin || fabs(y - cy) > 0.5 * ey + dmin)
      continue;
    for (PetscInt c = 0; c < st[k].n; c++)
      for (int l = 0; l < 2; l++) {
        const double px =
            st[k].origin[0] + st[k].spacing * (c * st[k].along[0] + l * st[k].across[0]);
        const double py =
            st[k].origin[1] + st[k].spacing * (c * st[k].along[1] + l * st[k].across[1]);
        if (fabs(px - x) < dmin && fabs(py - y) < dmin && hypot(px - x, py - y) < dmin)
          return PETSC_TRUE;
      }
  }
  return PETSC_FALSE;
}

static PetscErrorCode vein_build(scene *self, sim *s) {
  const sph_params *sp = sph_params_get(s);
  vein_data *v = self->data;
  const double dx = v->dx, r = dx / VEIN_DX_REF, zero[2] = {0, 0};
  const double m_fluid = v->fluid_mass_ref * r * r, m_solid = v->solid_mass_ref * r * r;
  const double A = 0.5 * v->sinus_length, B = 0.5 * (v->diameter - v->width);
  const double xc = 0.5 * v->length, x_root = xc - A;
  const PetscInt nx = (PetscInt)floor(v->length / dx + 0.5);
  const double reach = (v->wall_layers + 1.5) * dx, ymax = 0.5 * v->width + B + reach;
  const PetscInt ny = (PetscInt)ceil(ymax / dx);
  vein_surface sf;
  solid_strip st[2];
  PetscInt64 gid = 0;
  double F[2], T;
  PetscFunctionBeginUser;
  PetscCheck(fabs(nx * dx - v->length) < 1e-6 * dx, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-vein_length (%g m) must be a whole number of -vein_dx (%g m)", v->length, dx);
  const PetscInt n_free = (PetscInt)floor(v->leaflet_length / dx + 0.5);
  double theta = v->leaflet_angle_deg * M_PI / 180.0;
  if (v->leaflet_angle_deg == 0) {
    const double gap = v->leaflet_gap + 2 * (dx - VEIN_DX_REF);
    const double sn = (0.5 * v->width - 0.5 * gap) / (n_free * dx);
    PetscCheck(gap >= 0 && sn > 0 && sn < 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
               "vein: a leaflet of %g m cannot leave a gap of %g m (-vein_leaflet_gap %g m at dx "
               "= 1e-4 m) in a channel of %g m (set -vein_leaflet_angle)",
               v->leaflet_length, gap, v->leaflet_gap, v->width);
    theta = asin(sn);
  }
  s->dom.lo[0] = 0;
  s->dom.hi[0] = nx * dx;
  s->dom.periodic[0] = PETSC_TRUE;
  s->dom.lo[1] = -(ny + 2) * dx;
  s->dom.hi[1] = (ny + 2) * dx;
  s->dom.periodic[1] = PETSC_FALSE;
  vein_leaflet_strip(v, x_root, theta, +1, m_solid, sp->rho0, &st[0]);
  vein_leaflet_strip(v, x_root, theta, -1, m_solid, sp->rho0, &st[1]);
  PetscCall(vein_surface_build(v, xc, &sf));

  /* liquid first (gids 0 .. n_fluid - 1), then walls, then the leaflets */
  const double x_tip = x_root + n_free * dx * cos(theta);
  PetscInt64 n_sinus = 0;
  for (int pass = 0; pass < 2; pass++)
    for (PetscInt i = 0; i < nx; i++)
      for (PetscInt j = -ny; j < ny; j++) {
        const double x[2] = {(i + 0.5) * dx, (j + 0.5) * dx}, ay = fabs(x[1]);
        const double Y = vein_surface_y(v, xc, x[0]);
        const PetscBool inside = ay < Y ? PETSC_TRUE : PETSC_FALSE;
        if (pass == 0 && !inside)
          continue;
        if (pass == 1 && (inside || ay > Y + reach))
          continue;
        /* far inside: no need to measure (the surface's slope is finite there) */
        const double d = inside && Y - ay > 2 * dx && fabs(fabs(x[0] - xc) - A) > 2 * dx
                             ? INFINITY
                             : vein_surface_distance(v, &sf, x[0], ay, reach);
        if (pass == 0 && d < 0.5 * dx - 1e-9 * dx)
          continue;
        if (pass == 1 && (d < 0.45 * dx || d >= (v->wall_layers + 0.45) * dx))
          continue;
        if (vein_near_strips(st, x[0], x[1], dx * (1 - 1e-9)))
          continue;
        PetscInt idx;
        PetscCall(particles_add_owned(&s->ps, gid++, pass == 0 ? PTYPE_FLUID : PTYPE_WALL, x, zero,
                                      pass == 0 ? m_fluid : m_solid, sp->rho0, &idx));
        if (pass == 0 && x[0] > x_root && x[0] < xc + A) {
          /* between a leaflet's mid-plane (or the channel line past the tip) and the sinus wall */
          const double y_leaf =
              x[0] < x_tip ? 0.5 * v->width - (x[0] - x_root) * tan(theta) : 0.5 * v->width;
          if (ay > y_leaf) {
            s->ps.tracer[idx] = VEIN_TRACER_SINUS;
            n_sinus++;
          }
        }
      }
  const PetscInt64 n_fluid = particles_count_type(&s->ps, PTYPE_FLUID);
  const PetscInt64 n_wall = gid - n_fluid;
  PetscCall(PetscFree(sf.p));
  for (int k = 0; k < 2; k++) {
    const PetscInt first = s->ps.n_owned;
    PetscCall(solid_strip_build(s, &st[k], &gid));
    for (PetscInt i = first; i < s->ps.n_owned; i++) {
      s->ps.body[i] = k + 1;
    }
    v->lay.leaflet[k].first_gid = st[k].first_gid;
    v->lay.leaflet[k].n_columns = st[k].n;
    v->lay.leaflet[k].sinus_layer = 0;
  }
  const int n_fixed = v->hinged ? 2 : 4; /* a hinge fixes one particle of the root column */
  const PetscInt64 n_leaflet = 4 * n_free + 4 - n_fixed;
  PetscCall(
      PetscPrintf(s->comm,
                  "vein: period %g m, sinus %g m long at x = [%g, %g] m (half-ellipses, D = %g m), "
                  "W = %g m, dx = %g m\n",
                  v->length, v->sinus_length, x_root, xc + A, v->diameter, v->width, dx));
  PetscCall(PetscPrintf(s->comm,
                        "vein: particles fluid %" PetscInt64_FMT " (%" PetscInt64_FMT
                        " in the sinus), wall %" PetscInt64_FMT " (%" PetscInt_FMT
                        " layers, %d of them leaflet %s), leaflet %" PetscInt64_FMT
                        " (2 x 2 x %" PetscInt_FMT "%s)\n",
                        n_fluid, n_sinus, n_wall + n_fixed, v->wall_layers, n_fixed,
                        v->hinged ? "hinge pivots" : "clamps", n_leaflet, n_free,
                        v->hinged ? " + 2 at the hinges" : ""));
  PetscCall(PetscPrintf(s->comm,
                        "vein: leaflets of %g m at %.3f deg to the axis, rooted at x = %g m; tips "
                        "%g m apart at rest\n",
                        n_free * dx, theta * 180.0 / M_PI, x_root,
                        2 * (0.5 * v->width - n_free * dx * sin(theta))));

  /* the diagnostics, with what they need of the geometry */
  PetscCall(body_force_get(v->body, F, &T));
  v->lay.dx = dx;
  v->lay.width = v->width;
  v->lay.period_T = T;
  v->lay.x_station = 0.5 * dx; /* x = 0: the middle of the straight part (periodic) */
  v->lay.x_sinus0 = x_root;
  v->lay.sinus_length = v->sinus_length;
  v->lay.rest_gap = 2 * (0.5 * v->width - n_free * dx * sin(theta));
  v->lay.crossing_interval = v->crossing_interval;
  v->lay.probe_time = v->probe_time > 0 ? v->probe_time : (T > 0 ? 0.25 * T : 0.0);
  v->lay.leaflet_length = n_free * dx;
  v->lay.g0 = F[0];
  v->lay.ka_ref = v->ka_ref;
  diagnostic *crossings;
  PetscCall(vein_crossings_register(s, &v->lay, &crossings));
  PetscCall(vein_metrics_register(s, &v->lay, crossings));
  PetscFunctionReturn(0);
}

static PetscErrorCode vein_destroy(scene *self) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode vein_scene_create(scene **out) {
  vein_data *v;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(out));
  PetscCall(PetscNew(&v));
  /* the reference case, run 1 of the study (doc/cases.md) */
  v->dx = VEIN_DX_REF;
  v->width = 0.008;
  v->diameter = 0.014;
  v->sinus_length = 0.04;
  v->length = 0.09;
  v->leaflet_length = 0.0256;
  v->leaflet_gap = 1e-3;
  v->ka_ref = 0.01;
  v->fluid_mass_ref = 1.05e-5;
  v->solid_mass_ref = 2e-5;
  v->wall_layers = 3;
  v->crossing_interval = 10;
  (*out)->name = "vein";
  (*out)->set_from_options = vein_set_from_options;
  (*out)->build = vein_build;
  (*out)->destroy = vein_destroy;
  (*out)->data = v;
  PetscFunctionReturn(0);
}
