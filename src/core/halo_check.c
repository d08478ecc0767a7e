/* -debug_halo: after every ghost and pair-list rebuild, check that each owned
 * particle's neighbours in the pair list are exactly those a brute-force
 * search over all particles of all ranks finds (same cutoff, nearest periodic
 * image, wall-wall pairs left out), with no neighbour listed twice. A test
 * aid: it gathers every particle on every rank, O(N_owned x N_total) per step. */
#include <stdlib.h>
#include "dmhs/sim.h"
#include "dmhs/halo.h"
#include "dmhs/gather.h"

PetscErrorCode halo_check_set_from_options(sim *s) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Halo check", NULL);
  PetscCall(options_read_bool(
      "-debug_halo",
      "Check every step that the pair list equals a brute-force neighbour search (slow)", NULL,
      s->debug_halo, &s->debug_halo, NULL));
  PetscCall(options_run_control("-debug_halo"));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

static int halo_check_cmp_pair(const void *a, const void *b) {
  const PetscInt64 *p = a, *q = b;
  if (p[0] != q[0])
    return (p[0] > q[0]) - (p[0] < q[0]);
  return (p[1] > q[1]) - (p[1] < q[1]);
}

static int halo_check_cmp_gid(const void *a, const void *b) {
  const PetscInt64 p = *(const PetscInt64 *)a, q = *(const PetscInt64 *)b;
  return (p > q) - (p < q);
}

PetscErrorCode halo_check_pairs(sim *s) {
  const particles *ps = &s->ps;
  const PetscInt n_owned = ps->n_owned;
  const double cut = PetscMax(s->pair_cutoff, s->list_cutoff),
               cut2 = cut * cut; /* the list radius */
  double(*mine)[4], (*all)[4];
  size_t n_gathered;
  PetscInt64 *listed, *found;
  PetscInt n_listed = 0, bad = 0;
  PetscFunctionBeginUser;
  /* everybody's (gid, type, x, y) */
  PetscCall(PetscMalloc1(n_owned + 1, &mine));
  for (PetscInt i = 0; i < n_owned; i++) {
    mine[i][0] = (double)ps->gid[i];
    mine[i][1] = (double)ps->type[i];
    mine[i][2] = ps->x[i][0];
    mine[i][3] = ps->x[i][1];
  }
  PetscCall(gather_all(s->comm, "-debug_halo particles", mine, (size_t)n_owned, sizeof(*mine), &all,
                       &n_gathered, NULL));
  const PetscInt n_all = (PetscInt)n_gathered;

  /* (owned row, neighbour gid) from the pair list, sorted */
  PetscCall(PetscMalloc1(2 * (2 * s->cel.n_pairs + 1), &listed));
  for (PetscInt k = 0; k < s->cel.n_pairs; k++) {
    const PetscInt i = s->cel.pair_i[k], j = s->cel.pair_j[k];
    if (i < n_owned) {
      listed[2 * n_listed] = i;
      listed[2 * n_listed++ + 1] = ps->gid[j];
    }
    if (j < n_owned) {
      listed[2 * n_listed] = j;
      listed[2 * n_listed++ + 1] = ps->gid[i];
    }
  }
  qsort(listed, (size_t)n_listed, 2 * sizeof(PetscInt64), halo_check_cmp_pair);

  PetscCall(PetscMalloc1(n_all + 1, &found));
  PetscInt at = 0;
  for (PetscInt i = 0; i < n_owned && bad < 5; i++) {
    PetscInt n_found = 0;
    for (PetscInt j = 0; j < n_all; j++) {
      const double *o = all[j];
      if ((PetscInt64)o[0] == ps->gid[i])
        continue;
      if (ps->type[i] == PTYPE_WALL && (PetscInt)o[1] == PTYPE_WALL)
        continue;
      double d2 = 0;
      for (int k = 0; k < DMHS_DIM; k++) {
        /* the image as halo.c makes it: x + shift, shift in {0, +-L} */
        double xj = o[2 + k];
        if (s->dom.periodic[k]) {
          const double L = domain_length(&s->dom, k);
          /* pick the image nearest to x_i among x_j, x_j + L, x_j - L */
          const double c0 = o[2 + k], c1 = o[2 + k] + L, c2 = o[2 + k] - L;
          const double e0 = fabs(ps->x[i][k] - c0), e1 = fabs(ps->x[i][k] - c1),
                       e2 = fabs(ps->x[i][k] - c2);
          xj = e0 <= e1 && e0 <= e2 ? c0 : e1 <= e2 ? c1 : c2;
        }
        const double dx = ps->x[i][k] - xj;
        d2 += dx * dx;
      }
      if (d2 < cut2)
        found[n_found++] = (PetscInt64)o[0];
    }
    qsort(found, (size_t)n_found, sizeof(PetscInt64), halo_check_cmp_gid);
    PetscInt first = at;
    while (at < n_listed && listed[2 * at] == i)
      at++;
    const PetscInt n_have = at - first;
    PetscBool same = n_have == n_found ? PETSC_TRUE : PETSC_FALSE;
    for (PetscInt k = 0; k < n_found && same; k++)
      same = listed[2 * (first + k) + 1] == found[k];
    if (!same) {
      bad++;
      PetscCall(PetscPrintf(PETSC_COMM_SELF,
                            "-debug_halo: rank %d step %" PetscInt_FMT
                            ": particle gid %" PetscInt64_FMT " has %" PetscInt_FMT
                            " neighbours in the pair list, brute force finds %" PetscInt_FMT "\n",
                            (int)s->rank, s->step, ps->gid[i], n_have, n_found));
    }
  }
  PetscCall(PetscFree(found));
  PetscCall(PetscFree(listed));
  PetscCall(PetscFree(mine));
  PetscCall(PetscFree(all));
  PetscInt bad_total;
  PetscCallMPI(MPI_Allreduce(&bad, &bad_total, 1, MPIU_INT, MPI_SUM, s->comm));
  PetscCheck(bad_total == 0, s->comm, PETSC_ERR_PLIB,
             "-debug_halo: step %" PetscInt_FMT ": %" PetscInt_FMT
             " particle(s) whose pair-list neighbours differ from "
             "a brute-force search (ghosts missing or duplicated)",
             s->step, bad_total);
  PetscFunctionReturn(0);
}
