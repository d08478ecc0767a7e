/* Counts the MPI collectives and point-to-point calls a run makes (the PMPI
 * profiling interface), for the latency term of the scaling model in
 * doc/performance.md, "Past one node". Not part of the build:
 *   mpicc -O2 -shared -fPIC -o /tmp/pmpi_count.so bench/pmpi_count.c
 *   mpirun -n 2 -x LD_PRELOAD=/tmp/pmpi_count.so build/dmhs ...
 * Rank 0 prints one line per call at MPI_Finalize: its count and bytes sent. */
#include <mpi.h>
#include <stdio.h>

enum { ALLREDUCE, ALLTOALL, ALLTOALLV, BCAST, REDUCE, ALLGATHER, ALLGATHERV, BARRIER, N_CALLS };
static const char *names[N_CALLS] = {"MPI_Allreduce",  "MPI_Alltoall", "MPI_Alltoallv",
                                     "MPI_Bcast",      "MPI_Reduce",   "MPI_Allgather",
                                     "MPI_Allgatherv", "MPI_Barrier"};
static long long calls[N_CALLS], bytes[N_CALLS];

static long long size_of(MPI_Datatype t, long long n) {
  int s;
  PMPI_Type_size(t, &s);
  return n * s;
}

int MPI_Allreduce(const void *sb, void *rb, int n, MPI_Datatype t, MPI_Op op, MPI_Comm c) {
  calls[ALLREDUCE]++, bytes[ALLREDUCE] += size_of(t, n);
  return PMPI_Allreduce(sb, rb, n, t, op, c);
}
int MPI_Alltoall(const void *sb, int sn, MPI_Datatype st, void *rb, int rn, MPI_Datatype rt,
                 MPI_Comm c) {
  int p;
  PMPI_Comm_size(c, &p);
  calls[ALLTOALL]++, bytes[ALLTOALL] += size_of(st, (long long)sn * p);
  return PMPI_Alltoall(sb, sn, st, rb, rn, rt, c);
}
int MPI_Alltoallv(const void *sb, const int *sn, const int *sd, MPI_Datatype st, void *rb,
                  const int *rn, const int *rd, MPI_Datatype rt, MPI_Comm c) {
  int p;
  long long total = 0;
  PMPI_Comm_size(c, &p);
  for (int r = 0; r < p; r++)
    total += sn[r];
  calls[ALLTOALLV]++, bytes[ALLTOALLV] += size_of(st, total);
  return PMPI_Alltoallv(sb, sn, sd, st, rb, rn, rd, rt, c);
}
int MPI_Bcast(void *b, int n, MPI_Datatype t, int root, MPI_Comm c) {
  calls[BCAST]++, bytes[BCAST] += size_of(t, n);
  return PMPI_Bcast(b, n, t, root, c);
}
int MPI_Reduce(const void *sb, void *rb, int n, MPI_Datatype t, MPI_Op op, int root, MPI_Comm c) {
  calls[REDUCE]++, bytes[REDUCE] += size_of(t, n);
  return PMPI_Reduce(sb, rb, n, t, op, root, c);
}
int MPI_Allgather(const void *sb, int sn, MPI_Datatype st, void *rb, int rn, MPI_Datatype rt,
                  MPI_Comm c) {
  calls[ALLGATHER]++, bytes[ALLGATHER] += size_of(st, sn);
  return PMPI_Allgather(sb, sn, st, rb, rn, rt, c);
}
int MPI_Allgatherv(const void *sb, int sn, MPI_Datatype st, void *rb, const int *rn, const int *rd,
                   MPI_Datatype rt, MPI_Comm c) {
  calls[ALLGATHERV]++, bytes[ALLGATHERV] += size_of(st, sn);
  return PMPI_Allgatherv(sb, sn, st, rb, rn, rd, rt, c);
}
int MPI_Barrier(MPI_Comm c) {
  calls[BARRIER]++;
  return PMPI_Barrier(c);
}
int MPI_Finalize(void) {
  int rank;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    for (int k = 0; k < N_CALLS; k++)
      if (calls[k])
        printf("pmpi_count: %-14s %10lld calls %14lld bytes sent by rank 0\n", names[k], calls[k],
               bytes[k]);
  return PMPI_Finalize();
}
