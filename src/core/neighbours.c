/* Neighbour handling, in one place: the Verlet rebuild policy (a particle moved half the
 * skin, the partition's balance check, or a module forced it), migration and the rebuild of
 * rows, ghosts, cells and the pair list, the ghost refresh between builds (the fields modules
 * read there), and the rebuild a restart needs from the positions of the last build. */
#include <stdint.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/neighbours.h"
#include "dmhs/fields.h"
#include "dmhs/events.h"
#include "dmhs/migrate.h"

PetscErrorCode neighbours_rebuild(sim *s) {
  double lo[DMHS_DIM], hi[DMHS_DIM];
  PetscFunctionBeginUser;
  for (int k = 0; k < DMHS_DIM; k++) {
    lo[k] = s->dom.lo[k] - s->hal.width;
    hi[k] = s->dom.hi[k] + s->hal.width;
  }
  const double cutoff = PetscMax(s->pair_cutoff, s->list_cutoff);
  if (s->pair_cutoff > 0) /* owned rows in the order the pair build will visit them */
    PetscCall(cells_sort_owned_rows(&s->ps, lo, hi, cutoff));
  PetscCall(halo_build(&s->hal, &s->dom, &s->part, &s->ps)); /* mpi: + partition */
  /* solids: bonds/angles by gid -> local rows, and the bonded pairs the pair list leaves
   * out */
  if (s->topo) {
    PetscCall(PetscLogEventBegin(events.topology, 0, 0, 0, 0));
    PetscCall(topology_resolve(s->topo, &s->ps));
    PetscCall(PetscLogEventEnd(events.topology, 0, 0, 0, 0));
    s->cel.excl = s->topo->special_include ? NULL : s->topo;
  }
  if (s->pair_cutoff > 0) {
    PetscCall(PetscLogEventBegin(events.pairs, 0, 0, 0, 0));
    PetscCall(cells_build_pairs(&s->cel, &s->ps, lo, hi, cutoff));
    PetscCall(PetscLogEventEnd(events.pairs, 0, 0, 0, 0));
    if (s->debug_halo)
      PetscCall(halo_check_pairs(s)); /* mpi */
  }
  PetscFunctionReturn(0);
}

/* Names of every FIELD_GHOST field: what a full ghost refresh copies (diagnostics, restart). */
static const char *const *neighbours_all_ghost_fields(int *n) {
  static const char *names[32];
  static int count = -1;
  if (count < 0) {
    size_t nf;
    const field_desc *t = fields_table(&nf);
    count = 0;
    for (size_t k = 0; k < nf && count < 32; k++)
      if (t[k].flags & FIELD_GHOST)
        names[count++] = t[k].name;
  }
  *n = count;
  return names;
}

/* Verlet lists: rebuild when a particle may have moved half the skin since the
 * last build (then a pair can have come from outside the list radius into the
 * interaction range), or when the partition is due for its balance check. The
 * order of every particle's sums follows the cells of the last build, so the
 * build steps must not depend on the rank count. */
static PetscErrorCode neighbours_due(sim *s, PetscBool *rebuild) {
  const particles *ps = &s->ps;
  double local = 0, global;
  PetscFunctionBeginUser;
  *rebuild = PETSC_TRUE;
  if (s->skin <= 0)
    PetscFunctionReturn(0);
  /* on every rank count alike, so that runs stay bitwise rank-count invariant */
  if (s->part.interval > 0 && s->step % s->part.interval == 0)
    PetscFunctionReturn(0);
  /* the largest squared displacement, over its bits as unsigned integers (they order as
   * the values do for numbers >= 0), so that the scan vectorises */
  uint64_t max_bits = 0;
  const double *restrict x = &ps->x[0][0], *restrict x_build = &ps->x_build[0][0];
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    const double dx = x[2 * i] - x_build[2 * i], dy = x[2 * i + 1] - x_build[2 * i + 1];
    const double d2 = dx * dx + dy * dy;
    uint64_t bits;
    memcpy(&bits, &d2, sizeof(bits));
    max_bits = bits > max_bits ? bits : max_bits;
  }
  memcpy(&local, &max_bits, sizeof(local));
  PetscCallMPI(MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, s->comm));
  *rebuild = global > 0.25 * s->skin * s->skin ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* The fields a step refreshes on ghosts between builds: those some module reads there
 * (module.ghost_reads) and that can change between builds (not FIELD_FIXED). */
PetscErrorCode neighbours_collect_ghost_reads(sim *s) {
  size_t nf;
  const field_desc *t = fields_table(&nf);
  PetscFunctionBeginUser;
  s->n_ghost_step_fields = 0;
  for (int m = 0; m < s->n_modules; m++)
    for (const char *const *r = s->modules[m]->ghost_reads; r && *r; r++) {
      const field_desc *f = fields_find(*r);
      PetscCheck(f && (f->flags & FIELD_GHOST), s->comm, PETSC_ERR_PLIB,
                 "module %s reads field '%s' on ghosts, which is not a ghost field of this run",
                 s->modules[m]->name, *r);
    }
  for (size_t k = 0; k < nf; k++) {
    if (!(t[k].flags & FIELD_GHOST) || (t[k].flags & FIELD_FIXED))
      continue;
    PetscBool read = PETSC_FALSE;
    for (int m = 0; m < s->n_modules && !read; m++)
      for (const char *const *r = s->modules[m]->ghost_reads; r && *r && !read; r++)
        read = strcmp(*r, t[k].name) ? PETSC_FALSE : PETSC_TRUE;
    if (!read)
      continue;
    PetscCheck(s->n_ghost_step_fields <
                   (int)(sizeof(s->ghost_step_fields) / sizeof(s->ghost_step_fields[0])),
               s->comm, PETSC_ERR_PLIB, "too many ghost fields");
    s->ghost_step_fields[s->n_ghost_step_fields++] = t[k].name;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode neighbours_update(sim *s, PetscBool force) {
  /* bonds made or removed at run time (collectively, so every rank agrees) need their
   * local lists and exclusions before the next force sweep */
  PetscBool rebuild = force || (s->topo && s->topo->changed) ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionBeginUser;
  if (!rebuild)
    PetscCall(neighbours_due(s, &rebuild));
  if (rebuild) {
    PetscCall(migrate_particles(s));
    PetscCall(neighbours_rebuild(s));
    PetscCall(PetscArraycpy(s->ps.x_build, s->ps.x, s->ps.n_owned));
    s->n_rebuilds++;
  } else if (s->n_ghost_step_fields > 0)
    PetscCall(halo_forward(&s->hal, &s->ps, s->ghost_step_fields, s->n_ghost_step_fields));
  PetscFunctionReturn(0);
}

PetscErrorCode neighbours_refresh_ghosts(sim *s) {
  int n;
  const char *const *names = neighbours_all_ghost_fields(&n);
  PetscFunctionBeginUser;
  PetscCall(halo_forward(&s->hal, &s->ps, names, n));
  PetscFunctionReturn(0);
}

PetscErrorCode neighbours_rebuild_as_last_built(sim *s) {
  particles *ps = &s->ps;
  int n;
  const char *const *names = neighbours_all_ghost_fields(&n);
  PetscFunctionBeginUser;
  /* build with x_build in the x slot; both migrate together, so rows stay paired */
  double(*current)[DMHS_DIM] = ps->x;
  ps->x = ps->x_build;
  ps->x_build = current;
  PetscCall(migrate_particles(s));
  PetscCall(neighbours_rebuild(s));
  current = ps->x_build;
  ps->x_build = ps->x;
  ps->x = current;
  PetscCall(halo_forward(&s->hal, ps, names, n));
  PetscFunctionReturn(0);
}
