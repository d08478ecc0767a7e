/* -dump_final <file>: the owned particles' final states, gathered to rank 0,
 * sorted by global id and written as CSV (gid,type,x,y,vx,vy,rho) with 17
 * significant digits, so that runs on different rank counts can be compared
 * (test/mpi/compare_dumps.py). */
#ifndef DMHS_DUMP_H
#define DMHS_DUMP_H
#include <petscsys.h>

struct sim;
/* Reads -dump_final into s->dump_final (empty = no dump). */
PetscErrorCode dump_set_from_options(struct sim *s);
/* Writes the dump if requested. Collective. */
PetscErrorCode dump_final(struct sim *s);

#endif
