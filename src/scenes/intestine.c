/* Scene intestine: the Dynamic Colon Model, a 2D channel of N + 1
 * pockets (haustra) of length b on a lower membrane only, partly filled with
 * liquid, squeezed by a peristaltic wave (module peristalsis).
 *
 * Geometry (x along the colon, y up; pocket k spans [k b, (k+1) b], so the
 * published centre x_k = k b is measured from -b/2 here):
 *   membrane: 3 layers (-intestine_membrane_layers) of bonded MSM + SPH
 *     particles; the top layer follows the haustral profile
 *       y_s(x) = -A sin^2(pi x / b)   (A = -intestine_amplitude),
 *     columns spaced r0 = dx along the middle layer's arc, the other layers
 *     offset by r0 along its normal; the first and last -intestine_clamp
 *     columns are fixed (wall particles): the membrane cannot drift;
 *   liquid: the lattice (i + 1/2) dx above the membrane up to the level y = L
 *     (-intestine_level, above the folds y = 0, where pockets meet);
 *   a wall closes the left end (x < 0), up to L + -intestine_wall_height;
 *   a weir closes the right end (x > (N+1) b) up to y = -intestine_weir
 *     (default L): liquid that rises over it passes x = (N+1) b and counts as
 *     pocket N + 1; beyond the weir it is parked (turned into a fixed,
 *     isolated particle in a parking lot right of the channel, one slot per
 *     fluid gid), never lost: "overflow" in the CSV and the final report.
 * Tracked sets: the liquid initially in pocket 0 ("white", tracer 1) and, with
 * -intestine_red, in pocket -intestine_red_pocket ("red", tracer 2).
 *
 * Diagnostics, <output_dir>/intestine.csv every output interval:
 *   t, sub (sub-period, -1 = no wave), x_F [m] (mean x of white),
 *   white_0 .. white_{N+1} (counts per pocket, N+1 = overflow), alpha
 *   (fraction of white out of pocket 0), [red_0 .. red_{N+1}], overflow
 *   (all parked fluid), fluid (fluid in the computation), rho_dev and mach
 *   (max |rho/rho0 - 1| and max |v|/c0 of the liquid), in_membrane and
 *   through (liquid particles lodged between the membrane's top and bottom
 *   layers, and below its bottom layer), lift_0 .. lift_N
 *   (mean y displacement of the middle third of each segment [m]),
 *   s_0 .. s_N (the schedule's value per pocket).
 * At the end: u_F, V_w, alpha after one period, u_P, u_S, Re, Ga, Fr, Lambda
 * (doc/theory.md, "Peristalsis and tracking"). */
#include <math.h>
#include <errno.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/fields.h"
#include "dmhs/modules.h"
#include "dmhs/scenes.h"
#include "dmhs/bond.h"
#include "dmhs/angle_harmonic.h"
#include "dmhs/repulsion.h"
#include "dmhs/body_force.h"
#include "dmhs/peristalsis.h"
#include "dmhs/tracking.h"
#include "dmhs/checkpoint.h"
#include "dmhs/csv.h"
#include "dmhs/liquid_state.h"
#include "dmhs/membrane_leak.h"

#define TRACER_WHITE 1
#define TRACER_RED   2

typedef struct {
  PetscInt n_pockets; /* N + 1 */
  double b, dx, level, amplitude, wall_height, weir;
  PetscInt layers, clamp, red_pocket;
  PetscBool red;
  module *body, *rep, *peri;
  PetscInt64 n_fluid; /* fluid gids 0 .. n_fluid - 1 */
  PetscInt64 n_white0, n_red0;
  double x_end, x_park; /* (N+1) b; parking line past the weir */
  double lot_x0, lot_y0, lot_sp;
  PetscInt lot_rows;
  /* history of x_F for the slope (replicated) */
  double *hist_t, *hist_x;
  PetscInt n_hist, cap_hist;
  double alpha_T;                     /* alpha after one period (NAN until reached) */
  double lift_max;                    /* largest segment lift seen [m] */
  membrane_layout mem;                /* the liquid must stay above its top layer */
  double rho_dev_max, mach_max;       /* over the output rows so far */
  PetscInt64 inside_max, through_max; /* most liquid particles in / through the membrane in a row */
  FILE *csv;
} intestine_data;

static PetscErrorCode intestine_set_from_options(scene *self, sim *s) {
  intestine_data *c = self->data;
  PetscBool set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Scene intestine (colon with peristalsis)", NULL);
  PetscCall(PetscOptionsInt("-intestine_pockets", "Number of pockets N + 1 [1]", NULL, c->n_pockets,
                            &c->n_pockets, NULL));
  PetscCall(PetscOptionsReal("-intestine_b", "Pocket length b [m]", NULL, c->b, &c->b, NULL));
  PetscCall(PetscOptionsReal("-intestine_dx", "Particle spacing dx [m] (also the membrane's r0)",
                             NULL, c->dx, &c->dx, NULL));
  PetscCall(PetscOptionsReal("-intestine_level", "Liquid level L above the folds [m]", NULL,
                             c->level, &c->level, NULL));
  PetscCall(PetscOptionsReal("-intestine_amplitude",
                             "Haustral depth A of the profile -A sin^2(pi x/b) [m]", NULL,
                             c->amplitude, &c->amplitude, NULL));
  PetscCall(PetscOptionsInt("-intestine_membrane_layers", "Membrane particle layers [1]", NULL,
                            c->layers, &c->layers, NULL));
  PetscCall(PetscOptionsInt("-intestine_clamp", "Fixed membrane columns at each end [1]", NULL,
                            c->clamp, &c->clamp, NULL));
  PetscCall(PetscOptionsReal("-intestine_wall_height", "Left wall's height above the level [m]",
                             NULL, c->wall_height, &c->wall_height, NULL));
  c->weir = c->level;
  PetscCall(PetscOptionsReal("-intestine_weir",
                             "Top of the overflow weir above the folds [m] (default: the level)",
                             NULL, c->weir, &c->weir, NULL));
  PetscCall(PetscOptionsBool("-intestine_red", "Track the liquid of a second pocket (red)", NULL,
                             c->red, &c->red, NULL));
  PetscCall(PetscOptionsInt("-intestine_red_pocket", "Pocket of the red set [1]", NULL,
                            c->red_pocket, &c->red_pocket, NULL));
  PetscOptionsEnd();
  PetscCheck(c->n_pockets >= 1 && c->b > 0 && c->dx > 0 && c->dx < 0.1 * c->b, s->comm,
             PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_pockets must be >= 1, -intestine_b > 0 and 0 < -intestine_dx < b/10");
  PetscCheck(c->level > c->dx && c->amplitude >= 0 && c->wall_height >= 0 && c->weir >= 0, s->comm,
             PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_level must exceed dx; amplitude, wall height and weir must be >= 0");
  PetscCheck(c->layers >= 2 && c->clamp >= 1, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_membrane_layers must be >= 2 and -intestine_clamp >= 1");
  PetscCheck(!c->red || (c->red_pocket > 0 && c->red_pocket < c->n_pockets), s->comm,
             PETSC_ERR_ARG_OUTOFRANGE,
             "-intestine_red_pocket must lie in [1, N] (got %" PetscInt_FMT ")", c->red_pocket);
  s->dx = c->dx;
  /* the published case; h = 2.5 dx, not the published h = dx (no neighbour inside the support) */
  module *sph;
  PetscCall(modules_enable(s, "sph", &sph));
  sph_params *sp = sph_defaults(sph);
  /* c0 = 5 m/s, not the published 1 m/s (doc/validation.md, "Intestine"):
   * at 1 m/s (B = 143 Pa) the hydrostatic pressure of the 7.6 mm deep pockets
   * alone compresses the liquid by 5.7 %, and the pouring liquid reaches
   * 0.2-0.4 m/s (Mach 0.2-0.4); 5 m/s keeps both within 1 % and 0.1;
   * nu = 1e-5 lies inside the published 0.5e-6 ... 500e-6 m^2/s, quieter than water's 1e-6 */
  PetscCall(sph_set_liquid(sph, 2.5 * c->dx, 1000.0, 5.0, 1e-5)); /* h, rho0, c0, nu */
  /* density diffusion: without it the liquid at rest on the membrane is
   * unstable (continuity density at cell Reynolds number c0 h/nu ~ 600:
   * at c0 = 5 m/s Mach 0.5 after 0.05 s with no wave, at 1 m/s Mach 0.17
   * after 0.12 s); with delta = 0.1 it stays at Mach 0.004 (doc/theory.md) */
  sp->delta = 0.1;
  /* the automatic dt unless -dt is given: the repulsion's limit (0.035 dx
   * [s/m], 8.8e-6 s at dx = 2.5e-4 m) lies below the published 1e-5 s, and
   * the bonds' limit tightens as the membrane stretches under the wave */
  PetscCall(PetscOptionsHasName(NULL, NULL, "-dt", &set));
  if (!set)
    s->dt = 0.0;
  PetscCall(fields_enable("tracer")); /* the white (and red) liquid */
  PetscCall(fields_enable("x0"));     /* tracking's displacements, the segments' centres */
  PetscCall(modules_enable(s, "body_force", &c->body));
  PetscCall(body_force_set_default_gravity(c->body, 9.81));
  /* the published membrane is nonlinear (FENE-like) */
  PetscCall(solid_modules_enable(s, BOND_NONLINEAR));
  /* k_b = 1e-4 J, r0 = dx, r_max = 1.8 dx (4.5e-4 m at dx = 2.5e-4 m) */
  PetscCall(bond_set_default(s, 1e-4, c->dx, 1.8 * c->dx));
  PetscCall(angle_set_default(s, 8e-5, 90.0));
  PetscCall(modules_enable(s, "repulsion", &c->rep));
  /* K = 8000 J/m^2 x dx^2 (2e-3 J at dx = 5e-4 m, 5e-4 J at the study's
   * 2.5e-4 m), not the published 1e-10 J (doc/validation.md, "Intestine"):
   * where the wave stretches the membrane to ~1.9 r0, a liquid particle in a
   * gap between two membrane particles is 0.95 r* from both, where the SPH
   * pressure force vanishes (dW/dr -> 0) and 1e-10 J pushes ~1e-7 N/m against
   * the liquid's p dx ~ 0.05 N/m: the liquid went through (half this K still
   * let it through near a clamped end). The repulsion's limit, 0.035 dx
   * [s/m], binds dt: 1.8x below the sound speed's at c0 = 5 m/s. */
  PetscCall(repulsion_set_default(c->rep, 8000.0 * c->dx * c->dx, c->dx, 4, 2));
  PetscCall(modules_enable(s, "peristalsis", &c->peri));
  PetscCall(peristalsis_set_geometry(c->peri, c->n_pockets, c->b, 0.0));
  PetscFunctionReturn(0);
}

static inline double intestine_profile(const intestine_data *c, double x) {
  const double sn = sin(M_PI * x / c->b);
  return -c->amplitude * sn * sn;
}
static inline double intestine_slope(const intestine_data *c, double x) {
  return -c->amplitude * M_PI / c->b * sin(2.0 * M_PI * x / c->b);
}

static PetscErrorCode intestine_build(scene *self, sim *s) {
  const sph_params *sp = sph_params_get(s);
  intestine_data *c = self->data;
  const double dx = c->dx, m = sp->rho0 * dx * dx, zero[2] = {0, 0};
  const PetscInt wl = (PetscInt)ceil(sp->h / dx - 1e-9); /* wall layers filling the support */
  PetscInt64 gid = 0;
  PetscFunctionBeginUser;
  c->x_end = c->n_pockets * c->b;
  double a_body[DMHS_DIM]; /* the hydrostatic start's g: the body force's downward part */
  body_force_at(c->body, 0.0, a_body);
  const double g = -a_body[1];
  const double y_bottom = -c->amplitude - c->layers * dx; /* lowest membrane particle, about */
  const double y_top = c->level + c->wall_height;
  s->dom.lo[0] = -(wl + 2) * dx;
  s->dom.lo[1] = y_bottom - 0.02 - 2 * dx; /* room for the membrane pushed down */
  s->dom.hi[1] = y_top + 0.02;
  s->dom.periodic[0] = s->dom.periodic[1] = PETSC_FALSE;
  /* parked as it passes the centre of the weir's inner column, i.e. once it is
   * over the weir (doc/validation.md, "Intestine"): a film that clung to the
   * outer face crept under the weir and the membrane, and a lone particle
   * left on the crest, its pressure extrapolated to the wall from itself
   * alone, rattled up to Mach 0.23 */
  c->x_park = c->x_end + 0.5 * dx;
  c->lot_sp = 2.2 * sp->h;
  c->lot_x0 = c->x_park + 2 * c->lot_sp;
  c->lot_y0 = s->dom.lo[1] + c->lot_sp;
  c->lot_rows = (PetscInt)floor((s->dom.hi[1] - s->dom.lo[1] - 2 * c->lot_sp) / c->lot_sp);
  PetscCheck(c->lot_rows > 0, s->comm, PETSC_ERR_PLIB, "intestine: no room for the parking lot");
  /* liquid (gids 0 .. n_fluid - 1) */
  const PetscInt nx = (PetscInt)floor(c->x_end / dx + 1e-9);
  const PetscInt j0 = (PetscInt)floor((-c->amplitude) / dx) - 1,
                 j1 = (PetscInt)ceil(c->level / dx) + 1;
  for (PetscInt i = 0; i < nx; i++)
    for (PetscInt j = j0; j <= j1; j++) {
      const double x[2] = {(i + 0.5) * dx, (j + 0.5) * dx};
      const double ys = intestine_profile(c, x[0]), sl = intestine_slope(c, x[0]);
      if (x[1] >= c->level || x[1] < ys + 0.95 * dx * sqrt(1 + sl * sl))
        continue;
      /* hydrostatic start, rho from p = rho0 g (L - y) through the Tait EOS: no collapse under
       * gravity */
      const double B = sp->c0 * sp->c0 * sp->rho0 / 7.0, ph = sp->rho0 * g * (c->level - x[1]);
      const double rho =
          sp->eos == SPH_EOS_TAIT ? sp->rho0 * pow(1.0 + ph / B, 1.0 / 7.0) : sp->rho0;
      PetscInt idx;
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_FLUID, x, zero, m, rho, &idx));
      const PetscInt k = tracking_pocket(x[0], c->n_pockets, c->b, 0.0);
      if (k == 0)
        s->ps.tracer[idx] = TRACER_WHITE;
      else if (c->red && k == c->red_pocket)
        s->ps.tracer[idx] = TRACER_RED;
    }
  c->n_fluid = gid;
  /* the parking lot must fit in x: widen the domain */
  const PetscInt lot_cols = (PetscInt)((c->n_fluid + c->lot_rows - 1) / c->lot_rows);
  s->dom.hi[0] = c->lot_x0 + (lot_cols + 1) * c->lot_sp;
  /* left wall and right weir: wl columns from below the membrane's end up */
  const PetscInt jb = (PetscInt)floor(-c->layers * dx / dx) - 1;
  for (PetscInt k = 0; k < wl; k++) {
    for (PetscInt j = jb; (j + 0.5) * dx < y_top; j++) {
      const double x[2] = {-(k + 0.5) * dx, (j + 0.5) * dx};
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_WALL, x, zero, m, sp->rho0, NULL));
    }
    for (PetscInt j = jb; (j + 0.5) * dx < c->weir; j++) {
      const double x[2] = {c->x_end + (k + 0.5) * dx, (j + 0.5) * dx};
      PetscCall(particles_add_owned(&s->ps, gid++, PTYPE_WALL, x, zero, m, sp->rho0, NULL));
    }
  }
  /* membrane: middle-line arc y_m(x) = y_s(x) - (layers-1)/2 dx, columns every dx of arc */
  const double off = 0.5 * (c->layers - 1) * dx;
  double *cx;
  PetscInt ncol = 0, cap = (PetscInt)(4 * c->x_end / dx) + 16;
  PetscCall(PetscMalloc1(cap, &cx));
  {
    double x = 0.5 * dx, arc = 0;
    const double step = dx / 64;
    cx[ncol++] = x;
    while (x < c->x_end - 0.5 * dx) {
      const double sl = intestine_slope(c, x + 0.5 * step);
      arc += step * sqrt(1 + sl * sl);
      x += step;
      if (arc >= dx) {
        PetscCheck(ncol < cap, s->comm, PETSC_ERR_PLIB, "intestine: membrane columns overflow");
        cx[ncol++] = x;
        arc -= dx;
      }
    }
  }
  const PetscInt64 g0 = gid;
  const PetscInt L = c->layers;
  for (PetscInt col = 0; col < ncol; col++) {
    const double x = cx[col], sl = intestine_slope(c, x), nl = sqrt(1 + sl * sl);
    const double n[2] = {-sl / nl, 1.0 / nl};
    const double ym = intestine_profile(c, x) - off;
    const PetscBool fixed = col < c->clamp || col >= ncol - c->clamp ? PETSC_TRUE : PETSC_FALSE;
    const PetscInt k = tracking_pocket(x, c->n_pockets, c->b, 0.0);
    for (PetscInt l = 0; l < L; l++) {
      const double sh = off - l * dx; /* layer 0 on top */
      const double p[2] = {x + sh * n[0], ym + sh * n[1]};
      PetscInt idx;
      PetscCall(particles_add_owned(&s->ps, gid++, fixed ? PTYPE_WALL : PTYPE_SOLID, p, zero, m,
                                    sp->rho0, &idx));
      if (!fixed)
        s->ps.segment[idx] = PERISTALSIS_SEGMENT0 + (PetscInt)PetscMin(k, c->n_pockets - 1);
    }
  }
  PetscCall(PetscFree(cx));
  c->mem = (membrane_layout){.g0 = g0, .n_columns = ncol, .layers = L};
  PetscCall(PetscPrintf(
      s->comm,
      "intestine: %" PetscInt_FMT " pockets of %g m, fluid gids 0..%" PetscInt64_FMT
      ", walls %" PetscInt64_FMT "..%" PetscInt64_FMT ", membrane %" PetscInt64_FMT
      "..%" PetscInt64_FMT " (%" PetscInt_FMT " columns x %" PetscInt_FMT " layers, %" PetscInt_FMT
      " fixed at each end), parking lot of %" PetscInt_FMT " rows at x >= %g m\n",
      c->n_pockets, c->b, c->n_fluid - 1, c->n_fluid, g0 - 1, g0, gid - 1, ncol, L, c->clamp,
      c->lot_rows, c->lot_x0));
  topology *t = s->topo;
#define G(col, l)  (g0 + (PetscInt64)(col)*L + (l))
#define FIXED(col) ((col) < c->clamp || (col) >= ncol - c->clamp)
  for (PetscInt col = 0; col < ncol; col++) {
    if (!FIXED(col))
      for (PetscInt l = 0; l + 1 < L; l++)
        PetscCall(topology_add_bond(t, G(col, l), G(col, l + 1), 0));
    if (col + 1 == ncol || (FIXED(col) && FIXED(col + 1)))
      continue;
    for (PetscInt l = 0; l < L; l++)
      PetscCall(topology_add_bond(t, G(col, l), G(col + 1, l), 0));
    for (PetscInt l = 0; l + 1 < L; l++) { /* the four corners of cell (col..col+1, l..l+1) */
      PetscCall(topology_add_angle(t, G(col + 1, l), G(col, l), G(col, l + 1), 0));
      PetscCall(topology_add_angle(t, G(col, l), G(col + 1, l), G(col + 1, l + 1), 0));
      PetscCall(topology_add_angle(t, G(col + 1, l + 1), G(col, l + 1), G(col, l), 0));
      PetscCall(topology_add_angle(t, G(col, l + 1), G(col + 1, l + 1), G(col + 1, l), 0));
    }
  }
#undef G
#undef FIXED
  PetscCheck(s->dom.lo[1] < y_bottom && c->lot_y0 + c->lot_rows * c->lot_sp < s->dom.hi[1], s->comm,
             PETSC_ERR_PLIB, "intestine: domain too small");
  PetscFunctionReturn(0);
}

/* Fluid past the weir is parked: a fixed particle (wall type, at rest) in its
 * own slot of the lot, > 2 h from every other particle, so that it takes no
 * part in any sum. The slot is a function of the gid: rank-count invariant. */
static PetscErrorCode intestine_park(intestine_data *c, sim *s) {
  const sph_params *sp = sph_params_get(s);
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID || ps->x[i][0] <= c->x_park)
      continue;
    const PetscInt64 g = ps->gid[i];
    PetscCheck(g >= 0 && g < c->n_fluid, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "intestine: fluid gid %" PetscInt64_FMT " out of range", g);
    const double slot[DMHS_DIM] = {c->lot_x0 + (double)(g / c->lot_rows) * c->lot_sp,
                                   c->lot_y0 + (double)(g % c->lot_rows) * c->lot_sp};
    particles_retire(ps, i, slot, sp->rho0);
  }
  PetscFunctionReturn(0);
}

typedef struct {
  const intestine_data *c;
  PetscInt k;
} seg_sel;

static PetscBool intestine_segment_centre(const sim *s, PetscInt i, void *ctx) {
  const seg_sel *q = ctx;
  if (s->ps.type[i] != PTYPE_SOLID || s->ps.segment[i] != PERISTALSIS_SEGMENT0 + q->k)
    return PETSC_FALSE;
  return fabs(s->ps.x0[i][0] - (q->k + 0.5) * q->c->b) < q->c->b / 6 ? PETSC_TRUE : PETSC_FALSE;
}

static PetscErrorCode intestine_fluid_counts(intestine_data *c, sim *s, PetscInt64 *fluid,
                                             PetscInt64 *parked) {
  PetscInt64 buf[2] = {0, 0};
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < s->ps.n_owned; i++) {
    if (s->ps.type[i] == PTYPE_FLUID)
      buf[0]++;
    else if (s->ps.gid[i] < c->n_fluid)
      buf[1]++;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, buf, 2, MPIU_INT64, MPI_SUM, s->comm));
  *fluid = buf[0];
  *parked = buf[1];
  PetscFunctionReturn(0);
}

/* intestine.csv and its header (csv.h: a restart keeps the rows up to the checkpoint) */
static PetscErrorCode intestine_open_csv(intestine_data *c, sim *s, double tw, double Tw) {
  const PetscInt np = c->n_pockets;
  const size_t len = 512 + 32 * (size_t)(4 * np + 8);
  size_t at = 0;
  char *h;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(len, &h));
#define INTESTINE_HEADER(...) at += (size_t)snprintf(h + at, at < len ? len - at : 0, __VA_ARGS__)
  INTESTINE_HEADER("# intestine: %" PetscInt_FMT
                   " pockets, b %g m, dx %g m, level %g m, amplitude %g m, "
                   "t_w %g s, T_w %g s, fluid %" PetscInt64_FMT "\n",
                   np, c->b, c->dx, c->level, c->amplitude, tw, Tw, c->n_fluid);
  INTESTINE_HEADER("t,sub,x_F");
  for (PetscInt k = 0; k <= np; k++)
    INTESTINE_HEADER(",white_%" PetscInt_FMT, k);
  INTESTINE_HEADER(",alpha");
  if (c->red)
    for (PetscInt k = 0; k <= np; k++)
      INTESTINE_HEADER(",red_%" PetscInt_FMT, k);
  INTESTINE_HEADER(",overflow,fluid,rho_dev,mach,in_membrane,through");
  for (PetscInt k = 0; k < np; k++)
    INTESTINE_HEADER(",lift_%" PetscInt_FMT, k);
  for (PetscInt k = 0; k < np; k++)
    INTESTINE_HEADER(",s_%" PetscInt_FMT, k);
  INTESTINE_HEADER("\n");
#undef INTESTINE_HEADER
  PetscCheck(at < len, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "intestine.csv header longer than %zu bytes", len);
  PetscCall(csv_open(s, "intestine.csv", h, &c->csv));
  PetscCall(PetscFree(h));
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_diagnose(scene *self, sim *s) {
  intestine_data *c = self->data;
  const PetscInt np = c->n_pockets;
  PetscInt64 *cw, *cr, nw, nr, fluid, parked;
  double xw, xr, tw, Tw, delay;
  PetscFunctionBeginUser;
  PetscCall(intestine_park(c, s));
  PetscCall(peristalsis_get(c->peri, &tw, &Tw, NULL, NULL, &delay));
  /* rows at step 0 and at output times; a restarted run continues the CSV (csv.h) */
  if (s->step > 0 && s->t < s->next_output_t - 0.5 * s->dt)
    PetscFunctionReturn(0);
  PetscCall(PetscCalloc2(np + 1, &cw, np + 1, &cr));
  PetscCall(tracking_count(s, TRACER_WHITE, np, c->b, 0.0, cw, &nw, &xw));
  if (c->red)
    PetscCall(tracking_count(s, TRACER_RED, np, c->b, 0.0, cr, &nr, &xr));
  PetscCall(intestine_fluid_counts(c, s, &fluid, &parked));
  double rho_dev, mach;
  PetscInt64 inside, through;
  PetscCall(liquid_state_bounds(s, &rho_dev, &mach));
  PetscCall(membrane_leak_count(s, &c->mem, &inside, &through));
  c->rho_dev_max = PetscMax(c->rho_dev_max, rho_dev);
  c->mach_max = PetscMax(c->mach_max, mach);
  c->inside_max = PetscMax(c->inside_max, inside);
  c->through_max = PetscMax(c->through_max, through);
  PetscCheck(fluid + parked == c->n_fluid, s->comm, PETSC_ERR_PLIB,
             "intestine: %" PetscInt64_FMT " fluid + %" PetscInt64_FMT " parked != %" PetscInt64_FMT
             " initial at t = %g s",
             fluid, parked, c->n_fluid, s->t);
  if (s->step == 0) {
    c->n_white0 = nw;
    c->n_red0 = c->red ? nr : 0;
  }
  const double alpha = c->n_white0 > 0 ? 1.0 - (double)cw[0] / (double)c->n_white0 : 0.0;
  double *lift;
  PetscCall(PetscMalloc1(np, &lift));
  for (PetscInt k = 0; k < np; k++) {
    seg_sel q = {c, k};
    PetscInt64 n;
    PetscCall(tracking_mean_displacement(s, intestine_segment_centre, &q, 1, &lift[k], &n));
    c->lift_max = PetscMax(c->lift_max, lift[k]);
  }
  const PetscInt sub = peristalsis_subperiod(c->peri, s->t);
  /* x_F history of the squeezing phase for u_F: the first wave */
  if (s->t >= delay - 0.5 * s->dt && s->t <= delay + Tw + 0.5 * s->dt) {
    if (c->n_hist == c->cap_hist) {
      c->cap_hist = 2 * c->cap_hist + 64;
      PetscCall(PetscRealloc(sizeof(double) * c->cap_hist, &c->hist_t));
      PetscCall(PetscRealloc(sizeof(double) * c->cap_hist, &c->hist_x));
    }
    c->hist_t[c->n_hist] = s->t;
    c->hist_x[c->n_hist++] = xw;
  }
  if (isnan(c->alpha_T) && s->t >= delay + Tw - 0.5 * s->dt)
    c->alpha_T = alpha;
  if (s->rank == 0) { /* mpi: rank 0 writes */
    if (!c->csv)
      PetscCall(intestine_open_csv(c, s, tw, Tw));
    const size_t len = 64 + 32 * (size_t)(4 * np + 8);
    size_t at = 0;
    char *row;
    PetscCall(PetscMalloc1(len, &row));
#define INTESTINE_ROW(...) at += (size_t)snprintf(row + at, at < len ? len - at : 0, __VA_ARGS__)
    INTESTINE_ROW("%.8g,%" PetscInt_FMT ",%.10g", s->t, sub, xw);
    for (PetscInt k = 0; k <= np; k++)
      INTESTINE_ROW(",%" PetscInt64_FMT, cw[k]);
    INTESTINE_ROW(",%.8g", alpha);
    if (c->red)
      for (PetscInt k = 0; k <= np; k++)
        INTESTINE_ROW(",%" PetscInt64_FMT, cr[k]);
    INTESTINE_ROW(",%" PetscInt64_FMT ",%" PetscInt64_FMT ",%.6g,%.6g,%" PetscInt64_FMT
                  ",%" PetscInt64_FMT,
                  parked, fluid, rho_dev, mach, inside, through);
    for (PetscInt k = 0; k < np; k++)
      INTESTINE_ROW(",%.8g", lift[k]);
    for (PetscInt k = 0; k < np; k++)
      INTESTINE_ROW(",%d", peristalsis_value(c->peri, s->t, k));
    INTESTINE_ROW("\n");
#undef INTESTINE_ROW
    PetscCheck(at < len, PETSC_COMM_SELF, PETSC_ERR_PLIB, "intestine.csv row longer than %zu bytes",
               len);
    PetscCall(csv_line(c->csv, "intestine.csv", row));
    PetscCall(PetscFree(row));
  }
  PetscCall(PetscFree(lift));
  PetscCall(PetscFree2(cw, cr));
  PetscFunctionReturn(0);
}

/* <output_dir>/intestine-summary.csv (key,value; "n/a" for an undefined
 * value, e.g. alpha when the run ends before one period), written to a
 * temporary name and renamed. */
static PetscErrorCode intestine_write_summary(sim *s, const char **keys, const double *values,
                                              PetscInt n) {
  char path[PETSC_MAX_PATH_LEN], tmp[PETSC_MAX_PATH_LEN + 8];
  PetscFunctionBeginUser;
  PetscCall(io_output_path(s, "intestine-summary.csv", path, sizeof(path)));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
  FILE *f = fopen(tmp, "w");
  PetscCheck(f, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot write %s: %s", tmp, strerror(errno));
  int ok = fprintf(f, "key,value\n") > 0;
  for (PetscInt i = 0; i < n; i++)
    ok = (isfinite(values[i]) ? fprintf(f, "%s,%.8g\n", keys[i], values[i])
                              : fprintf(f, "%s,n/a\n", keys[i])) > 0 &&
         ok;
  ok = (fclose(f) == 0) && ok;
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot write %s", tmp);
  PetscCheck(rename(tmp, path) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
             "cannot rename %s to %s: %s", tmp, path, strerror(errno));
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_finish(scene *self, sim *s) {
  const sph_params *sp = sph_params_get(s);
  intestine_data *c = self->data;
  double tw, Tw, delay, uF;
  PetscInt64 fluid, parked;
  PetscFunctionBeginUser;
  PetscCall(peristalsis_get(c->peri, &tw, &Tw, NULL, NULL, &delay));
  PetscCall(tracking_slope(c->hist_t, c->hist_x, c->n_hist, &uF));
  /* the initial-slope rule (when the level drops, x_F bends over): the slope
   * while pocket 0 squeezes in the first wave, the front's first advance */
  double uF0 = NAN;
  {
    PetscInt i0 = -1, n0 = 0;
    for (PetscInt i = 0; i < c->n_hist; i++)
      if (peristalsis_value(c->peri, c->hist_t[i], 0) > 0) {
        if (i0 < 0)
          i0 = i;
        if (i == i0 + n0)
          n0++; /* the first contiguous squeeze only */
      }
    if (i0 >= 0)
      PetscCall(tracking_slope(c->hist_t + i0, c->hist_x + i0, n0, &uF0));
  }
  PetscCall(intestine_fluid_counts(c, s, &fluid, &parked));
  double a_body[DMHS_DIM];
  body_force_at(c->body, s->t, a_body);
  const double nu = sp->nu, g = fabs(a_body[1]);
  const double Vw = c->n_pockets * c->b / Tw;
  const PetscBool reached = isnan(c->alpha_T) ? PETSC_FALSE : PETSC_TRUE;
  const double a = c->alpha_T;
  const double uP = a / (1 - a) * Vw / c->n_pockets, uS = a * Vw;
  const PetscBool measured = c->lift_max > c->dx ? PETSC_TRUE : PETSC_FALSE;
  const double h = measured ? c->lift_max : c->amplitude;
  PetscCall(PetscPrintf(s->comm,
                        "intestine: fluid %" PetscInt64_FMT " in the computation + %" PetscInt64_FMT
                        " overflowed (pocket N+1, parked) = %" PetscInt64_FMT " of %" PetscInt64_FMT
                        " initial\n",
                        fluid, parked, fluid + parked, c->n_fluid));
  PetscCall(PetscPrintf(
      s->comm,
      "intestine: liquid bounds over the output rows: max |rho/rho0 - 1| %.3g, max Mach %.3g; "
      "liquid in the membrane (between its top and bottom layers) at most %" PetscInt64_FMT
      ", through it %" PetscInt64_FMT " particles\n",
      c->rho_dev_max, c->mach_max, c->inside_max, c->through_max));
  PetscCall(PetscPrintf(
      s->comm,
      "intestine: front velocity u_F = %g m/s (least squares of x_F over %" PetscInt_FMT
      " rows, t in [%g, %g] s)\n",
      uF, c->n_hist, c->n_hist ? c->hist_t[0] : NAN, c->n_hist ? c->hist_t[c->n_hist - 1] : NAN));
  PetscCall(PetscPrintf(
      s->comm, "intestine: initial front velocity (while pocket 0 squeezes) u_F0 = %g m/s\n", uF0));
  PetscCall(PetscPrintf(s->comm, "intestine: V_w = (N+1) b / T_w = %g m/s (T_w = %g s)\n", Vw, Tw));
  if (reached)
    PetscCall(PetscPrintf(s->comm,
                          "intestine: alpha after one period = %g, u_P = alpha/(1-alpha) V_w/(N+1) "
                          "= %g m/s, u_S = alpha V_w = %g m/s\n",
                          a, uP, uS));
  else
    PetscCall(PetscPrintf(s->comm,
                          "intestine: alpha after one period: not reached (t_end < delay + T_w = "
                          "%g s); u_P, u_S undefined\n",
                          delay + Tw));
  PetscCall(PetscPrintf(s->comm,
                        "intestine: h = %g m (%s), Re = b u_F/nu = %g, Ga = h^3 g/nu^2 = %g, Fr = "
                        "V_w/sqrt(g h) = %g, Lambda = h/L = %g\n",
                        h,
                        measured ? "largest measured segment lift"
                                 : "configured amplitude A: no lift above dx measured",
                        c->b * uF / nu, h * h * h * g / (nu * nu), Vw / sqrt(g * h), h / c->level));
  PetscCall(csv_close(&c->csv, "intestine.csv"));
  if (s->rank == 0) {
    const double Re = c->b * uF / nu, Ga = h * h * h * g / (nu * nu), Fr = Vw / sqrt(g * h),
                 Lambda = h / c->level;
    const double values[] = {c->b,
                             c->level,
                             nu,
                             Tw,
                             Vw,
                             uF,
                             uF0,
                             a,
                             uP,
                             uS,
                             h,
                             Re,
                             Ga,
                             Fr,
                             Lambda,
                             c->rho_dev_max,
                             c->mach_max,
                             (double)c->inside_max,
                             (double)c->through_max,
                             (double)fluid,
                             (double)parked,
                             s->t};
    static const char *keys[] = {
        "b",           "level",   "nu",       "T_w",         "V_w",      "u_F",
        "u_F_initial", "alpha_T", "u_P",      "u_S",         "h",        "Re",
        "Ga",          "Fr",      "Lambda",   "rho_dev_max", "mach_max", "in_membrane_max",
        "through_max", "fluid",   "overflow", "t_end"};
    PetscCall(intestine_write_summary(s, keys, values, (PetscInt)(sizeof(keys) / sizeof(keys[0]))));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_checkpoint_write(scene *self, sim *s, struct checkpoint_io *io) {
  intestine_data *c = self->data;
  const PetscInt64 ints[5] = {c->n_white0, c->n_red0, c->n_hist, c->inside_max, c->through_max};
  const double reals[4] = {c->alpha_T, c->lift_max, c->rho_dev_max, c->mach_max};
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(checkpoint_put_ints(io, "intestine_ints", ints, 5));
  PetscCall(checkpoint_put_reals(io, "intestine_reals", reals, 4));
  if (c->n_hist) {
    PetscCall(checkpoint_put_reals(io, "intestine_hist_t", c->hist_t, c->n_hist));
    PetscCall(checkpoint_put_reals(io, "intestine_hist_x", c->hist_x, c->n_hist));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_checkpoint_read(scene *self, sim *s, struct checkpoint_io *io) {
  intestine_data *c = self->data;
  PetscInt64 ints[5];
  double reals[4];
  PetscFunctionBeginUser;
  (void)s;
  PetscCall(checkpoint_get_ints(io, "intestine_ints", ints, 5));
  PetscCall(checkpoint_get_reals(io, "intestine_reals", reals, 4));
  c->n_white0 = ints[0];
  c->n_red0 = ints[1];
  c->n_hist = c->cap_hist = (PetscInt)ints[2];
  c->alpha_T = reals[0];
  c->lift_max = reals[1];
  c->rho_dev_max = reals[2];
  c->mach_max = reals[3];
  c->inside_max = ints[3];
  c->through_max = ints[4];
  PetscCall(PetscFree(c->hist_t));
  PetscCall(PetscFree(c->hist_x));
  if (c->n_hist) {
    PetscCall(PetscMalloc1(c->n_hist, &c->hist_t));
    PetscCall(PetscMalloc1(c->n_hist, &c->hist_x));
    PetscCall(checkpoint_get_reals(io, "intestine_hist_t", c->hist_t, c->n_hist));
    PetscCall(checkpoint_get_reals(io, "intestine_hist_x", c->hist_x, c->n_hist));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode intestine_destroy(scene *self) {
  intestine_data *c = self->data;
  PetscFunctionBeginUser;
  if (c->csv)
    fclose(c->csv);
  PetscCall(PetscFree(c->hist_t));
  PetscCall(PetscFree(c->hist_x));
  PetscCall(PetscFree(self->data));
  PetscFunctionReturn(0);
}

PetscErrorCode intestine_scene_create(scene **out) {
  intestine_data *c;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(out));
  PetscCall(PetscNew(&c));
  c->n_pockets = 10;
  c->b = 0.02;
  c->dx = 2.5e-4;
  c->level = 0.0046;
  c->amplitude = 0.003;
  c->layers = 3;
  c->clamp = 3;
  c->wall_height = 0.03;
  c->red_pocket = 4;
  c->alpha_T = NAN;
  (*out)->name = "intestine";
  (*out)->set_from_options = intestine_set_from_options;
  (*out)->build = intestine_build;
  (*out)->diagnose = intestine_diagnose;
  (*out)->finish = intestine_finish;
  (*out)->destroy = intestine_destroy;
  (*out)->checkpoint_write = intestine_checkpoint_write;
  (*out)->checkpoint_read = intestine_checkpoint_read;
  (*out)->data = c;
  PetscFunctionReturn(0);
}
