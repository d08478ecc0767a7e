/* Struct-of-arrays particle store. Owned rows first, ghost rows after; every
 * array is allocated, grown and copied through the field table. */
#include <string.h>
#include "dmhs/particles.h"
#include "dmhs/fields.h"

PetscErrorCode particles_create(particles *ps) {
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(ps, sizeof(*ps)));
  PetscFunctionReturn(0);
}

PetscErrorCode particles_destroy(particles *ps) {
  size_t n;
  const field_desc *t = fields_table(&n);
  PetscFunctionBeginUser;
  for (size_t k = 0; k < n; k++)
    PetscCall(PetscFree(*fields_member(ps, &t[k])));
  PetscCall(PetscMemzero(ps, sizeof(*ps)));
  PetscFunctionReturn(0);
}

PetscErrorCode particles_reserve(particles *ps, PetscInt n) {
  size_t nf;
  const field_desc *t = fields_table(&nf);
  PetscFunctionBeginUser;
  if (n <= ps->capacity)
    PetscFunctionReturn(0);
  fields_freeze(PETSC_TRUE);
  /* grow geometrically so appending one particle at a time stays linear */
  PetscInt cap = PetscMax(n, ps->capacity + ps->capacity / 2 + 16);
  size_t per_particle = 0;
  for (size_t k = 0; k < nf; k++)
    per_particle += fields_row_bytes(&t[k]);
  for (size_t k = 0; k < nf; k++) {
    void **member = fields_member(ps, &t[k]);
    void *fresh;
    size_t row = fields_row_bytes(&t[k]);
    /* PETSc's own message names only this function: say what and how much */
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    const PetscErrorCode err = PetscCalloc(row * (size_t)cap, &fresh);
    PetscCall(PetscPopErrorHandler());
    PetscCheck(
        !err, PETSC_COMM_SELF, PETSC_ERR_MEM,
        "out of memory: cannot allocate %.4g MB for particle field '%s' (room for %" PetscInt_FMT
        " particles, %" PetscInt_FMT " requested; all fields together need %.4g MB, %zu bytes per "
        "particle); use more ranks or fewer particles",
        (double)row * (double)cap / 1e6, t[k].name, cap, n,
        (double)per_particle * (double)cap / 1e6, per_particle);
    if (*member)
      PetscCall(PetscMemcpy(fresh, *member, row * (size_t)ps->capacity));
    PetscCall(PetscFree(*member));
    *member = fresh;
  }
  ps->capacity = cap;
  PetscFunctionReturn(0);
}

PetscErrorCode particles_add_owned(particles *ps, PetscInt64 gid, particle_type type,
                                   const double x[DMHS_DIM], const double v[DMHS_DIM], double mass,
                                   double rho, PetscInt *index) {
  PetscFunctionBeginUser;
  PetscCheck(ps->n_ghost == 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE,
             "particles_add_owned: ghosts must be dropped before adding owned particles");
  PetscCall(particles_reserve(ps, ps->n_owned + 1));
  PetscInt i = ps->n_owned++;
  ps->gid[i] = gid;
  ps->type[i] = type;
  if (ps->load)
    ps->load[i] = 0;
  if (ps->segment)
    ps->segment[i] = 0;
  if (ps->tracer)
    ps->tracer[i] = 0;
  for (int k = 0; k < DMHS_DIM; k++) {
    ps->x[i][k] = x[k];
    if (ps->x0)
      ps->x0[i][k] = x[k];
    ps->x_build[i][k] = x[k];
    ps->v[i][k] = v[k];
    ps->v_est[i][k] = v[k];
    if (ps->v_visc)
      ps->v_visc[i][k] = v[k];
    ps->a[i][k] = 0.0;
  }
  ps->mass[i] = mass;
  ps->rho[i] = rho;
  if (ps->drho)
    ps->drho[i] = 0.0;
  if (ps->p)
    ps->p[i] = 0.0;
  if (index)
    *index = i;
  PetscFunctionReturn(0);
}

void particles_copy_row(particles *ps, PetscInt dst, PetscInt src, unsigned flags) {
  size_t nf;
  const field_desc *t = fields_table(&nf);
  for (size_t k = 0; k < nf; k++) {
    if (!(t[k].flags & flags))
      continue;
    size_t row = fields_row_bytes(&t[k]);
    char *base = *fields_member(ps, &t[k]);
    memcpy(base + row * (size_t)dst, base + row * (size_t)src, row);
  }
}

void particles_retire(particles *ps, PetscInt i, const double x_rest[DMHS_DIM], double rho_rest) {
  ps->type[i] = PTYPE_WALL;
  for (int d = 0; d < DMHS_DIM; d++) {
    ps->x[i][d] = x_rest[d];
    ps->v[i][d] = ps->v_est[i][d] = ps->a[i][d] = 0;
    if (ps->v_visc)
      ps->v_visc[i][d] = 0;
    if (ps->a_hold)
      ps->a_hold[i][d] = 0;
  }
  if (ps->substepped)
    ps->substepped[i] = 0;
  ps->rho[i] = rho_rest;
  if (ps->drho)
    ps->drho[i] = 0;
  if (ps->drho_prev)
    ps->drho_prev[i] = 0;
}

PetscInt particles_count_type(const particles *ps, particle_type type) {
  PetscInt n = 0;
  for (PetscInt i = 0; i < ps->n_owned; i++)
    n += ps->type[i] == (PetscInt)type;
  return n;
}

/* mpi: field-table packing for migration and ghosts (particle-major rows). */
int particles_select_fields(unsigned flags, const field_desc **out, int max) {
  size_t nf;
  const field_desc *t = fields_table(&nf);
  int n = 0;
  for (size_t k = 0; k < nf && n < max; k++)
    if (t[k].flags & flags)
      out[n++] = &t[k];
  return n;
}

size_t particles_packed_bytes(const field_desc *const *f, int nf) {
  size_t b = 0;
  for (int k = 0; k < nf; k++)
    b += fields_row_bytes(f[k]);
  return b;
}

void particles_pack(const particles *ps, const field_desc *const *f, int nf, const PetscInt *rows,
                    PetscInt n, const double (*shift)[DMHS_DIM], char *buf) {
  for (PetscInt e = 0; e < n; e++) {
    const PetscInt r = rows[e];
    for (int k = 0; k < nf; k++) {
      const size_t row = fields_row_bytes(f[k]);
      const char *base = *fields_member((void *)ps, f[k]);
      if (shift && f[k]->offset == offsetof(particles, x)) {
        double x[DMHS_DIM];
        memcpy(x, base + row * (size_t)r, row);
        for (int d = 0; d < DMHS_DIM; d++)
          x[d] += shift[e][d];
        memcpy(buf, x, row);
      } else
        memcpy(buf, base + row * (size_t)r, row);
      buf += row;
    }
  }
}

void particles_unpack(particles *ps, const field_desc *const *f, int nf, PetscInt first, PetscInt n,
                      const char *buf) {
  for (PetscInt e = 0; e < n; e++)
    for (int k = 0; k < nf; k++) {
      const size_t row = fields_row_bytes(f[k]);
      char *base = *fields_member(ps, f[k]);
      memcpy(base + row * (size_t)(first + e), buf, row);
      buf += row;
    }
}
