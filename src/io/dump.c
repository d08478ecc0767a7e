/* Final-state dump for rank-count comparisons (see dump.h). Every rank sends
 * its owned (gid, type, x, y, vx, vy, rho) rows to rank 0 with MPI_Gatherv;
 * rank 0 sorts them by gid and writes a CSV through a temporary name. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "dmhs/sim.h"
#include "dmhs/gather.h"
#include "dmhs/dump.h"
#include "dmhs/whole_file.h"

#define DUMP_COLS 7 /* gid, type, x, y, vx, vy, rho: all stored as doubles (gids < 2^53) */

PetscErrorCode dump_set_from_options(sim *s) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(s->comm, NULL, "Final-state dump", NULL);
  PetscCall(options_read_string("-dump_final",
                                "Write gid-sorted final particle states to this CSV file", NULL,
                                s->dump_final, s->dump_final, sizeof(s->dump_final), NULL));
  PetscCall(options_run_control("-dump_final"));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

static int dump_compare(const void *a, const void *b) {
  const double ga = ((const double *)a)[0], gb = ((const double *)b)[0];
  return (ga > gb) - (ga < gb);
}

PetscErrorCode dump_final(sim *s) {
  const particles *ps = &s->ps;
  double *mine, *all = NULL;
  size_t n_mine, total;
  PetscFunctionBeginUser;
  if (!s->dump_final[0])
    PetscFunctionReturn(0);
  n_mine = (size_t)ps->n_owned * DUMP_COLS;
  PetscCall(PetscMalloc1(n_mine + 1, &mine));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    double *row = mine + DUMP_COLS * i;
    row[0] = (double)ps->gid[i];
    row[1] = (double)ps->type[i];
    row[2] = ps->x[i][0];
    row[3] = ps->x[i][1];
    row[4] = ps->v[i][0];
    row[5] = ps->v[i][1];
    row[6] = ps->rho[i];
  }
  PetscCall(gather_to_root(s->comm, mine, n_mine, &all, &total));
  if (s->rank == 0) {
    const size_t n = total / DUMP_COLS;
    qsort(all, n, DUMP_COLS * sizeof(double), dump_compare);
    whole_file w;
    PetscCall(whole_file_open(&w, s->dump_final, "-dump_final"));
    FILE *f = w.f;
    int ok = fprintf(f, "gid,type,x,y,vx,vy,rho\n") > 0;
    for (size_t k = 0; k < n && ok; k++) {
      const double *r = all + DUMP_COLS * k;
      ok = fprintf(f, "%.0f,%.0f,%.17e,%.17e,%.17e,%.17e,%.17e\n", r[0], r[1], r[2], r[3], r[4],
                   r[5], r[6]) > 0;
    }
    PetscCall(whole_file_commit(&w, ok, "-dump_final"));
    PetscCall(PetscFree(all));
  }
  PetscCall(PetscFree(mine));
  PetscFunctionReturn(0);
}
