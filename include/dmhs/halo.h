/* Ghost particles: periodic images and copies of other ranks' particles,
 * rebuilt after every migration; forward updates refresh ghost fields from
 * their owners in the order of the build. No reverse exchange: owners compute
 * their own pairs with ghosts redundantly (doc/parallel.md). */
#ifndef DMHS_HALO_H
#define DMHS_HALO_H
#include <petscsys.h>
#include "dmhs/particles.h"
#include "dmhs/domain.h"
#include "dmhs/partition.h"

typedef struct halo {
  double width; /* every interaction reach (SPH support, ...) plus skin */
  MPI_Comm comm;
  PetscMPIInt rank, size;
  /* One rank: one entry per ghost (its owned source row and periodic shift).
   * Several ranks: one entry per copy sent, grouped by destination rank
   * (entries [send_off[r], send_off[r + 1]) go to rank r, itself included for
   * periodic images); the shift is added to x before sending. */
  PetscInt n, n_alloc;
  PetscInt *source;
  double (*shift)[DMHS_DIM];
  PetscMPIInt *dest;                  /* build scratch: destination of each entry */
  PetscInt *send_off, *recv_off;      /* size + 1 offsets, in particles */
  PetscMPIInt *send_cnt, *send_displ; /* in bytes, for MPI_Alltoallv */
  PetscMPIInt *recv_cnt, *recv_displ;
  char *send_buf, *recv_buf;
  size_t send_buf_len, recv_buf_len;
  PetscInt n_recv; /* ghosts received (= n_ghost) */
} halo;

PetscErrorCode halo_create(halo *h, double width, MPI_Comm comm);
PetscErrorCode halo_destroy(halo *h);
/* Drops old ghosts and creates new ones, with every FIELD_GHOST field:
 * one rank: periodic images of owned particles within `width` of a periodic boundary;
 * several ranks: a copy of each owned particle for every rank (itself included,
 * with a periodic shift) owning a cell of `part` within `width` of it.
 * Collective on several ranks. */
PetscErrorCode halo_build(halo *h, const domain *d, const partition *part, particles *ps);
/* Refreshes the named FIELD_GHOST fields of the ghosts from their owners
 * (x gets its periodic shift again). Collective on several ranks. */
PetscErrorCode halo_forward(halo *h, particles *ps, const char *const field_names[], int n_fields);

/* Halo sizes at the last build, over the ranks (halo_stats.c; run.json's "halo"):
 * what the cost of the ghosts and of their exchange scales with. Per rank:
 * owned rows, ghost rows (periodic images included: they cost compute like
 * any ghost), remote ghosts (received from other ranks: they cost the
 * exchange), copies sent to other ranks, and partners (other ranks it sends
 * to or receives from: the messages a neighbour-wise exchange would need). */
typedef struct halo_count {
  PetscInt64 min, max, total;
} halo_count;
typedef struct halo_stats {
  PetscMPIInt ranks;
  halo_count owned, ghost, remote, sent, partners;
  halo_count forward_bytes; /* bytes a rank receives from other ranks per ghost refresh */
  PetscInt64 ghost_bytes;   /* one packed ghost row of a refresh: the fields it sends */
} halo_stats;
/* Gathers st from the state of the last halo_build; refresh: the n fields a ghost refresh
 * between builds sends (sim.ghost_step_fields). Collective. */
PetscErrorCode halo_stats_gather(const halo *h, const particles *ps, const char *const *refresh,
                                 int n, halo_stats *st);

/* -debug_halo (halo_check.c): the pair list of every owned particle equals a
 * brute-force search over all ranks' particles. Collective. */
struct sim;
PetscErrorCode halo_check_set_from_options(struct sim *s);
PetscErrorCode halo_check_pairs(struct sim *s);

#endif
