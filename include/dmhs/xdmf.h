/* The XDMF index of the snapshots (src/io/xdmf.c): <output_dir>/particles.xdmf,
 * an Xdmf 2 Temporal Collection with one Uniform grid per snapshot: Polyvertex
 * topology over the N particles, XYZ geometry from /particles/x (z = 0), one
 * Attribute per output field (Scalar or Vector). ParaView opens it as is
 * ("Xdmf Reader") and animates it over the snapshot times. Rank 0 keeps the
 * list and rewrites the file atomically after each snapshot. */
#ifndef DMHS_XDMF_H
#define DMHS_XDMF_H
#include <petscsys.h>

/* Optional connectivity drawn over the same points (bonds as Polyline):
 * an n_elements x nodes_per_element integer dataset inside the snapshot whose
 * entries are rows of the snapshot's particle datasets (0-based). */
typedef struct xdmf_connectivity {
  char dataset[64]; /* e.g. "/bonds/rows" */
  PetscInt64 n_elements;
  int nodes_per_element; /* 2 for bonds */
  const char *name;      /* grid name, e.g. "bonds" */
} xdmf_connectivity;

typedef struct xdmf xdmf;

PetscErrorCode xdmf_create(xdmf **x);
PetscErrorCode xdmf_destroy(xdmf **x);
/* Appends one snapshot (file name relative to the XDMF file). bonds may be NULL. */
PetscErrorCode xdmf_add(xdmf *x, const char *h5_name, double t, PetscInt64 n,
                        const xdmf_connectivity *bonds);
/* Writes the whole index to path (via path.tmp + rename). */
PetscErrorCode xdmf_write(const xdmf *x, const char *path);
/* Rebuilds the index from the snapshot files snap_000000.h5 .. snap_<n-1>.h5 found in dir
 * (after a restart); files that are missing are skipped. Serial (one rank). */
PetscErrorCode xdmf_scan(xdmf *x, const char *dir, PetscInt n);

#endif
