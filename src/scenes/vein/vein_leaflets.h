/* The vein's two leaflets replicated on every rank (src/scenes/vein/vein_leaflets.c),
 * for the vein's diagnostics, refreshed per use. */
#ifndef DMHS_VEIN_LEAFLETS_H
#define DMHS_VEIN_LEAFLETS_H
#include "vein_metrics.h"

typedef struct vein_leaflets {
  vein_layout lay;
  PetscInt n_leaf[2]; /* particles per leaflet (2 x columns) */
  double (*x)[2];     /* every leaflet particle: [leaflet 0 | leaflet 1] */
} vein_leaflets;

PetscErrorCode vein_leaflets_create(const vein_layout *lay, vein_leaflets *lf);
PetscErrorCode vein_leaflets_destroy(vein_leaflets *lf);
/* Every leaflet particle's position on every rank: owners fill, one exact SUM. Collective. */
PetscErrorCode vein_leaflets_gather(vein_leaflets *lf, sim *s);
/* Index in x of a leaflet particle (leaflet in *which), or -1 for another gid. */
PetscInt vein_leaflets_index(const vein_leaflets *lf, PetscInt64 gid, int *which);
/* Mid-point of column c of leaflet w. */
void vein_leaflets_column_mid(const vein_leaflets *lf, int w, PetscInt c, double m[2]);

#endif
