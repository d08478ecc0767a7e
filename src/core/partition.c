/* Domain decomposition on a coarse cell graph (the only file that calls METIS).
 *
 * The box is covered by nc[0] x nc[1] cells of edge >= the ghost width, so a
 * particle's ghosts can only be needed by the owners of its 3 x 3 neighbour
 * cells (halo.c). Vertex weight of a cell = sum over its particles of
 * (16 + 4 x bonded partners) + 1: a particle's SPH pairs cost about 16 units,
 * each bond or angle partner about 4 more; the constant keeps empty cells (the
 * intestine's and vein's empty regions) valid METIS vertices without letting
 * them weigh like occupied ones. Edges join the
 * 8 neighbours of a cell, wrapping along periodic directions.
 *
 * Determinism: rank 0 alone calls METIS (fixed seed) and broadcasts the owner
 * of every cell, so all ranks hold the same map whatever METIS does inside. */
#include <metis.h>
#include "dmhs/sim.h"
#include "dmhs/partition.h"
#include "dmhs/events.h"

#define PARTITION_WEIGHT_PER_PARTICLE       16
#define PARTITION_WEIGHT_PER_BONDED_PARTNER 4

/* A particle's share of a cell's vertex weight: its pairs plus its bonded work. */
static PetscErrorCode partition_particle_work(sim *s, PetscInt64 gid, PetscInt *work) {
  PetscInt partners = 0;
  PetscFunctionBeginUser;
  if (s->topo)
    PetscCall(topology_partner_count(s->topo, gid, &partners));
  *work = PARTITION_WEIGHT_PER_PARTICLE + PARTITION_WEIGHT_PER_BONDED_PARTNER * partners;
  PetscFunctionReturn(0);
}

/* The one checked wrapper around a METIS return code. */
static PetscErrorCode partition_metis_check(int status, const char *call) {
  PetscFunctionBeginUser;
  PetscCheck(status == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS %s failed: %s", call,
             status == METIS_ERROR_INPUT    ? "input error"
             : status == METIS_ERROR_MEMORY ? "out of memory"
                                            : "error");
  PetscFunctionReturn(0);
}

PetscErrorCode partition_set_from_options(partition *p, sim *s) {
  PetscFunctionBeginUser;
  p->imbalance_max = 1.2;
  p->interval = 100;
  PetscOptionsBegin(s->comm, NULL, "Domain decomposition (partition)", NULL);
  PetscCall(
      options_read_real("-partition_imbalance",
                        "Repartition when max/mean owned particles over ranks exceeds this [1]",
                        NULL, p->imbalance_max, &p->imbalance_max, NULL));
  PetscCall(options_run_control("-partition_imbalance"));
  PetscCall(options_read_int("-partition_interval",
                             "Steps between load-imbalance checks (0 = never repartition)", NULL,
                             p->interval, &p->interval, NULL));
  PetscOptionsEnd();
  PetscCheck(p->imbalance_max >= 1.0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-partition_imbalance must be >= 1 (got %g)", p->imbalance_max);
  PetscCheck(p->interval >= 0, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "-partition_interval must be >= 0 (got %" PetscInt_FMT ")", p->interval);
  p->imbalance = 1.0;
  PetscFunctionReturn(0);
}

/* The cell graph in CSR form (8 neighbours, periodic wrap, no duplicates, no self loops). */
static PetscErrorCode partition_graph(const partition *p, const PetscBool periodic[DMHS_DIM],
                                      idx_t **xadj_out, idx_t **adjncy_out) {
  idx_t *xadj, *adjncy;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(p->n_cells + 1, &xadj));
  PetscCall(PetscMalloc1(8 * p->n_cells, &adjncy));
  idx_t n = 0;
  xadj[0] = 0;
  for (PetscInt cy = 0; cy < p->nc[1]; cy++)
    for (PetscInt cx = 0; cx < p->nc[0]; cx++) {
      const PetscInt self = cy * p->nc[0] + cx;
      const idx_t first = n;
      for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
          PetscInt ux = cx + dx, uy = cy + dy;
          if (!periodic[0] && (ux < 0 || ux >= p->nc[0]))
            continue;
          if (!periodic[1] && (uy < 0 || uy >= p->nc[1]))
            continue;
          ux = (ux + p->nc[0]) % p->nc[0];
          uy = (uy + p->nc[1]) % p->nc[1];
          const idx_t other = (idx_t)(uy * p->nc[0] + ux);
          if (other == self)
            continue;
          PetscBool seen = PETSC_FALSE;
          for (idx_t k = first; k < n; k++)
            seen = seen || adjncy[k] == other;
          if (!seen)
            adjncy[n++] = other;
        }
      xadj[self + 1] = n;
    }
  *xadj_out = xadj;
  *adjncy_out = adjncy;
  PetscFunctionReturn(0);
}

/* Marks this rank's cells whose 3 x 3 neighbourhood reaches another rank or
 * wraps around a periodic boundary (halo.c skips particles of other cells). */
static void partition_mark_frontier(partition *p, const sim *s) {
  for (PetscInt cy = 0; cy < p->nc[1]; cy++)
    for (PetscInt cx = 0; cx < p->nc[0]; cx++) {
      const PetscInt self = cy * p->nc[0] + cx;
      char f = 0;
      if (p->owner[self] == s->rank)
        for (int dy = -1; dy <= 1 && !f; dy++)
          for (int dx = -1; dx <= 1 && !f; dx++) {
            const PetscInt ux = cx + dx, uy = cy + dy;
            if (ux < 0 || ux >= p->nc[0]) {
              f = s->dom.periodic[0];
              continue;
            }
            if (uy < 0 || uy >= p->nc[1]) {
              f = s->dom.periodic[1];
              continue;
            }
            f = p->owner[uy * p->nc[0] + ux] != s->rank;
          }
      p->frontier[self] = f;
    }
}

/* Rank 0 partitions with `counts` (work per cell; other ranks pass NULL) and
 * broadcasts the owners. A METIS failure on rank 0 is reported on every rank. */
static PetscErrorCode partition_run(partition *p, sim *s, const PetscInt *counts) {
  PetscInt64 status[2] = {0, 0}; /* error flag, edge cut */
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.partition, 0, 0, 0, 0));
  if (s->rank == 0) {
    idx_t *xadj = NULL, *adjncy = NULL, *vwgt, *part;
    idx_t nvtxs = (idx_t)p->n_cells, ncon = 1, nparts = (idx_t)s->size, objval = 0;
    idx_t options[METIS_NOPTIONS];
    PetscCall(partition_graph(p, s->dom.periodic, &xadj, &adjncy));
    PetscCall(PetscMalloc2(p->n_cells, &vwgt, p->n_cells, &part));
    for (PetscInt c = 0; c < p->n_cells; c++)
      vwgt[c] = (idx_t)(counts[c] + 1); /* each cell's work */
    PetscCall(partition_metis_check(METIS_SetDefaultOptions(options), "SetDefaultOptions"));
    options[METIS_OPTION_NUMBERING] = 0;
    options[METIS_OPTION_SEED] = 7; /* fixed: the same counts always give the same partition */
    options[METIS_OPTION_CONTIG] =
        1; /* connected subdomains: fewer neighbour ranks, thinner halos */
    const int rc = METIS_PartGraphKway(&nvtxs, &ncon, xadj, adjncy, vwgt, NULL, NULL, &nparts, NULL,
                                       NULL, options, &objval, part);
    if (rc == METIS_OK) {
      for (PetscInt c = 0; c < p->n_cells; c++)
        p->owner[c] = (PetscMPIInt)part[c];
      status[1] = objval;
    } else
      status[0] = rc;
    PetscCall(PetscFree2(vwgt, part));
    PetscCall(PetscFree(xadj));
    PetscCall(PetscFree(adjncy));
  }
  PetscCallMPI(MPI_Bcast(status, 2, MPIU_INT64, 0, s->comm));
  if (status[0])
    PetscCall(partition_metis_check((int)status[0], "PartGraphKway (on rank 0)"));
  PetscCallMPI(MPI_Bcast(p->owner, (PetscMPIInt)p->n_cells, MPI_INT, 0, s->comm));
  p->edge_cut = status[1];
  partition_mark_frontier(p, s);
  PetscCall(PetscLogEventEnd(events.partition, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode partition_setup(partition *p, sim *s) {
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  p->n_cells = 1;
  for (int k = 0; k < DMHS_DIM; k++) {
    const double L = domain_length(&s->dom, k);
    /* no reach at all (no pair module): any grid will do */
    const double target = s->hal.width > 0 ? s->hal.width : L / 64;
    p->nc[k] = PetscMax(1, (PetscInt)floor(L / target));
    p->lo[k] = s->dom.lo[k];
    p->edge[k] = L / (double)p->nc[k];
    p->inv_edge[k] = (double)p->nc[k] / L;
    PetscCheck(p->edge[k] >= s->hal.width, s->comm, PETSC_ERR_PLIB,
               "partition: cell edge %g < ghost width %g", p->edge[k], s->hal.width);
    p->n_cells *= p->nc[k];
  }
  PetscCall(PetscCalloc1(p->n_cells, &p->owner));
  PetscCall(PetscCalloc1(p->n_cells, &p->frontier));
  if (s->size == 1)
    PetscFunctionReturn(0);
  PetscCheck(p->n_cells >= s->size, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "partition: the box holds only %" PetscInt_FMT
             " cells of the ghost width %g m, fewer than the %d ranks; "
             "run on fewer ranks",
             p->n_cells, s->hal.width, (int)s->size);

  /* Scenes build every particle on every rank (the same, deterministic set):
   * partition by rank 0's copy, then each rank keeps its share. */
  PetscInt64 built = ps->n_owned, built_max, built_min;
  PetscCallMPI(MPI_Allreduce(&built, &built_max, 1, MPIU_INT64, MPI_MAX, s->comm));
  PetscCallMPI(MPI_Allreduce(&built, &built_min, 1, MPIU_INT64, MPI_MIN, s->comm));
  PetscCheck(built_min == built_max, s->comm, PETSC_ERR_PLIB,
             "partition: scene '%s' built %" PetscInt64_FMT " to %" PetscInt64_FMT
             " particles per rank; scenes must build the full set on every rank",
             s->scene_name, built_min, built_max);
  PetscInt *counts = NULL;
  if (s->rank == 0) {
    PetscCall(PetscCalloc1(p->n_cells, &counts));
    for (PetscInt i = 0; i < ps->n_owned; i++) {
      double x[DMHS_DIM] = {ps->x[i][0], ps->x[i][1]};
      domain_wrap(&s->dom, x);
      PetscInt work = 0;
      PetscCall(partition_particle_work(s, ps->gid[i], &work));
      counts[partition_cell_of(p, x)] += work;
    }
  }
  PetscCall(partition_run(p, s, counts));
  PetscCall(PetscFree(counts));
  PetscInt kept = 0;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    double x[DMHS_DIM] = {ps->x[i][0], ps->x[i][1]};
    domain_wrap(&s->dom, x);
    if (p->owner[partition_cell_of(p, x)] != s->rank)
      continue;
    if (kept != i)
      particles_copy_row(ps, kept, i, ~0u);
    kept++;
  }
  ps->n_owned = kept;
  PetscInt64 local = kept, total;
  PetscCallMPI(MPI_Allreduce(&local, &total, 1, MPIU_INT64, MPI_SUM, s->comm));
  PetscCheck(total == built, s->comm, PETSC_ERR_PLIB,
             "partition: %" PetscInt64_FMT " particles built but %" PetscInt64_FMT
             " kept over the ranks",
             built, total);
  PetscCall(partition_measure_imbalance(p, s));
  PetscFunctionReturn(0);
}

PetscErrorCode partition_destroy(partition *p) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(p->owner));
  PetscCall(PetscFree(p->frontier));
  PetscFunctionReturn(0);
}

PetscErrorCode partition_compute(partition *p, sim *s) {
  const particles *ps = &s->ps;
  PetscInt *local, *counts = NULL;
  PetscFunctionBeginUser;
  if (s->size == 1)
    PetscFunctionReturn(0);
  PetscCall(PetscCalloc1(p->n_cells, &local));
  if (s->rank == 0)
    PetscCall(PetscMalloc1(p->n_cells, &counts));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    PetscInt work = 0;
    PetscCall(partition_particle_work(s, ps->gid[i], &work));
    local[partition_cell_of(p, ps->x[i])] += work;
  }
  PetscCallMPI(MPI_Reduce(local, counts, (PetscMPIInt)p->n_cells, MPIU_INT, MPI_SUM, 0, s->comm));
  PetscCall(partition_run(p, s, counts));
  PetscCall(PetscFree(local));
  PetscCall(PetscFree(counts));
  p->n_repartitions++;
  PetscFunctionReturn(0);
}

PetscErrorCode partition_measure_imbalance(partition *p, sim *s) {
  PetscInt64 local = 0, max, total;
  PetscFunctionBeginUser;
  if (s->size == 1) {
    p->imbalance = 1.0;
    PetscFunctionReturn(0);
  }
  /* in the partition's own currency: the work its vertex weights balance */
  for (PetscInt i = 0; i < s->ps.n_owned; i++) {
    PetscInt work = 0;
    PetscCall(partition_particle_work(s, s->ps.gid[i], &work));
    local += work;
  }
  PetscCallMPI(MPI_Allreduce(&local, &max, 1, MPIU_INT64, MPI_MAX, s->comm));
  PetscCallMPI(MPI_Allreduce(&local, &total, 1, MPIU_INT64, MPI_SUM, s->comm));
  p->imbalance = total > 0 ? (double)max * (double)s->size / (double)total : 1.0;
  PetscFunctionReturn(0);
}

PetscErrorCode partition_check(partition *p, sim *s) {
  PetscFunctionBeginUser;
  if (s->size == 1 || p->interval == 0 || s->step % p->interval)
    PetscFunctionReturn(0);
  PetscCall(partition_measure_imbalance(p, s));
  if (p->imbalance <= p->imbalance_max)
    PetscFunctionReturn(0);
  const double before = p->imbalance;
  PetscCall(partition_compute(p, s));
  if (!p->quiet)
    PetscCall(PetscPrintf(s->comm,
                          "partition: step %" PetscInt_FMT
                          ": imbalance %.3f > %.3f (-partition_imbalance), "
                          "repartitioned (edge cut %" PetscInt64_FMT ")\n",
                          s->step, before, p->imbalance_max, p->edge_cut));
  PetscFunctionReturn(0);
}
