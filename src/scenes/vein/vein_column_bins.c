/* The column mid-points of a vein leaflet binned for the nearest-column search
 * (vein_column_bins.h). */
#include <math.h>
#include "vein_column_bins.h"

#define VEIN_BIN_DX 4.0 /* bin size in dx: more than sqrt(10), the farthest "beside" reaches */

PetscErrorCode column_bins_destroy(column_bins *b) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(b->col, b->mid));
  PetscCall(PetscFree(b->first));
  PetscFunctionReturn(0);
}

PetscErrorCode column_bins_build(column_bins *b, const vein_leaflets *v, const domain *dom, int w,
                                 const double box[4]) {
  const PetscInt nc = v->lay.leaflet[w].n_columns;
  const double bin = VEIN_BIN_DX * v->lay.dx;
  PetscFunctionBeginUser;
  b->inv_bin = 1.0 / bin;
  for (int d = 0; d < 2; d++) {
    b->lo[d] = -box[2 + d];
    b->nb[d] = (PetscInt)(2.0 * box[2 + d] * b->inv_bin) + 1;
  }
  const PetscInt nbins = b->nb[0] * b->nb[1];
  if (nbins + 1 > b->n_bins_alloc) {
    PetscCall(PetscFree(b->first));
    b->n_bins_alloc = nbins + 1 + nbins / 4;
    PetscCall(PetscMalloc1(b->n_bins_alloc, &b->first));
  }
  if (nc > b->n_cols_alloc) {
    PetscCall(PetscFree2(b->col, b->mid));
    b->n_cols_alloc = nc;
    PetscCall(PetscMalloc2(nc, &b->col, nc, &b->mid));
  }
  PetscCall(PetscArrayzero(b->first, nbins + 1));
  for (PetscInt c = 0; c < nc; c++) {
    vein_leaflets_column_mid(v, w, c, b->mid[c]);
    b->mid[c][0] -= box[0];
    b->mid[c][1] -= box[1];
    domain_min_image(dom, b->mid[c]);
  }
  /* counting sort by bin (a mid-point lies inside the box, which reaches 4 dx beyond it);
   * columns ascend within a bin */
  PetscInt *bin_of, *fill;
  PetscCall(PetscMalloc2(nc, &bin_of, nbins, &fill));
  for (PetscInt c = 0; c < nc; c++) {
    PetscInt ij[2];
    for (int d = 0; d < 2; d++)
      ij[d] =
          PetscMin(PetscMax((PetscInt)((b->mid[c][d] - b->lo[d]) * b->inv_bin), 0), b->nb[d] - 1);
    bin_of[c] = ij[1] * b->nb[0] + ij[0];
    b->first[bin_of[c] + 1]++;
  }
  for (PetscInt k = 0; k < nbins; k++)
    b->first[k + 1] += b->first[k];
  PetscCall(PetscArraycpy(fill, b->first, nbins));
  for (PetscInt c = 0; c < nc; c++)
    b->col[fill[bin_of[c]]++] = c;
  PetscCall(PetscFree2(bin_of, fill));
  PetscFunctionReturn(0);
}

PetscInt column_bins_nearest(const column_bins *b, const double d[2], double dx) {
  PetscInt ij[2];
  for (int k = 0; k < 2; k++)
    ij[k] = (PetscInt)floor((d[k] - b->lo[k]) * b->inv_bin);
  double best = 10.0 * dx * dx;
  PetscInt cb = -1;
  for (PetscInt j = PetscMax(ij[1] - 1, 0); j <= PetscMin(ij[1] + 1, b->nb[1] - 1); j++)
    for (PetscInt i = PetscMax(ij[0] - 1, 0); i <= PetscMin(ij[0] + 1, b->nb[0] - 1); i++)
      for (PetscInt k = b->first[j * b->nb[0] + i]; k < b->first[j * b->nb[0] + i + 1]; k++) {
        const PetscInt c = b->col[k];
        const double e0 = d[0] - b->mid[c][0], e1 = d[1] - b->mid[c][1];
        const double r2 = e0 * e0 + e1 * e1;
        if (r2 < best || (r2 == best && c < cb)) {
          best = r2;
          cb = c;
        }
      }
  return cb;
}
